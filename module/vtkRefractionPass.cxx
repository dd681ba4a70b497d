#include "vtkRefractionPass.h"

#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLState.h"
#include "vtkRefractionDepthRange.h"
#include "vtkRefractionFrameBuilder.h"
#include "vtkRefractionGBufferComposite.h"
#include "vtkRefractionGeometryStage.h"
#include "vtkRefractionGlassChecker.h"
#include "vtkRefractionGlassKeys.h"
#include "vtkRefractionLayerPack.h"
#include "vtkRefractionLights.h"
#include "vtkRefractionMaterials.h"
#include "vtkRefractionMethod.h"
#include "vtkRefractionOpaqueStep.h"
#include "vtkRefractionRankExchange.h"
#include "vtkRefractionRendererOpaqueStep.h"
#include "vtkRefractionSampleComposite.h"
#include "vtkRefractionSelectionPass.h"
#include "vtkRefractionSHTransfer.h"
#include "vtkRefractionShadeStage.h"
#include "vtkRefractionStageTimers.h"
#include "vtkRefractionSurfaceModel.h"
#include "vtkRefractionTargets.h"
#include "vtkRefractionTranslucentStep.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkTextureObject.h"

#include "rf_validate.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cstdio>

vtkStandardNewMacro(vtkRefractionPass);

//------------------------------------------------------------------------------
vtkRefractionPass::vtkRefractionPass()
{
  this->StageTimers->SetNumberOfStages(TIMED_STAGE_COUNT);
}

//------------------------------------------------------------------------------
vtkRefractionPass::~vtkRefractionPass()
{
  this->SetDelegatePass(nullptr);
}

//------------------------------------------------------------------------------
void vtkRefractionPass::SetDelegatePass(vtkRenderPass* delegatePass)
{
  if (delegatePass == this->DelegatePass)
  {
    return;
  }
  // Give the previous steps pass its own opaque step back.
  if (auto* steps = vtkRenderStepsPass::SafeDownCast(this->DelegatePass))
  {
    if (this->OpaqueStep && steps->GetOpaquePass() == this->OpaqueStep)
    {
      steps->SetOpaquePass(this->OpaqueStep->Original);
    }
  }
  if (this->OpaqueStep)
  {
    this->OpaqueStep->Owner = nullptr;
    this->OpaqueStep = nullptr;
  }
  vtkSetObjectBodyMacro(DelegatePass, vtkRenderPass, delegatePass);
  auto* steps = vtkRenderStepsPass::SafeDownCast(this->DelegatePass);
  if (steps && steps->GetOpaquePass())
  {
    this->OpaqueStep = vtkSmartPointer<vtkRefractionOpaqueStep>::New();
    this->OpaqueStep->Owner = this;
    this->OpaqueStep->Original = steps->GetOpaquePass();
    steps->SetOpaquePass(this->OpaqueStep);
  }
}

