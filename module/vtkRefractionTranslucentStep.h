/**
 * @class   vtkRefractionTranslucentStep
 * @brief   The translucent step of the pass's own vtkRenderStepsPass, as VTK's renderer does it.
 *
 * Without a render pass, vtkOpenGLRenderer draws translucent geometry with depth peeling
 * (dual where the driver allows) when UseDepthPeeling is on, and with order-independent
 * translucency otherwise. A vtkRenderStepsPass draws it with a vtkTranslucentPass alone:
 * unsorted, so translucent actors came out differently as soon as the refraction pass was
 * set, glass or not. This step reads the renderer's settings (UseDepthPeeling,
 * MaximumNumberOfPeels, OcclusionRatio) every frame and draws through the same passes the
 * renderer would, where the pass draws into the window; inside another pass's framebuffer
 * (a vtkFramebufferPass) it draws as a vtkRenderStepsPass does there. Then, as the renderer
 * does after its translucent geometry, the renderer's FXAA when UseFXAA is on (VTK skips it
 * with a render pass set).
 */
#ifndef vtkRefractionTranslucentStep_h
#define vtkRefractionTranslucentStep_h

#include "vtkRenderPass.h"
#include "vtkSmartPointer.h" // For members

class vtkDepthPeelingPass;
class vtkOpenGLFXAAFilter;
class vtkOrderIndependentTranslucentPass;
class vtkTranslucentPass;

class vtkRefractionTranslucentStep : public vtkRenderPass
{
public:
  static vtkRefractionTranslucentStep* New();
  vtkTypeMacro(vtkRefractionTranslucentStep, vtkRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  vtkRefractionTranslucentStep();
  ~vtkRefractionTranslucentStep() override;

private:
  vtkRefractionTranslucentStep(const vtkRefractionTranslucentStep&) = delete;
  void operator=(const vtkRefractionTranslucentStep&) = delete;

  /// The pass that draws the translucent props of this state, as the renderer would choose it.
  vtkRenderPass* TranslucentPass(const vtkRenderState* s);

  vtkSmartPointer<vtkDepthPeelingPass> Peeling; ///< made at the first frame that peels
  vtkSmartPointer<vtkOrderIndependentTranslucentPass> OrderIndependent;
  vtkSmartPointer<vtkTranslucentPass> Unsorted; ///< inside another pass's framebuffer
  vtkSmartPointer<vtkOpenGLFXAAFilter> FXAA;
};

#endif
