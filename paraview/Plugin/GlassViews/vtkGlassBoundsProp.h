/**
 * @class   vtkGlassBoundsProp
 * @brief   A prop that draws nothing and has the bounds it is given.
 *
 * IceT composites from each rank only the part of its image that the rank's visible props
 * project to. When the glass is composited across ranks, rank 0 shades all of it, including
 * the pieces other ranks hold: vtkGlassRenderView gives rank 0's renderer this prop, with the
 * bounds of the whole data, so that IceT takes rank 0's whole glass.
 */
#ifndef vtkGlassBoundsProp_h
#define vtkGlassBoundsProp_h

#include "RefractionGlassViewsModule.h" // For export macro
#include "vtkProp.h"

class REFRACTIONGLASSVIEWS_EXPORT vtkGlassBoundsProp : public vtkProp
{
public:
  static vtkGlassBoundsProp* New();
  vtkTypeMacro(vtkGlassBoundsProp, vtkProp);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  vtkSetVector6Macro(PropBounds, double);
  double* GetBounds() override { return this->PropBounds; }

protected:
  vtkGlassBoundsProp();
  ~vtkGlassBoundsProp() override;

  double PropBounds[6] = { 0.0, -1.0, 0.0, -1.0, 0.0, -1.0 };

private:
  vtkGlassBoundsProp(const vtkGlassBoundsProp&) = delete;
  void operator=(const vtkGlassBoundsProp&) = delete;
};

#endif