//------------------------------------------------------------------------------
void vtkRefractionPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  static const char* const names[] = { "SIR", "DIR", "ISR", "SSP", "PEEL", "SH" };
  os << indent << "Method: " << names[this->Method] << "\n";
  os << indent << "AdaptiveSearch: " << this->AdaptiveSearch << "\n";
  os << indent << "SecantRefinement: " << this->SecantRefinement << "\n";
  os << indent << "BackSurface: " << (this->BackSurface == BACK_SURFACE_NEAREST ? "nearest" : "furthest") << "\n";
  os << indent << "SSPStrength: " << this->SSPStrength << "\n";
  os << indent << "SSPFresnelBias: " << this->SSPFresnelBias << "\n";
  os << indent << "SSPFresnelPower: " << this->SSPFresnelPower << "\n";
  os << indent << "ChromaticAberration: " << this->ChromaticAberration << "\n";
  os << indent << "SearchSteps: " << this->SearchSteps << "\n";
  os << indent << "DepthRangeMode: "
     << (this->DepthRangeMode == DEPTH_RANGE_REDUCTION ? "reduction" : "bounds") << "\n";
  os << indent << "TIRPolicy: " << (this->TIRPolicy == TIR_CLAMP ? "clamp" : "reflect") << "\n";
  os << indent << "Fresnel: " << this->Fresnel << "\n";
  os << indent << "FilteredLookups: " << this->FilteredLookups << "\n";
  os << indent << "AntiAliasing: " << this->AntiAliasing << "\n";
  os << indent << "CoarseShading: " << this->CoarseShading << "\n";
  os << indent << "MultiSampleSilhouette: " << this->MultiSampleSilhouette << "\n";
  os << indent << "CompositeProgram: "
     << (this->CompositeProgram == COMPOSITE_PROGRAM_SEPARATE ? "separate"
           : this->CompositeProgram == COMPOSITE_PROGRAM_SHARED ? "shared"
                                                                : "auto")
     << "\n";
  os << indent << "TIRBounces: " << this->TIRBounces << "\n";
  os << indent << "ExitReflection: " << this->ExitReflection << "\n";
  os << indent << "SmoothInternalReflections: " << this->SmoothInternalReflections << "\n";
  os << indent << "PeelLayers: " << this->PeelLayers << "\n";
  os << indent << "PeelLayersFound: " << this->PeelLayersFound << "\n";
  os << indent << "PeelLayersDrawn: " << this->PeelLayersDrawn << "\n";
  os << indent << "PeelFacingCulled: " << this->PeelFacingCulled << "\n";
  os << indent
     << "PeelFacingPossible: " << this->GeometryStage->GetPeelFacingPossible() << "\n";
  os << indent << "PeelCapture: " << this->PeelCapture << "\n";
  os << indent << "SHSmoothing: " << this->SHSmoothing << "\n";
  os << indent << "EnvironmentMode: "
     << (this->EnvironmentMode == ENVIRONMENT_RENDERER ? "renderer" : "builtin") << "\n";
  os << indent << "SceneRefraction: " << this->SceneRefraction << "\n";
  os << indent << "DataColour: " << this->DataColour << "\n";
  os << indent << "AbsorptionDistance: " << this->AbsorptionDistance << "\n";
  os << indent << "TextureBytes: " << this->GetTextureBytes() << "\n";
  os << indent << "DebugOutput: " << this->DebugOutput << "\n";
  os << indent << "NumberOfGlassProps: " << this->NumberOfGlassProps << "\n";
  os << indent << "RankExchange: " << this->RankExchange << "\n";
  os << indent << "UseCompositingBackground: " << this->UseCompositingBackground << "\n";
  os << indent << "DelegatePass: ";
  if (this->DelegatePass)
  {
    this->DelegatePass->PrintSelf(os, indent.GetNextIndent());
  }
  else
  {
    os << "(none)\n";
  }
}

