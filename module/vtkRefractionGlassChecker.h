/**
 * @class   vtkRefractionGlassChecker
 * @brief   Sorts a render state's props into glass and the rest, and checks the glass.
 *
 * A glass prop with a bad index of refraction (set on the keys by hand) or without polygons
 * is drawn as an ordinary actor; one with an empty vtkPolyData, NaN/infinite points (or
 * beyond float range), cells naming missing points, offsets beyond the connectivity, or cells
 * too small for their kind (polygons and strips under 3 points, lines under 2, empty
 * vertices) is not drawn. One with vertices or lines besides its polygons is drawn without
 * them, with a warning (glass is its surfaces). Each verdict is reported once, with the
 * prop and the value, and kept until the prop's index or data change, so a static scene scans
 * no points and repeats no message.
 */
#ifndef vtkRefractionGlassChecker_h
#define vtkRefractionGlassChecker_h

#include "vtkObject.h"

#include <map>    // For members
#include <set>    // For members
#include <string> // For CheckMesh
#include <vector> // For SplitProps

class vtkPolyData;
class vtkProp;
class vtkRenderState;

class vtkRefractionGlassChecker : public vtkObject
{
public:
  static vtkRefractionGlassChecker* New();
  vtkTypeMacro(vtkRefractionGlassChecker, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The state's props: the glass to draw as glass, and (when `others` is given) the rest,
  /// including glass props drawn as ordinary actors. With `acrossRanks` (compositing across
  /// MPI ranks, where each rank holds a piece of each glass prop and some pieces are empty),
  /// the glass is every visible glass prop of the renderer that is not refused, empty ones
  /// included and said nothing of, in the renderer's order: the same list on every rank,
  /// whose position is the material index the composited G-buffers carry.
  void SplitProps(const vtkRenderState* s, std::vector<vtkProp*>& glass,
    std::vector<vtkProp*>* others, bool acrossRanks = false);

  /// The cells as CheckCells checks them, and coordinates finite and within float range; else
  /// false and why in `error` ("has ..."). Also what the reference module's filters check
  /// before they read a glass mesh.
  static bool CheckMesh(vtkPolyData* poly, std::string& error);

  /// The part of CheckMesh that keeps VTK's own filters from reading beyond the arrays:
  /// offsets within the connectivity, points named by cells exist, vertices of 1 point or
  /// more, lines 2, polygons and strips 3. What a reader checks before any filter runs.
  static bool CheckCells(vtkPolyData* poly, std::string& error);

protected:
  vtkRefractionGlassChecker() = default;
  ~vtkRefractionGlassChecker() override = default;

private:
  vtkRefractionGlassChecker(const vtkRefractionGlassChecker&) = delete;
  void operator=(const vtkRefractionGlassChecker&) = delete;

  enum GlassVerdictType
  {
    GLASS_OK = 0,
    GLASS_AS_ORDINARY = 1, ///< drawn as an ordinary actor (bad IOR, no polygons)
    GLASS_SKIPPED = 2,     ///< not drawn (NaN or infinite points, cells naming no point)
    GLASS_EMPTY = 3        ///< not drawn: no points or no cells
  };
  struct GlassCheck
  {
    vtkMTimeType Time = 0; ///< the data's
    const void* Data = nullptr;
    size_t Blocks = 0;
    double IOR = 0.0;
    int Verdict = GLASS_OK;
  };
  int CheckGlassProp(vtkProp* prop);
  bool QuietEmpty = false; ///< an empty piece is ordinary across ranks: no warning
  // Says once per prop that a translucent glass actor is left to VTK's translucent pass.
  void CheckOpacity(vtkProp* prop);
  // Says once per part that a glass prop inside an assembly is drawn as the assembly draws it.
  void CheckAssemblies(const vtkRenderState* s);
  std::map<vtkProp*, GlassCheck> GlassChecks;
  std::map<vtkProp*, double> WarnedOpacity;
  std::set<vtkProp*> WarnedAssemblyParts;
};

#endif
