#include "vtkGlassRenderView.h"

#include "vtkObjectFactory.h"
#include "vtkPVSynchronizedRenderer.h"
#include "vtkRefractionPass.h"

vtkStandardNewMacro(vtkGlassRenderView);

vtkGlassRenderView::vtkGlassRenderView()
  : GlassPass(vtkSmartPointer<vtkRefractionPass>::New())
{
  this->SynchronizedRenderers->SetRenderPass(this->GlassPass);
}

vtkGlassRenderView::~vtkGlassRenderView() = default;

void vtkGlassRenderView::AboutToRenderOnLocalProcess(bool interactive)
{
  this->Superclass::AboutToRenderOnLocalProcess(interactive);
  if (this->SynchronizedRenderers->GetRenderPass() != this->GlassPass)
  {
    this->SynchronizedRenderers->SetRenderPass(this->GlassPass);
  }
}

void vtkGlassRenderView::SetGlassMethod(int method)
{
  this->GlassPass->SetMethod(method);
  this->Modified();
}

int vtkGlassRenderView::GetGlassMethod()
{
  return this->GlassPass->GetMethod();
}

int vtkGlassRenderView::GetNumberOfGlassProps()
{
  return this->GlassPass->GetNumberOfGlassProps();
}

void vtkGlassRenderView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "GlassPass: " << this->GlassPass << "\n";
}
