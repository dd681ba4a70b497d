/**
 * @class   vtkGlassRenderView
 * @brief   ParaView's render view drawing through vtkRefractionPass.
 *
 * The pass is the geometry pass of the view's synchronized renderers (set again before each
 * local render, should the view have replaced it); representations
 * of type "Glass" (vtkGlassRepresentation) are drawn as refractive glass, every other one as
 * in a plain render view.
 */
#ifndef vtkGlassRenderView_h
#define vtkGlassRenderView_h

#include "RefractionGlassViewsModule.h" // For export macro
#include "vtkPVRenderView.h"
#include "vtkSmartPointer.h" // For members

class vtkRefractionPass;

class REFRACTIONGLASSVIEWS_EXPORT vtkGlassRenderView : public vtkPVRenderView
{
public:
  static vtkGlassRenderView* New();
  vtkTypeMacro(vtkGlassRenderView, vtkPVRenderView);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The pass's method: vtkRefractionPass::SIR (0), DIR (1, default), ISR (2), SSP (3),
  /// PEEL (4).
  void SetGlassMethod(int method);
  int GetGlassMethod();
  ///@}

  /// Glass props the pass drew in the last render (for tests).
  int GetNumberOfGlassProps();

protected:
  vtkGlassRenderView();
  ~vtkGlassRenderView() override;

  void AboutToRenderOnLocalProcess(bool interactive) override;

  vtkSmartPointer<vtkRefractionPass> GlassPass;

private:
  vtkGlassRenderView(const vtkGlassRenderView&) = delete;
  void operator=(const vtkGlassRenderView&) = delete;
};

#endif
