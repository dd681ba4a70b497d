#include "vtkGlassRenderView.h"

#include "vtkDualDepthPeelingPass.h"
#include "vtkGlassBoundsProp.h"
#include "vtkGlassRankExchange.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpaquePass.h"
#include "vtkOpenGLFXAAPass.h"
#include "vtkPVLogger.h"
#include "vtkPVSynchronizedRenderer.h"
#include "vtkRefractionPass.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkSSAOPass.h"
#include "vtkTranslucentPass.h"

vtkStandardNewMacro(vtkGlassRenderView);

vtkGlassRenderView::vtkGlassRenderView()
  : GlassPass(vtkSmartPointer<vtkRefractionPass>::New())
  , RankExchange(vtkSmartPointer<vtkGlassRankExchange>::New())
  , BoundsProp(vtkSmartPointer<vtkGlassBoundsProp>::New())
{
  this->SynchronizedRenderers->SetRenderPass(this->GlassPass);
}

vtkGlassRenderView::~vtkGlassRenderView() = default;

void vtkGlassRenderView::AboutToRenderOnLocalProcess(bool interactive)
{
  this->Superclass::AboutToRenderOnLocalProcess(interactive);
  // Sort-last across ranks: every rank renders this frame and IceT composites the images.
  // One process, or a frame rendered on one process only (the data delivered there), has
  // nobody to exchange with.
  const bool acrossRanks = this->AcrossRanks && this->SynchronizedRenderers->GetEnabled() &&
    !this->SynchronizedRenderers->GetDataReplicatedOnAllProcesses() &&
    this->RankExchange->GetNumberOfRanks() > 1;

  // ParaView applies FXAA in vtkRenderer::UpdateGeometry, which its default pass calls and
  // this one does not; with an image processing pass (tone mapping) its own pass chain has an
  // FXAA pass. So FXAA is added here when it is on and the chain has none: around the glass
  // pass on one process; across ranks, on the composited image (IceT's image processing
  // pass), since an edge filter before the compositing would see each rank's part alone.
  vtkImageProcessingPass* imagePass = this->SynchronizedRenderers->GetImageProcessingPass();
  const bool ownImagePass = imagePass && imagePass == this->CompositedFXAAPass;
  const bool fxaa = this->GetRenderer()->GetUseFXAA() && (!imagePass || ownImagePass);
  vtkRenderPass* wanted = this->GlassPass;
  if (fxaa && acrossRanks)
  {
    if (!this->CompositedFXAAPass)
    {
      this->CompositedFXAAPass = vtkSmartPointer<vtkOpenGLFXAAPass>::New();
    }
    this->CompositedFXAAPass->SetFXAAOptions(this->GetRenderer()->GetFXAAOptions());
    if (!ownImagePass)
    {
      this->SynchronizedRenderers->SetImageProcessingPass(this->CompositedFXAAPass);
    }
  }
  else
  {
    if (ownImagePass)
    {
      this->SynchronizedRenderers->SetImageProcessingPass(nullptr);
    }
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
  }
  if (this->SynchronizedRenderers->GetRenderPass() != wanted)
  {
    this->SynchronizedRenderers->SetRenderPass(wanted);
  }
  this->ConfigureDelegate();

  // With PARAVIEW_LOG_RENDERING_VERBOSITY=INFO, each rank's frames and its exchange's calls
  // in the frame before: a rank whose counts differ from the others' is where a hang began.
  vtkVLogF(PARAVIEW_LOG_RENDERING_VERBOSITY(),
    "glass: across ranks %d (synchronized %d, replicated %d, ranks %d); the last frame's "
    "exchange: %d all-reduces, %d sends, %d receives",
    acrossRanks ? 1 : 0, this->SynchronizedRenderers->GetEnabled() ? 1 : 0,
    this->SynchronizedRenderers->GetDataReplicatedOnAllProcesses() ? 1 : 0,
    this->RankExchange->GetNumberOfRanks(), this->RankExchange->GetAllReduceCount(),
    this->RankExchange->GetSendCount(), this->RankExchange->GetReceiveCount());
  this->RankExchange->ResetCounts();
  this->GlassPass->SetRankExchange(acrossRanks ? this->RankExchange.GetPointer() : nullptr);
  this->CompositeRanks = acrossRanks ? this->RankExchange->GetNumberOfRanks() : 1;
  this->GlassPass->SetUseCompositingBackground(acrossRanks);
  this->GlassPass->SetCompositingBackground(this->GetRenderer()->GetBackground());
  // The exchange is collective: IceT must call every rank's pass, those with nothing visible
  // too (vtkPVRenderView::Render sets ParaView's own choice again before each frame). And
  // rank 0 shades the whole glass, so its image counts wherever the data are.
  if (acrossRanks)
  {
    this->SynchronizedRenderers->SetRenderEmptyImages(true);
  }
  const bool wholeBounds = acrossRanks && this->RankExchange->GetRank() == 0;
  vtkRenderer* renderer = this->GetRenderer();
  if (wholeBounds)
  {
    double bounds[6];
    this->GeometryBounds.GetBounds(bounds);
    this->BoundsProp->SetPropBounds(bounds);
    if (!renderer->HasViewProp(this->BoundsProp))
    {
      renderer->AddViewProp(this->BoundsProp);
    }
  }
  else if (renderer->HasViewProp(this->BoundsProp))
  {
    renderer->RemoveViewProp(this->BoundsProp);
  }
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
vtkGlassRenderViewSetting(CoarseShading, int, SetCoarseShading, GetCoarseShading);
vtkGlassRenderViewSetting(Layers, int, SetPeelLayers, GetPeelLayers);
vtkGlassRenderViewSetting(PeelCapture, int, SetPeelCapture, GetPeelCapture);
vtkGlassRenderViewSetting(TIRBounces, int, SetTIRBounces, GetTIRBounces);
vtkGlassRenderViewSetting(ExitReflection, int, SetExitReflection, GetExitReflection);
vtkGlassRenderViewSetting(SmoothInternalReflections, int, SetSmoothInternalReflections,
  GetSmoothInternalReflections);

int vtkGlassRenderView::GetNumberOfGlassProps()
{
  return this->GlassPass->GetNumberOfGlassProps();
}

double vtkGlassRenderView::GetGlassTextureBytes()
{
  return static_cast<double>(this->GlassPass->GetTextureBytes());
}

double vtkGlassRenderView::GetGlassCompositeMilliseconds()
{
  return this->GlassPass->GetCompositeMilliseconds();
}

double vtkGlassRenderView::GetGlassCompositeWaitMilliseconds()
{
  return this->GlassPass->GetCompositeWaitMilliseconds();
}

double vtkGlassRenderView::GetGlassCompositeBufferBytes()
{
  return static_cast<double>(this->GlassPass->GetCompositeBufferBytes());
}

void vtkGlassRenderView::SetGlassAcrossRanks(int on)
{
  this->AcrossRanks = on != 0;
  this->Modified();
}

int vtkGlassRenderView::GetGlassAcrossRanks()
{
  return this->AcrossRanks ? 1 : 0;
}

int vtkGlassRenderView::GetGlassCompositeRanks()
{
  return this->CompositeRanks;
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
  os << indent << "CompositedFXAAPass: " << this->CompositedFXAAPass << "\n";
  os << indent << "RankExchange: " << this->RankExchange << "\n";
  os << indent << "BoundsProp: " << this->BoundsProp << "\n";
  os << indent << "CompositeRanks: " << this->CompositeRanks << "\n";
}
