/**
 * @class   vtkRefractionMaterials
 * @brief   The glass props' materials of one frame: index of refraction, surface model, colour.
 *
 * Per glass prop (its position is its material index in the G-buffer): the index of
 * refraction, the thin-sheet thickness (0 for a solid; surfaces open as a whole become sheets
 * unless the prop's SURFACE_MODEL key says otherwise; a mesh whose connected pieces disagree
 * keeps the prop's material for its solid pieces and gets one more material, after the
 * props', for its sheet pieces; the pieces taken for sheets are named once in a warning), and whether any prop has a colour of its own (actor colour, scalar colours,
 * edges), with the absorption distance of the tint.
 */
#ifndef vtkRefractionMaterials_h
#define vtkRefractionMaterials_h

#include "vtkObject.h"

#include <string> // For members
#include <vector> // For members

class vtkProp;
class vtkRefractionSurfaceModel;

class vtkRefractionMaterials : public vtkObject
{
public:
  static vtkRefractionMaterials* New();
  vtkTypeMacro(vtkRefractionMaterials, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The materials of `glass`. `surfaces` answers which props are open; `dataColour` whether
   * the method may tint at all; `absorptionDistance` and `thinSheetThickness` are the pass's
   * settings (0: automatic from the props' bounds). `bounds`, when given, holds 6 values per
   * glass prop in place of its own GetBounds (across MPI ranks, where each rank holds a piece
   * of each prop: the whole prop's; xmin > xmax: none).
   */
  void Update(const std::vector<vtkProp*>& glass, vtkRefractionSurfaceModel* surfaces,
    bool dataColour, double absorptionDistance, double thinSheetThickness,
    const std::vector<double>* bounds = nullptr);

  const std::vector<float>& GetIndexOfRefraction() const { return this->IOR; }
  /// Red and blue indices per material (the green one is GetIndexOfRefraction); equal to it
  /// for props without dispersion.
  const std::vector<float>& GetRedIndex() const { return this->RedIOR; }
  const std::vector<float>& GetBlueIndex() const { return this->BlueIOR; }
  /// Whether a glass prop disperses (vtkRefractionPass::SetDispersion).
  bool GetDispersion() const { return this->Dispersion; }
  const std::vector<float>& GetSheetThickness() const { return this->Sheet; }
  /// Per glass prop, the material of its thin-sheet pieces when its mesh's connected pieces
  /// disagree (a material after the props', with the prop's indices), else -1.
  const std::vector<int>& GetSheetPieceMaterial() const { return this->SheetPieceMaterial; }
  /// Whether a glass prop has a colour of its own (then the G-buffer keeps the data colour).
  bool GetDataColour() const { return this->DataColour; }
  /// The tint's absorption distance (0 without data colour).
  double GetAbsorptionDistance() const { return this->AbsorptionDistance; }
  /// The largest bounding-box diagonal of the glass props (world units): no path inside the
  /// glass between two interfaces is longer.
  double GetLargestDiagonal() const { return this->LargestDiagonal; }
  /// The diagonal of the bounding box of all the glass props together.
  double GetExtentDiagonal() const { return this->ExtentDiagonal; }
  /// 4 floats per material: the highlights' colour (the actor's Specular times its
  /// SpecularColor) and SpecularPower.
  const std::vector<float>& GetHighlights() const { return this->Highlights; }
  /// Whether any glass prop has highlights (Specular above 0).
  bool GetHasHighlights() const { return this->HasHighlights; }

protected:
  vtkRefractionMaterials() = default;
  ~vtkRefractionMaterials() override = default;

private:
  vtkRefractionMaterials(const vtkRefractionMaterials&) = delete;
  void operator=(const vtkRefractionMaterials&) = delete;

  std::vector<float> IOR;
  std::vector<float> RedIOR;
  std::vector<float> BlueIOR;
  bool Dispersion = false;
  std::vector<float> Sheet;
  std::vector<int> SheetPieceMaterial;
  std::vector<float> Highlights;
  bool HasHighlights = false;
  bool DataColour = false;
  double AbsorptionDistance = 0.0;
  double RequestedAbsorptionDistance = 0.0; ///< the pass's setting the last Update saw
  double DerivedAbsorptionDistance = 0.0;   ///< kept while the setting stays 0
  double LargestDiagonal = 0.0;
  double ExtentDiagonal = 0.0;
  std::vector<vtkProp*> SheetsReported;
  std::vector<std::string> SheetPiecesReported;
  std::vector<vtkProp*> MixedReported; ///< composite props with open and closed blocks
};

#endif
