#include "vtkRefractionSelectionPass.h"

#include "vtkCameraPass.h"
#include "vtkHardwareSelector.h"
#include "vtkLightsPass.h"
#include "vtkObjectFactory.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkSequencePass.h"

//------------------------------------------------------------------------------
// The last step: what vtkRenderer::UpdateGeometry does with a selector.
class vtkRefractionSelectionPass::SelectorStep : public vtkRenderPass
{
public:
  static SelectorStep* New();
  vtkTypeMacro(SelectorStep, vtkRenderPass);

  void Render(const vtkRenderState* s) override
  {
    vtkRenderer* ren = s->GetRenderer();
    vtkHardwareSelector* selector = ren->GetSelector();
    this->NumberOfRenderedProps =
      selector ? selector->Render(ren, s->GetPropArray(), s->GetPropArrayCount()) : 0;
  }

protected:
  SelectorStep() = default;
  ~SelectorStep() override = default;
};
vtkStandardNewMacro(vtkRefractionSelectionPass::SelectorStep);

vtkStandardNewMacro(vtkRefractionSelectionPass);

//------------------------------------------------------------------------------
vtkRefractionSelectionPass::vtkRefractionSelectionPass()
{
  vtkNew<SelectorStep> selectorStep;
  vtkNew<vtkRenderPassCollection> steps;
  steps->AddItem(this->Lights);
  steps->AddItem(selectorStep);
  this->Sequence->SetPasses(steps);
  this->Camera->SetDelegatePass(this->Sequence);
}

//------------------------------------------------------------------------------
vtkRefractionSelectionPass::~vtkRefractionSelectionPass() = default;

//------------------------------------------------------------------------------
void vtkRefractionSelectionPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

//------------------------------------------------------------------------------
void vtkRefractionSelectionPass::Render(const vtkRenderState* s)
{
  this->Camera->Render(s);
  this->NumberOfRenderedProps = this->Camera->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
void vtkRefractionSelectionPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Camera->ReleaseGraphicsResources(w);
}