//------------------------------------------------------------------------------
void vtkRefractionPass::SetSearchSteps(int steps)
{
  if (rf_validate_cbs_steps(steps) != RF_OK)
  {
    vtkErrorMacro("SearchSteps " << steps << " rejected: "
                                 << rf_status_message(rf_validate_cbs_steps(steps))
                                 << " Keeping " << this->SearchSteps << ".");
    return;
  }
  if (steps != this->SearchSteps)
  {
    this->SearchSteps = steps;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkImageData* vtkRefractionPass::GetDebugImage()
{
  return this->DebugImage;
}

//------------------------------------------------------------------------------
double vtkRefractionPass::GetStageMilliseconds(int stage)
{
  if (stage < 0 || stage >= TIMED_STAGE_COUNT)
  {
    return -1.0;
  }
  return this->StageTimers->GetMilliseconds(stage);
}

//------------------------------------------------------------------------------
const char* vtkRefractionPass::GetStageName(int stage)
{
  static const char* const names[TIMED_STAGE_COUNT] = { "back capture", "depth range", "front",
    "shade" };
  return stage >= 0 && stage < TIMED_STAGE_COUNT ? names[stage] : nullptr;
}

//------------------------------------------------------------------------------
unsigned long long vtkRefractionPass::GetTextureBytes() const
{
  return this->Targets->GetBytes() + this->GeometryStage->GetSHBytes();
}

//------------------------------------------------------------------------------
void vtkRefractionPass::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  this->NumberOfGlassProps = 0;
  if (!this->DelegatePass)
  {
    vtkNew<vtkRenderStepsPass> steps;
    // Opaque and translucent geometry as VTK's renderer draws them without a pass (hidden
    // line removal, SSAO; depth peeling or order-independent translucency, FXAA), not plainly.
    vtkNew<vtkRefractionRendererOpaqueStep> opaque;
    steps->SetOpaquePass(opaque);
    vtkNew<vtkRefractionTranslucentStep> translucent;
    steps->SetTranslucentPass(translucent);
    this->SetDelegatePass(steps);
  }
  if (s->GetRenderer()->GetSelector())
  {
    this->RenderSelection(s);
    return;
  }
  if (this->OpaqueStep)
  {
    // The steps pass calls back RenderOpaqueAndGlass in place of its opaque step.
    this->DelegatePass->Render(s);
    this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
    return;
  }
  // Another kind of delegate: it draws everything but the glass, then the glass goes on top.
  std::vector<vtkProp*> glass;
  std::vector<vtkProp*> others;
  this->GlassChecker->SplitProps(s, glass, &others, this->CompositingExchange() != nullptr);
  // Compositing across ranks, a rank without glass still takes part in the frame's exchange.
  if (glass.empty() && static_cast<int>(others.size()) == s->GetPropArrayCount() &&
    !this->CompositingExchange())
  {
    this->DelegatePass->Render(s);
    this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
    return;
  }
  // Glass props refused (vtkRefractionGlassChecker) are in neither list: not drawn at all.
  vtkRenderState othersState(s->GetRenderer());
  othersState.SetFrameBuffer(s->GetFrameBuffer());
  othersState.SetRequiredKeys(s->GetRequiredKeys());
  othersState.SetPropArrayAndCount(others.data(), static_cast<int>(others.size()));
  this->DelegatePass->Render(&othersState);
  this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
  this->RenderGlass(s, glass, !others.empty());
}

//------------------------------------------------------------------------------
void vtkRefractionPass::RenderSelection(const vtkRenderState* s)
{
  // The props the frame would draw, glass included, in their order; the glass props the
  // checker refuses stay out, as in a frame.
  std::vector<vtkProp*> glass;
  std::vector<vtkProp*> others;
  this->GlassChecker->SplitProps(s, glass, &others, this->CompositingExchange() != nullptr);
  std::vector<vtkProp*> props;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    if (std::find(glass.begin(), glass.end(), prop) != glass.end() ||
      std::find(others.begin(), others.end(), prop) != others.end())
    {
      props.push_back(prop);
    }
  }
  vtkRenderState selection(s->GetRenderer());
  selection.SetFrameBuffer(s->GetFrameBuffer());
  selection.SetRequiredKeys(s->GetRequiredKeys());
  selection.SetPropArrayAndCount(props.data(), static_cast<int>(props.size()));
  this->SelectionPass->Render(&selection);
  this->NumberOfRenderedProps = this->SelectionPass->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
int vtkRefractionPass::RenderOpaqueAndGlass(const vtkRenderState* s, vtkRenderPass* opaque)
{
  std::vector<vtkProp*> glass;
  std::vector<vtkProp*> others;
  this->GlassChecker->SplitProps(s, glass, &others, this->CompositingExchange() != nullptr);
  this->NumberOfRenderedProps = 0;
  if (glass.empty() && static_cast<int>(others.size()) == s->GetPropArrayCount() &&
    !this->CompositingExchange())
  {
    opaque->Render(s);
    return opaque->GetNumberOfRenderedProps();
  }
  vtkRenderState othersState(s->GetRenderer());
  othersState.SetFrameBuffer(s->GetFrameBuffer());
  othersState.SetRequiredKeys(s->GetRequiredKeys());
  othersState.SetPropArrayAndCount(others.data(), static_cast<int>(others.size()));
  opaque->Render(&othersState);
  this->NumberOfRenderedProps = opaque->GetNumberOfRenderedProps();
  this->RenderGlass(s, glass, !others.empty());
  return this->NumberOfRenderedProps;
}

//------------------------------------------------------------------------------
void vtkRefractionPass::RenderGlass(
  const vtkRenderState* s, std::vector<vtkProp*>& glass, bool opaqueScene)
{
  this->NumberOfGlassProps = static_cast<int>(glass.size());
  this->Composited = false;
  // With ranks to composite across, every decision below that the ranks' pieces could take
  // differently is taken together (a maximum over the ranks), so that they all draw the same
  // targets and meet in the same exchange.
  vtkRefractionRankExchange* exchange = this->CompositingExchange();
  auto agree = [exchange](bool local) -> bool {
    if (!exchange)
    {
      return local;
    }
    int value = local ? 1 : 0;
    exchange->AllReduceMax(&value, 1);
    return value != 0;
  };
  if (!agree(!glass.empty()))
  {
    return;
  }
  // Errors of the passes before this one are theirs (VTK's own clear is compiled out).
  for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i)
  {
  }
  vtkOpenGLRenderer* ren = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  vtkOpenGLRenderWindow* renWin =
    ren ? vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow()) : nullptr;
  if (!renWin)
  {
    vtkErrorMacro("vtkRefractionPass needs an OpenGL renderer and render window.");
    return;
  }
  ren->GetTiledSizeAndOrigin(&this->Width, &this->Height, this->ViewportOrigin,
    this->ViewportOrigin + 1);
  if (this->Width < 1 || this->Height < 1)
  {
    // Nothing to allocate or draw; say so once, until the viewport has pixels again.
    if (!this->WarnedEmptyViewport)
    {
      vtkWarningMacro("The viewport of renderer " << ren << " is " << this->Width << " x "
                                                  << this->Height << " pixels: the "
                                                  << glass.size()
                                                  << " glass prop(s) are not drawn.");
      this->WarnedEmptyViewport = true;
    }
    return;
  }
  this->WarnedEmptyViewport = false;
  int methodType = this->Method;
  if (methodType == SH)
  {
    std::string reason;
    if (agree(!glass.empty() && !vtkRefractionSHTransfer::Check(glass, reason)))
    {
      if (reason.empty())
      {
        reason = "another rank's piece cannot use it";
      }
      if (reason != this->WarnedSHTransfer)
      {
        vtkWarningMacro("SH: " << reason << "; drawing the glass with DIR.");
      }
      this->WarnedSHTransfer = reason;
      methodType = DIR;
    }
    else
    {
      this->WarnedSHTransfer.clear();
    }
  }
  if (!this->MethodObject || this->MethodObjectType != methodType)
  {
    this->MethodObject = vtkRefractionMethod::Create(methodType);
    this->MethodObjectType = methodType;
  }
  vtkRefractionMethod* method = this->MethodObject;
  const bool reduction =
    method->NeedsDepthRange() && this->DepthRangeMode == DEPTH_RANGE_REDUCTION;
  // The scene behind the glass is captured only where it can show: opaque props drawn, a
  // method that follows rays through it.
  bool sceneRefraction =
    this->SceneRefraction && agree(opaqueScene) && method->SupportsSceneRefraction();
  // Composited across ranks, SSP's scene colour is merged by the scene's depth, so captured
  // with it too.
  bool sceneCapture = sceneRefraction || (exchange && method->NeedsSceneColor());
  if (sceneCapture)
  {
    std::string error;
    if (agree(!this->Targets->MatchSceneDepth(error)))
    {
      if (error.empty())
      {
        error = "another rank's framebuffer has no depth to capture";
      }
      if (error != this->WarnedSceneDepth)
      {
        vtkErrorMacro("Scene refraction is off: " << error << ".");
      }
      this->WarnedSceneDepth = error;
      sceneRefraction = false;
      sceneCapture = false;
    }
    else
    {
      this->WarnedSceneDepth.clear();
    }
  }
  std::vector<bool> wanted;
  method->AddTargets(wanted, this);
  const int peelLayers = method->GetPeelLayers(this);
  // AUTO: the k-buffer's fixed cost (its clears, two draws of every fragment with atomics)
  // beats peeling on llvmpipe only where many layers are drawn (SetPeelCapture), and not
  // where the layers can be peeled one facing at a time, each draw half the fragments. Not
  // across ranks, where every layer is drawn and no test runs the k-buffer yet.
  const bool peelKBuffer = peelLayers > 2 &&
    (this->PeelCapture == PEEL_CAPTURE_K_BUFFER ||
      (this->PeelCapture == PEEL_CAPTURE_AUTO && !exchange && peelLayers >= 6 &&
        this->PeelLayersFound > 3 && !this->GeometryStage->GetPeelFacingPossible())) &&
    vtkRefractionGeometryStage::SupportsPeelKBuffer(renWin, this->Height, peelLayers);
  wanted[vtkRefractionTargets::PEEL_SLOTS] = peelKBuffer;
  this->Targets->SetPeelSlots(peelLayers - 1);
  if (sceneCapture)
  {
    wanted[vtkRefractionTargets::SCENE_COLOR] = true;
    wanted[vtkRefractionTargets::SCENE_DEPTH] = true;
  }
  this->GeometryStage->GetSurfaceModel()->SetAcrossRanks(exchange != nullptr);
  // Across ranks, what is sized from the glass's bounds (PEEL's and DIR's search lengths,
  // PEEL's fault test, the automatic sheet thickness and tint) is sized from the whole props'.
  const std::vector<double> wholeBounds =
    exchange ? AgreeGlassBounds(glass, exchange) : std::vector<double>();
  this->Materials->Update(glass, this->GeometryStage->GetSurfaceModel(),
    this->DataColour && method->SupportsSceneRefraction(), this->AbsorptionDistance,
    this->ThinSheetThickness, exchange ? &wholeBounds : nullptr);
  const bool dataColour = agree(this->Materials->GetDataColour());
  wanted[vtkRefractionTargets::FRONT_COLOR] = dataColour;
  wanted[vtkRefractionTargets::GLASS_COLOR] = true; // the shading stage's output
  wanted[vtkRefractionTargets::GLASS_COLOR_SHADED] =
    this->SmoothInternalReflections && !this->AntiAliasing;
  wanted[vtkRefractionTargets::CORNER_Z] = this->AntiAliasing;
  const bool coarse = this->CoarseShading && !this->AntiAliasing;
  wanted[vtkRefractionTargets::COARSE_COLOR] = coarse;
  wanted[vtkRefractionTargets::COARSE_RAY] = coarse;
  wanted[vtkRefractionTargets::COARSE_Z] = coarse;
  wanted[vtkRefractionTargets::TRACE_Z] = coarse;
  wanted[vtkRefractionTargets::DEBUG_0] = this->DebugOutput;
  wanted[vtkRefractionTargets::DEBUG_1] = this->DebugOutput;
  this->Targets->Update(renWin, this->Width, this->Height, wanted, reduction);
  vtkRefractionShadeStage::Frame frame = this->FrameBuilder->Build(ren, this,
    this->EnvironmentMode == ENVIRONMENT_RENDERER, sceneRefraction,
    this->MultiSampleSilhouette && !exchange,
    this->Materials, this->Lights, this->BoundsDepthRange);
  frame.SmoothInternalReflections = this->SmoothInternalReflections && !this->AntiAliasing;
  frame.CoarseShading = coarse;
  // Where the glass can be on screen: the shading and the composite run there only. Across
  // ranks rank 0 shades every rank's glass, which its own props do not bound.
  frame.GlassRectangle[2] = this->Width;
  frame.GlassRectangle[3] = this->Height;
  if (!exchange)
  {
    // Two pixels of margin: anti-aliasing shades a pixel's corners, which reach one pixel
    // past it, and its composite averages the corner one pixel further on.
    vtkRefractionDepthRange::ComputeScreenRectangle(
      ren, glass, this->Width, this->Height, 2, frame.GlassRectangle);
  }
  // A compositor that draws each rank over black (IceT) has the real background given here.
  const bool compositingBackground = exchange && this->UseCompositingBackground;
  if (compositingBackground)
  {
    const bool gradient = ren->GetGradientBackground();
    for (int c = 0; c < 3; ++c)
    {
      frame.Background[c] = this->CompositingBackground[c];
      if (!gradient)
      {
        frame.Background2[c] = this->CompositingBackground[c];
      }
    }
  }
  if (!this->ShadeStage->Prepare(ren, method, this, frame, false))
  {
    return;
  }
  const std::vector<float>& materialIOR = this->Materials->GetIndexOfRefraction();
  const std::vector<float>& materialSheet = this->Materials->GetSheetThickness();
  if (static_cast<int>(glass.size()) > vtkRefractionShadeStage::MaximumMaterials)
  {
    vtkWarningMacro(<< glass.size() << " glass props: the last "
                    << glass.size() - vtkRefractionShadeStage::MaximumMaterials + 1
                    << " share one index of refraction (at most "
                    << vtkRefractionShadeStage::MaximumMaterials << " are told apart).");
  }
  this->GeometryStage->SetPeelKBuffer(peelKBuffer ? peelLayers : 0);
  this->GeometryStage->SetSHSmoothing(this->SHSmoothing);
  this->GeometryStage->SetSheetPieceMaterials(this->Materials->GetSheetPieceMaterial());
  this->GeometryStage->SetSignedFront(exchange && peelLayers > 1);
  this->GeometryStage->SetSampleComposite(frame.SampleComposite);
  this->GeometryStage->SetSeparateCompositeProgram(
    this->CompositeProgram == COMPOSITE_PROGRAM_SEPARATE ||
    (this->CompositeProgram == COMPOSITE_PROGRAM_AUTO && frame.SampleComposite &&
      vtkRefractionSampleComposite::IsSoftwareRasterizer()));
  this->GeometryStage->Configure(glass, method->NeedsNormalDistance(), dataColour,
    this->BackSurface == BACK_SURFACE_NEAREST, peelLayers > 1, method->NeedsSHTransfer(),
    frame.InverseProjection, frame.Parallel);

  // Stages this method does not run report no time (not the last method's).
  this->StageTimers->SetEnabled(this->GPUTiming);
  for (int stage = 0; stage < TIMED_STAGE_COUNT; ++stage)
  {
    const bool runs =
      (stage != TIMED_BACK_CAPTURE || method->NeedsBackSurface() || peelLayers > 1) &&
      (stage != TIMED_DEPTH_RANGE || method->NeedsDepthRange());
    if (!runs)
    {
      this->StageTimers->Forget(stage);
    }
  }
  if (sceneCapture)
  {
    this->CaptureScene(ren, true); // before any glass is drawn into the framebuffer
  }
  if (method->NeedsBackSurface())
  {
    this->StageTimers->Start(TIMED_BACK_CAPTURE);
    this->GeometryStage->DrawBack(ren, this->Targets);
    this->StageTimers->Stop(TIMED_BACK_CAPTURE);
  }
  this->StageTimers->Start(TIMED_FRONT);
  this->GeometryStage->DrawFront(ren, this->Targets);
  if (method->NeedsSceneColor() && !exchange)
  {
    this->GeometryStage->DrawMask(ren);
    this->CaptureScene(ren, false);
  }
  this->StageTimers->Stop(TIMED_FRONT);
  this->NumberOfRenderedProps += this->GeometryStage->GetNumberOfDrawnProps();
  if (exchange &&
    !this->CompositeAcrossRanks(ren, renWin, glass, method, frame.Background, frame.Background2,
      peelLayers, reduction, dataColour, sceneCapture, compositingBackground, exchange))
  {
    return; // rank 0 shades the whole glass
  }
  // After the front capture, which does not read it: llvmpipe rasterizes the back capture
  // while it bins the front one, and waits for the back capture only here.
  if (method->NeedsDepthRange())
  {
    this->StageTimers->Start(TIMED_DEPTH_RANGE);
    if (reduction)
    {
      this->DepthRange->Reduce(renWin, this->Targets, frame.GlassRectangle);
    }
    else if (!exchange) // agreed over the ranks above
    {
      vtkRefractionDepthRange::ComputeBounds(ren, glass, this->BoundsDepthRange);
    }
    this->StageTimers->Stop(TIMED_DEPTH_RANGE);
  }
  if (peelLayers > 1)
  {
    this->StageTimers->Start(TIMED_BACK_CAPTURE);
    this->PeelLayersFound = peelLayers;
    if (!exchange) // drawn and composited above
    {
      vtkRefractionDepthRange::ComputeBounds(ren, glass, this->BoundsDepthRange);
      this->PeelLayersFound =
        this->GeometryStage->DrawPeelLayers(ren, this->Targets, peelLayers, true);
      this->PeelLayersDrawn = this->GeometryStage->GetPeelDraws();
      this->PeelFacingCulled = this->GeometryStage->GetPeelByFacing();
    }
    const bool packed =
      this->LayerPack->Pack(
        renWin, this->Targets, peelLayers, this->PeelLayersFound, frame.GlassRectangle);
    this->StageTimers->Stop(TIMED_BACK_CAPTURE);
    if (!packed)
    {
      return;
    }
  }

  this->StageTimers->Start(TIMED_SHADE);
  this->ShadeStage->Render(ren, method, this, this->Targets, frame, materialIOR, materialSheet);
  if (frame.SampleComposite)
  {
    this->SampleComposite->Render(
      ren, this->GeometryStage, this->Targets, this->AntiAliasing, frame.GlassRectangle);
  }
  this->StageTimers->Stop(TIMED_SHADE);
  if (this->DebugOutput)
  {
    // None rather than the last frame's where this frame's debug program cannot be built.
    this->DebugImage = this->ShadeStage->Prepare(ren, method, this, frame, true)
      ? this->ShadeStage->RenderDebug(
          ren, method, this, this->Targets, frame, materialIOR, materialSheet)
      : nullptr;
  }
  this->ReportGLError("the refraction pass's frame");
}

