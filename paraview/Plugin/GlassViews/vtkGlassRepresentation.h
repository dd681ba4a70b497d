/**
 * @class   vtkGlassRepresentation
 * @brief   ParaView's Surface representation with its actor marked as refractive glass.
 *
 * The geometry, colouring and LOD handling are the Surface representation's (any data it
 * shows: polydata, the outer surface of grids and image data, multiblock and partitioned
 * data); the actor carries vtkRefractionPass's glass keys, so a view whose renderer draws
 * through vtkRefractionPass (vtkGlassRenderView) draws it as glass. In any other view it
 * renders as an ordinary surface.
 */
#ifndef vtkGlassRepresentation_h
#define vtkGlassRepresentation_h

#include "RefractionGlassViewsModule.h" // For export macro
#include "vtkGeometryRepresentationWithFaces.h"

class REFRACTIONGLASSVIEWS_EXPORT vtkGlassRepresentation : public vtkGeometryRepresentationWithFaces
{
public:
  static vtkGlassRepresentation* New();
  vtkTypeMacro(vtkGlassRepresentation, vtkGeometryRepresentationWithFaces);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Index of refraction of the glass (default 1.5); values vtkRefractionPass rejects
  /// (<= 0, NaN) get an error and leave the previous one.
  void SetIndexOfRefraction(double indexOfRefraction);
  vtkGetMacro(IndexOfRefraction, double);

  /// Dispersion: red is refracted with IndexOfRefraction - spread, blue with + spread
  /// (default 0: none). Negative or NaN spreads, or ones that take the red index to 0 or
  /// below, get an error and leave the previous one.
  void SetDispersion(double spread);
  vtkGetMacro(Dispersion, double);

protected:
  vtkGlassRepresentation();
  ~vtkGlassRepresentation() override;

  /// Put the index and dispersion on the actor's keys; false when the pass rejects them.
  bool MarkActor(double indexOfRefraction, double dispersion);

  double IndexOfRefraction = 1.5;
  double Dispersion = 0.0;

private:
  vtkGlassRepresentation(const vtkGlassRepresentation&) = delete;
  void operator=(const vtkGlassRepresentation&) = delete;
};

#endif
