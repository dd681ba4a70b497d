/**
 * @class   vtkRefractionRendererOpaqueStep
 * @brief   The opaque step of the pass's own vtkRenderStepsPass, as VTK's renderer does it.
 *
 * Without a render pass, vtkOpenGLRenderer draws opaque geometry with hidden line removal
 * when UseHiddenLineRemoval is on and a prop is shown as wireframe, with screen-space ambient
 * occlusion when UseSSAO is on, and plainly otherwise; a vtkRenderStepsPass always draws it
 * plainly, so those settings were lost as soon as the refraction pass was set. This step
 * reads them every frame (SSAO's radius, bias, kernel size and blur too) and draws through
 * the passes the renderer would, where the pass draws into the window; inside another pass's
 * framebuffer it draws plainly, as a vtkRenderStepsPass does there. The glass follows it
 * (vtkRefractionOpaqueStep), so the glass refracts the scene as the renderer drew it.
 */
#ifndef vtkRefractionRendererOpaqueStep_h
#define vtkRefractionRendererOpaqueStep_h

#include "vtkNew.h" // For members
#include "vtkRenderPass.h"
#include "vtkSmartPointer.h" // For members

class vtkHiddenLineRemovalPass;
class vtkOpaquePass;
class vtkSSAOPass;

class vtkRefractionRendererOpaqueStep : public vtkRenderPass
{
public:
  static vtkRefractionRendererOpaqueStep* New();
  vtkTypeMacro(vtkRefractionRendererOpaqueStep, vtkRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  vtkRefractionRendererOpaqueStep();
  ~vtkRefractionRendererOpaqueStep() override;

private:
  vtkRefractionRendererOpaqueStep(const vtkRefractionRendererOpaqueStep&) = delete;
  void operator=(const vtkRefractionRendererOpaqueStep&) = delete;

  vtkNew<vtkOpaquePass> Opaque;
  vtkSmartPointer<vtkHiddenLineRemovalPass> HiddenLines; ///< made at the first frame using it
  vtkSmartPointer<vtkSSAOPass> AmbientOcclusion;         ///< made at the first frame using it
};

#endif
