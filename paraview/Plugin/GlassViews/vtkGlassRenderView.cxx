#include "vtkGlassRenderView.h"

#include "vtkDualDepthPeelingPass.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpaquePass.h"
#include "vtkOpenGLFXAAPass.h"
#include "vtkPVSynchronizedRenderer.h"
#include "vtkRefractionPass.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkSSAOPass.h"
#include "vtkTranslucentPass.h"

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
  // ParaView applies FXAA in vtkRenderer::UpdateGeometry, which its default pass calls and
  // this one does not; with an image processing pass (tone mapping) its own pass chain has an
  // FXAA pass. So: the glass pass inside an FXAA pass when FXAA is on and the chain has none.
  const bool fxaa = this->GetRenderer()->GetUseFXAA() &&
    this->SynchronizedRenderers->GetImageProcessingPass() == nullptr;
  vtkRenderPass* wanted = this->GlassPass;
  if (fxaa)
  {
    if (!this->FXAAPass)
    {
      this->FXAAPass = vtkSmartPointer<vtkOpenGLFXAAPass>::New();
      this->FXAAPass->SetDelegatePass(this->GlassPass);
    }
    this->FXAAPass->SetFXAAOptions(this->GetRenderer()->GetFXAAOptions());
    wanted = this->FXAAPass;
  }
  if (this->SynchronizedRenderers->GetRenderPass() != wanted)
  {
    this->SynchronizedRenderers->SetRenderPass(wanted);
  }
  this->ConfigureDelegate();
}

void vtkGlassRenderView::ConfigureDelegate()
{
  // vtkPVRenderView::Render has set the renderer's SSAO and peeling settings by now. ParaView's
  // own default pass gets them through vtkRenderer::UpdateGeometry; the refraction pass draws
  // the scene through a vtkRenderStepsPass, whose steps are chosen here to match.
  vtkRenderer* renderer = this->GetRenderer();
  const int ssao = renderer->GetUseSSAO() ? 1 : 0;
  const int peeling = renderer->GetUseDepthPeeling() ? 1 : 0;
  if (ssao != this->DelegateSSAO || peeling != this->DelegatePeeling)
  {
    vtkNew<vtkRenderStepsPass> steps;
    this->SSAOPass = nullptr;
    this->PeelingPass = nullptr;
    if (ssao)
    {
      this->SSAOPass = vtkSmartPointer<vtkSSAOPass>::New();
      vtkNew<vtkOpaquePass> opaque;
      this->SSAOPass->SetDelegatePass(opaque);
      steps->SetOpaquePass(this->SSAOPass);
    }
    if (peeling)
    {
      this->PeelingPass = vtkSmartPointer<vtkDualDepthPeelingPass>::New();
      vtkNew<vtkTranslucentPass> translucent;
      this->PeelingPass->SetTranslucentPass(translucent);
      steps->SetTranslucentPass(this->PeelingPass);
    }
    // The refraction pass takes the steps' opaque step and draws the glass after it.
    this->GlassPass->SetDelegatePass(steps);
    this->DelegateSSAO = ssao;
    this->DelegatePeeling = peeling;
  }
  if (this->SSAOPass)
  {
    this->SSAOPass->SetRadius(renderer->GetSSAORadius());
    this->SSAOPass->SetBias(renderer->GetSSAOBias());
    this->SSAOPass->SetKernelSize(renderer->GetSSAOKernelSize());
    this->SSAOPass->SetBlur(renderer->GetSSAOBlur());
  }
  if (this->PeelingPass)
  {
    this->PeelingPass->SetMaximumNumberOfPeels(renderer->GetMaximumNumberOfPeels());
    this->PeelingPass->SetOcclusionRatio(renderer->GetOcclusionRatio());
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

// The view's glass settings are the pass's; a change is the view's modification too, so that
// ParaView renders again.
#define vtkGlassRenderViewSetting(name, type, passSetter, passGetter)                           \
  void vtkGlassRenderView::SetGlass##name(type value)                                         \
  {                                                                                            \
    this->GlassPass->passSetter(value);                                                        \
    this->Modified();                                                                          \
  }                                                                                            \
  type vtkGlassRenderView::GetGlass##name() { return static_cast<type>(this->GlassPass->passGetter()); }

vtkGlassRenderViewSetting(Environment, int, SetEnvironmentMode, GetEnvironmentMode);
vtkGlassRenderViewSetting(SceneRefraction, int, SetSceneRefraction, GetSceneRefraction);
vtkGlassRenderViewSetting(TintFromColours, int, SetDataColour, GetDataColour);
vtkGlassRenderViewSetting(AbsorptionDistance, double, SetAbsorptionDistance, GetAbsorptionDistance);
vtkGlassRenderViewSetting(AntiAliasing, int, SetAntiAliasing, GetAntiAliasing);
vtkGlassRenderViewSetting(Layers, int, SetPeelLayers, GetPeelLayers);
vtkGlassRenderViewSetting(TIRBounces, int, SetTIRBounces, GetTIRBounces);

int vtkGlassRenderView::GetNumberOfGlassProps()
{
  return this->GlassPass->GetNumberOfGlassProps();
}

vtkRefractionPass* vtkGlassRenderView::GetGlassPass()
{
  return this->GlassPass;
}

void vtkGlassRenderView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "GlassPass: " << this->GlassPass << "\n";
  os << indent << "SSAOPass: " << this->SSAOPass << "\n";
  os << indent << "PeelingPass: " << this->PeelingPass << "\n";
  os << indent << "FXAAPass: " << this->FXAAPass << "\n";
}
