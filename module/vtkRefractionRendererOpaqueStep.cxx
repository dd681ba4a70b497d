#include "vtkRefractionRendererOpaqueStep.h"

#include "vtkHiddenLineRemovalPass.h"
#include "vtkObjectFactory.h"
#include "vtkOpaquePass.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkSSAOPass.h"

vtkStandardNewMacro(vtkRefractionRendererOpaqueStep);

//------------------------------------------------------------------------------
vtkRefractionRendererOpaqueStep::vtkRefractionRendererOpaqueStep() = default;
vtkRefractionRendererOpaqueStep::~vtkRefractionRendererOpaqueStep() = default;

//------------------------------------------------------------------------------
void vtkRefractionRendererOpaqueStep::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "HiddenLines: " << (this->HiddenLines ? "made" : "none") << "\n";
  os << indent << "AmbientOcclusion: " << (this->AmbientOcclusion ? "made" : "none") << "\n";
}

//------------------------------------------------------------------------------
void vtkRefractionRendererOpaqueStep::Render(const vtkRenderState* s)
{
  // What vtkOpenGLRenderer::DeviceRenderOpaqueGeometry does (VTK 9.1), with the state's
  // props instead of all of the renderer's.
  vtkRenderer* ren = s->GetRenderer();
  const bool window = ren && !s->GetFrameBuffer();
  vtkRenderPass* pass = this->Opaque;
  if (window && ren->GetUseHiddenLineRemoval() &&
    vtkHiddenLineRemovalPass::WireframePropsExist(s->GetPropArray(), s->GetPropArrayCount()))
  {
    if (!this->HiddenLines)
    {
      this->HiddenLines = vtkSmartPointer<vtkHiddenLineRemovalPass>::New();
    }
    pass = this->HiddenLines;
  }
  else if (window && ren->GetUseSSAO())
  {
    if (!this->AmbientOcclusion)
    {
      this->AmbientOcclusion = vtkSmartPointer<vtkSSAOPass>::New();
      vtkNew<vtkOpaquePass> opaque;
      this->AmbientOcclusion->SetDelegatePass(opaque);
    }
    this->AmbientOcclusion->SetRadius(ren->GetSSAORadius());
    this->AmbientOcclusion->SetBias(ren->GetSSAOBias());
    this->AmbientOcclusion->SetKernelSize(ren->GetSSAOKernelSize());
    this->AmbientOcclusion->SetBlur(ren->GetSSAOBlur());
    pass = this->AmbientOcclusion;
  }
  pass->Render(s);
  this->NumberOfRenderedProps = pass->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
void vtkRefractionRendererOpaqueStep::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Opaque->ReleaseGraphicsResources(w);
  if (this->HiddenLines)
  {
    this->HiddenLines->ReleaseGraphicsResources(w);
  }
  if (this->AmbientOcclusion)
  {
    this->AmbientOcclusion->ReleaseGraphicsResources(w);
  }
}
