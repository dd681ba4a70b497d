/**
 * @class   vtkRefractionOpaqueStep
 * @brief   Stands in for a vtkRenderStepsPass's opaque step: opaque props, then the glass.
 *
 * It draws the opaque props through the original step, then the glass, so that translucent
 * geometry and overlays come after the glass as they come after opaque geometry. It holds
 * its owner by a plain pointer (the owner detaches it when it goes away), so no reference
 * cycle forms through the steps pass.
 */
#ifndef vtkRefractionOpaqueStep_h
#define vtkRefractionOpaqueStep_h

#include "vtkRenderPass.h"
#include "vtkSmartPointer.h" // For members

class vtkRefractionPass;

class vtkRefractionOpaqueStep : public vtkRenderPass
{
public:
  static vtkRefractionOpaqueStep* New();
  vtkTypeMacro(vtkRefractionOpaqueStep, vtkRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  vtkRefractionPass* Owner = nullptr;
  vtkSmartPointer<vtkRenderPass> Original;

protected:
  vtkRefractionOpaqueStep() = default;
  ~vtkRefractionOpaqueStep() override = default;

private:
  vtkRefractionOpaqueStep(const vtkRefractionOpaqueStep&) = delete;
  void operator=(const vtkRefractionOpaqueStep&) = delete;
};

#endif
