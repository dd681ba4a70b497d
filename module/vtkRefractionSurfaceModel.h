/**
 * @class   vtkRefractionSurfaceModel
 * @brief   Solid or thin sheet: the glass meshes' closedness, winding and open pieces.
 *
 * Part of vtkRefractionPass (issue 23). Per mesh, cached until the mesh is modified: whether
 * it is closed and consistently wound (the geometry stage culls hidden faces only then), its
 * winding (signed volume), and, when it has boundary edges, its connected pieces
 * (rf_pieces_label over points keyed by position) and which of them are open as a whole (a
 * thin sheet: boundary length at least RF_OPEN_AS_A_WHOLE times the square root of the
 * piece's area; a piece closed but for small holes stays a solid). A mesh whose pieces
 * disagree carries a per-point flag (1 in a sheet piece) that the geometry stage hands to the
 * G-buffer pass, so each fragment takes its piece's model. Per prop, the meshes together
 * (every block of composite data: there the decision stays per block, VTK 9.1's composite
 * mapper uploading no extra vertex data).
 */
#ifndef vtkRefractionSurfaceModel_h
#define vtkRefractionSurfaceModel_h

#include "vtkObject.h"

#include <map>    // For members
#include <vector> // For members

class vtkPolyData;
class vtkProp;

class vtkRefractionSurfaceModel : public vtkObject
{
public:
  static vtkRefractionSurfaceModel* New();
  vtkTypeMacro(vtkRefractionSurfaceModel, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// One mesh.
  struct Mesh
  {
    vtkMTimeType Time = 0;
    double Volume = 0.0; ///< signed, about the bounds' centre
    int WindingSign = 1; ///< +1 counter-clockwise seen from outside (the GL front face)
    bool Polygons = false; ///< any polygon or strip
    bool Closed = false;   ///< closed and consistently wound: faces can be culled
    bool Boundary = false;   ///< open as a whole: every piece is a thin sheet
    bool SmallHoles = false; ///< a piece with boundary edges that stays a solid
    int Pieces = 0;      ///< connected pieces (counted only when there are boundary edges)
    int SheetPieces = 0; ///< of those, the ones open as a whole
    /// Boundary length and square root of the area of the first sheet pieces (the warning).
    std::vector<std::pair<double, double>> SheetMeasures;
    /// Per point, 1 in a sheet piece: only when the pieces disagree (Mixed()).
    std::vector<unsigned char> PointSheet;
    double SheetBounds[6] = { 0.0, -1.0, 0.0, -1.0, 0.0, -1.0 }; ///< of the sheet pieces
    /// Closed, and every sight line crosses it entering and leaving by turns (Alternates()):
    /// -1 not decided yet (it is decided when asked), 0 no, 1 yes.
    int Alternating = -1;
    bool AskedBefore = false; ///< Alternates() was asked about this mesh's version before
    bool Mixed() const { return this->SheetPieces > 0 && this->SheetPieces < this->Pieces; }
  };

  /// A prop's meshes together.
  struct Prop
  {
    int WindingSign = 1;   ///< of the meshes' total signed volume
    bool Polygons = false;
    bool Closed = false;   ///< every mesh closed
    bool Boundary = false; ///< every mesh open as a whole: the prop is a thin sheet
    int Blocks = 0;        ///< meshes with polygons (composite data: blocks)
    int OpenBlocks = 0;    ///< of those, the ones open as a whole
    int MixedBlocks = 0;   ///< of those, the ones whose pieces disagree
    /// A plain vtkPolyData whose pieces disagree: its sheet pieces are decided per fragment.
    vtkPolyData* PerPiece = nullptr;
  };

  /// One mesh, cached until it is modified.
  const Mesh& GetMesh(vtkPolyData* poly);
  /// Whether every sight line crosses the prop's surfaces entering and leaving the glass by
  /// turns, so that PEEL's k-th layer behind the front faces the viewer exactly when k is
  /// even: one mesh (a vtkPolyData, or composite data with one visible block), closed and
  /// consistently wound, whose connected pieces are all wound the same way (their signed
  /// volumes) and none of which lies inside another's bounds (a piece inside another, wound
  /// the same way, is entered twice in a row). Decided the second time it is asked about the same version of a mesh (no at the
  /// first: a mesh that changes every frame is never labelled), then cached with it;
  /// conservative: pieces side by side whose bounds nest, or more than
  /// MaximumAlternatingPieces pieces, say no.
  bool Alternates(vtkProp* prop);
  static constexpr int MaximumAlternatingPieces = 256;
  /// The prop's meshes together (every block of composite data).
  Prop GetProp(vtkProp* prop);
  /// Forgets the meshes when more than `keep` are cached (entries of polydata that went away).
  void Prune(size_t keep);

  /// Compositing across MPI ranks, each rank holds a piece of each mesh, cut open where the
  /// data were split: an automatic surface model cannot tell those cuts from real boundaries,
  /// so every automatic prop is a solid (SetSurfaceModel(THIN_SHEET) marks open surfaces).
  void SetAcrossRanks(bool acrossRanks) { this->AcrossRanks = acrossRanks; }

protected:
  vtkRefractionSurfaceModel() = default;
  ~vtkRefractionSurfaceModel() override = default;

private:
  vtkRefractionSurfaceModel(const vtkRefractionSurfaceModel&) = delete;
  void operator=(const vtkRefractionSurfaceModel&) = delete;

  std::map<vtkPolyData*, Mesh> Meshes;
  bool AcrossRanks = false;
};

#endif