//------------------------------------------------------------------------------
void vtkRefractionPass::CaptureScene(vtkOpenGLRenderer* ren, bool depth)
{
  // The viewport of the scene drawn so far (colour, with SSP's mask in alpha, and with
  // `depth` its depth) into the textures the glass samples, by one blit: it resolves a
  // multisampled window (VTK's default), which a texture copy from the framebuffer cannot
  // read. SCENE_DEPTH has the scene's depth format (MatchSceneDepth), as a depth blit needs.
  vtkOpenGLState* ostate = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow())->GetState();
  vtkOpenGLFramebufferObject* fbo = this->Targets->GetFramebuffer();
  fbo->SaveCurrentBindingsAndBuffers();
  fbo->Bind(GL_DRAW_FRAMEBUFFER);
  fbo->AddColorAttachment(0, this->Targets->Get(vtkRefractionTargets::SCENE_COLOR));
  fbo->ActivateDrawBuffers(1);
  if (depth)
  {
    fbo->AddDepthAttachment(this->Targets->Get(vtkRefractionTargets::SCENE_DEPTH));
  }
  {
    vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
    ostate->vtkglScissor(0, 0, this->Width, this->Height);
    ostate->vtkglBlitFramebuffer(this->ViewportOrigin[0], this->ViewportOrigin[1],
      this->ViewportOrigin[0] + this->Width, this->ViewportOrigin[1] + this->Height, 0, 0,
      this->Width, this->Height, GL_COLOR_BUFFER_BIT | (depth ? GL_DEPTH_BUFFER_BIT : 0),
      GL_NEAREST);
  }
  if (depth)
  {
    fbo->RemoveDepthAttachment();
  }
  fbo->UnBind(GL_DRAW_FRAMEBUFFER);
  fbo->RestorePreviousBindingsAndBuffers();
  this->ReportGLError(depth ? "glBlitFramebuffer of the scene's colour and depth"
                            : "glBlitFramebuffer of the scene's colour");
}

