/**
 * @class   vtkRefractionSelectionPass
 * @brief   Hardware selection (picking, ParaView's selections) through the refraction pass.
 *
 * VTK 9.1 draws a selection's ids only where the renderer has no render pass
 * (vtkRenderer::UpdateGeometry hands the props to its vtkHardwareSelector); with any pass set,
 * vtkRenderStepsPass included, vtkPropPicker and vtkHardwareSelector find nothing. While the
 * renderer has a selector, vtkRefractionPass renders through this pass instead: the camera
 * and the lights as vtkRenderStepsPass sets them, then the selector draws the props given
 * (the glass as its surface, like any opaque prop, so that it can be picked).
 */
#ifndef vtkRefractionSelectionPass_h
#define vtkRefractionSelectionPass_h

#include "vtkNew.h" // For members
#include "vtkRenderPass.h"

class vtkCameraPass;
class vtkLightsPass;
class vtkSequencePass;

class vtkRefractionSelectionPass : public vtkRenderPass
{
public:
  static vtkRefractionSelectionPass* New();
  vtkTypeMacro(vtkRefractionSelectionPass, vtkRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Draws the state's props into the renderer's selector (nothing without one).
  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  vtkRefractionSelectionPass();
  ~vtkRefractionSelectionPass() override;

private:
  vtkRefractionSelectionPass(const vtkRefractionSelectionPass&) = delete;
  void operator=(const vtkRefractionSelectionPass&) = delete;

  class SelectorStep;
  vtkNew<vtkCameraPass> Camera;
  vtkNew<vtkSequencePass> Sequence;
  vtkNew<vtkLightsPass> Lights;
};

#endif