//------------------------------------------------------------------------------
void vtkRefractionPass::ReportGLError(const char* call)
{
  const GLenum code = glGetError();
  if (code == GL_NO_ERROR)
  {
    return;
  }
  for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i)
  {
  }
  const std::string where(call);
  if (this->ReportedGLErrors.insert(where).second)
  {
    // vtkErrorMacro's stream takes no manipulators (std::hex would print as "1").
    char hex[16];
    std::snprintf(hex, sizeof(hex), "0x%04X", static_cast<unsigned>(code));
    vtkErrorMacro("OpenGL error " << vtkOpenGLStrError(code) << " (" << hex << ") in " << where
                                  << "; reported once per call.");
  }
}

//------------------------------------------------------------------------------
void vtkRefractionPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  if (this->DelegatePass)
  {
    this->DelegatePass->ReleaseGraphicsResources(w);
  }
  this->GeometryStage->ReleaseGraphicsResources(w);
  this->SelectionPass->ReleaseGraphicsResources(w);
  this->DepthRange->ReleaseGraphicsResources(w);
  this->LayerPack->ReleaseGraphicsResources(w);
  this->ShadeStage->ReleaseGraphicsResources(w);
  this->SampleComposite->ReleaseGraphicsResources(w);
  this->Targets->ReleaseGraphicsResources(w);
  this->StageTimers->ReleaseGraphicsResources();
  this->Width = 0;
  this->Height = 0;
}
