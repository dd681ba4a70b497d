#include "vtkRefractionPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleKey.h"
#include "vtkInformationIntegerKey.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkPoints.h"
#include "vtkPolyDataMapper.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderTimer.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLTexture.h"
#include "vtkCellArray.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "rfShaders.h"
#include "rf_validate.h"

#include <algorithm>
#include <functional>
#include <cmath>
#include <sstream>

// Stands in for a vtkRenderStepsPass's opaque step: it draws the opaque props through the
// original step, then the glass, so that translucent geometry and overlays come after the
// glass as they come after opaque geometry. It holds its owner by a plain pointer (the owner
// detaches it when it goes away), so no reference cycle forms through the steps pass.
class vtkRefractionOpaqueStep : public vtkRenderPass
{
public:
  static vtkRefractionOpaqueStep* New();
  vtkTypeMacro(vtkRefractionOpaqueStep, vtkRenderPass);

  void Render(const vtkRenderState* s) override
  {
    if (this->Owner)
    {
      this->NumberOfRenderedProps = this->Owner->RenderOpaqueAndGlass(s, this->Original);
    }
    else if (this->Original)
    {
      this->Original->Render(s);
      this->NumberOfRenderedProps = this->Original->GetNumberOfRenderedProps();
    }
  }
  void ReleaseGraphicsResources(vtkWindow* w) override
  {
    if (this->Original)
    {
      this->Original->ReleaseGraphicsResources(w);
    }
  }

  vtkRefractionPass* Owner = nullptr;
  vtkSmartPointer<vtkRenderPass> Original;

protected:
  vtkRefractionOpaqueStep() = default;
  ~vtkRefractionOpaqueStep() override = default;

private:
  vtkRefractionOpaqueStep(const vtkRefractionOpaqueStep&) = delete;
  void operator=(const vtkRefractionOpaqueStep&) = delete;
};
vtkStandardNewMacro(vtkRefractionOpaqueStep);

vtkStandardNewMacro(vtkRefractionPass);
vtkInformationKeyMacro(vtkRefractionPass, GLASS, Integer);
vtkInformationKeyMacro(vtkRefractionPass, INDEX_OF_REFRACTION, Double);

namespace
{
const char* const kImplMarker = "//RF::Impl";
const char* const kEnvironmentMarker = "//RF::Environment";

vtkInformation* GetOrCreateKeys(vtkProp* prop)
{
  vtkInformation* keys = prop->GetPropertyKeys();
  if (!keys)
  {
    vtkNew<vtkInformation> created;
    prop->SetPropertyKeys(created);
    keys = created;
  }
  return keys;
}

vtkSmartPointer<vtkTextureObject> MakeTexture(vtkOpenGLRenderWindow* renWin, int width,
  int height, int components, int internalFormat, int format, int filter)
{
  auto texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(renWin);
  texture->SetInternalFormat(internalFormat);
  texture->SetFormat(format);
  texture->SetDataType(GL_FLOAT);
  texture->SetMinificationFilter(filter);
  texture->SetMagnificationFilter(filter);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->Allocate2D(width, height, components, VTK_FLOAT);
  return texture;
}
}

//------------------------------------------------------------------------------
vtkRefractionPass::vtkRefractionPass() = default;

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
  static const char* const names[] = { "SIR", "DIR", "ISR", "SSP" };
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
  os << indent << "DebugOutput: " << this->DebugOutput << "\n";
  os << indent << "NumberOfGlassProps: " << this->NumberOfGlassProps << "\n";
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
bool vtkRefractionPass::MakeGlass(vtkProp* prop, double indexOfRefraction)
{
  if (!prop)
  {
    vtkGenericWarningMacro("vtkRefractionPass::MakeGlass: no prop given.");
    return false;
  }
  const rf_status status = rf_validate_ior(indexOfRefraction);
  if (status != RF_OK)
  {
    vtkErrorWithObjectMacro(prop, "vtkRefractionPass::MakeGlass: index of refraction "
        << indexOfRefraction << " rejected for " << prop->GetClassName() << " " << prop << ": "
        << rf_status_message(status) << ". The prop is not marked as glass.");
    return false;
  }
  vtkInformation* keys = GetOrCreateKeys(prop);
  keys->Set(GLASS(), 1);
  keys->Set(INDEX_OF_REFRACTION(), indexOfRefraction);
  prop->Modified();
  return true;
}

//------------------------------------------------------------------------------
void vtkRefractionPass::ClearGlass(vtkProp* prop)
{
  vtkInformation* keys = prop ? prop->GetPropertyKeys() : nullptr;
  if (keys)
  {
    keys->Remove(GLASS());
    keys->Remove(INDEX_OF_REFRACTION());
    prop->Modified();
  }
}

//------------------------------------------------------------------------------
bool vtkRefractionPass::IsGlass(vtkProp* prop)
{
  vtkInformation* keys = prop ? prop->GetPropertyKeys() : nullptr;
  return keys && keys->Has(GLASS()) && keys->Get(GLASS()) != 0;
}

//------------------------------------------------------------------------------
double vtkRefractionPass::GetIndexOfRefraction(vtkProp* prop)
{
  vtkInformation* keys = prop ? prop->GetPropertyKeys() : nullptr;
  return keys && keys->Has(INDEX_OF_REFRACTION()) ? keys->Get(INDEX_OF_REFRACTION()) : 1.5;
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
void vtkRefractionPass::StartTimer(int stage)
{
  if (!this->GPUTiming || !vtkOpenGLRenderTimer::IsSupported())
  {
    return;
  }
  auto& timer = this->Timers[stage];
  if (!timer)
  {
    timer.reset(new vtkOpenGLRenderTimer);
  }
  if (timer->Ready())
  {
    this->StageMilliseconds[stage] = timer->GetElapsedMilliseconds();
  }
  if (!timer->Started() || timer->Ready())
  {
    timer->Reset();
    timer->Start();
  }
}

//------------------------------------------------------------------------------
void vtkRefractionPass::StopTimer(int stage)
{
  auto& timer = this->Timers[stage];
  if (this->GPUTiming && timer && timer->Started() && !timer->Stopped())
  {
    timer->Stop();
  }
}

//------------------------------------------------------------------------------
double vtkRefractionPass::GetStageMilliseconds(int stage)
{
  if (stage < 0 || stage >= TIMED_STAGE_COUNT)
  {
    return -1.0;
  }
  auto& timer = this->Timers[stage];
  if (timer && timer->Stopped() && timer->Ready())
  {
    this->StageMilliseconds[stage] = timer->GetElapsedMilliseconds();
  }
  return this->StageMilliseconds[stage];
}

//------------------------------------------------------------------------------
unsigned long long vtkRefractionPass::GetTextureBytes() const
{
  auto bytes = [](const vtkTextureObject* t, int texelBytes) {
    return t ? static_cast<unsigned long long>(const_cast<vtkTextureObject*>(t)->GetWidth()) *
        const_cast<vtkTextureObject*>(t)->GetHeight() * texelBytes
             : 0ULL;
  };
  // RGBA32F normals, R32F depths, a 32-bit depth buffer, RG32F reduction levels.
  unsigned long long total = bytes(this->BackNormalTexture, 16) +
    bytes(this->BackDepthTexture, 4) + bytes(this->BackZBuffer, 4);
  for (const auto& level : this->ReductionLevels)
  {
    total += bytes(level, 8);
  }
  total += bytes(this->DebugTextures[0], 16) + bytes(this->DebugTextures[1], 16) +
    bytes(this->DebugZBuffer, 4);
  return total;
}

//------------------------------------------------------------------------------
void vtkRefractionPass::SplitProps(
  const vtkRenderState* s, std::vector<vtkProp*>& glass, std::vector<vtkProp*>* others)
{
  glass.clear();
  if (others)
  {
    others->clear();
  }
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    if (!IsGlass(prop))
    {
      if (others)
      {
        others->push_back(prop);
      }
      continue;
    }
    const int verdict = this->CheckGlassProp(prop);
    if (verdict == GLASS_AS_ORDINARY && others)
    {
      others->push_back(prop);
    }
    else if (verdict == GLASS_OK)
    {
      glass.push_back(prop);
    }
  }
  // Glass props the renderer culled never reach the prop array (an empty vtkPolyData has no
  // bounds and is culled first): they still deserve their message, once (CheckGlassProp).
  vtkPropCollection* viewProps = s->GetRenderer() ? s->GetRenderer()->GetViewProps() : nullptr;
  if (viewProps && viewProps->GetNumberOfItems() > s->GetPropArrayCount())
  {
    vtkProp** arrayEnd = s->GetPropArray() + s->GetPropArrayCount();
    vtkCollectionSimpleIterator it;
    viewProps->InitTraversal(it);
    while (vtkProp* prop = viewProps->GetNextProp(it))
    {
      if (prop->GetVisibility() && IsGlass(prop) &&
        std::find(s->GetPropArray(), arrayEnd, prop) == arrayEnd)
      {
        this->CheckGlassProp(prop);
      }
    }
  }
  if (this->GlassChecks.size() > 4 * glass.size() + 16)
  {
    this->GlassChecks.clear(); // entries of props that went away
  }
}

//------------------------------------------------------------------------------
int vtkRefractionPass::CheckGlassProp(vtkProp* prop)
{
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  vtkPolyDataMapper* mapper = actor ? vtkPolyDataMapper::SafeDownCast(actor->GetMapper()) : nullptr;
  vtkPolyData* poly = nullptr;
  if (mapper && mapper->GetNumberOfInputConnections(0) > 0)
  {
    // What the mapper is about to draw (as GetBounds does; free when up to date).
    mapper->Update();
    poly = mapper->GetInput();
  }
  // The verdict depends on the index and on the data only. Not on the prop's or its keys'
  // modification times: every render adds and removes the pass on the keys, and moving an
  // actor should not rescan its points.
  const double ior = GetIndexOfRefraction(prop);
  const vtkMTimeType time = poly ? poly->GetMTime() : 0;
  auto cached = this->GlassChecks.find(prop);
  if (cached != this->GlassChecks.end() && cached->second.Time == time &&
    cached->second.Data == poly &&
    (cached->second.IOR == ior || (std::isnan(cached->second.IOR) && std::isnan(ior))))
  {
    return cached->second.Verdict;
  }
  GlassCheck& check = this->GlassChecks[prop];
  check.Time = time;
  check.Data = poly;
  check.IOR = ior;
  check.Verdict = GLASS_OK;

  const rf_status status = rf_validate_ior(ior);
  if (status != RF_OK)
  {
    // The key was set by hand (MakeGlass refuses): draw the prop as an ordinary actor.
    vtkErrorMacro("Glass prop " << prop->GetClassName() << " " << prop
                                << " has index of refraction " << ior << ": "
                                << rf_status_message(status) << ". It is drawn as opaque.");
    check.Verdict = GLASS_AS_ORDINARY;
    return check.Verdict;
  }
  if (!poly)
  {
    return check.Verdict; // not a polydata actor: nothing to check here
  }
  const vtkIdType points = poly->GetNumberOfPoints();
  const vtkIdType surfaces = poly->GetNumberOfPolys() + poly->GetNumberOfStrips();
  if (points == 0 || poly->GetNumberOfCells() == 0)
  {
    vtkWarningMacro("Glass prop " << prop->GetClassName() << " " << prop
                                  << " has an empty vtkPolyData (" << points << " points, "
                                  << poly->GetNumberOfCells() << " cells): nothing to draw.");
    check.Verdict = GLASS_SKIPPED;
    return check.Verdict;
  }
  // One scan per modification: NaN or infinite coordinates would reach the capture as NaN
  // depths and normals, which the filtered normal texture spreads to the neighbours.
  vtkDataArray* coordinates = poly->GetPoints()->GetData();
  vtkIdType bad = 0;
  vtkIdType first = -1;
  double firstPoint[3] = { 0.0, 0.0, 0.0 };
  for (vtkIdType i = 0; i < points; ++i)
  {
    double p[3];
    coordinates->GetTuple(i, p);
    if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])))
    {
      if (bad++ == 0)
      {
        first = i;
        std::copy(p, p + 3, firstPoint);
      }
    }
  }
  if (bad > 0)
  {
    vtkErrorMacro("Glass prop " << prop->GetClassName() << " " << prop << " has " << bad
                                << " of " << points
                                << " points with NaN or infinite coordinates (the first: point "
                                << first << " = (" << firstPoint[0] << ", " << firstPoint[1]
                                << ", " << firstPoint[2] << ")): it is not drawn.");
    check.Verdict = GLASS_SKIPPED;
    return check.Verdict;
  }
  if (surfaces == 0)
  {
    vtkWarningMacro("Glass prop " << prop->GetClassName() << " " << prop << " has no polygons ("
                                  << poly->GetNumberOfVerts() << " vertices, "
                                  << poly->GetNumberOfLines()
                                  << " lines): glass needs surfaces; it is drawn as an ordinary "
                                     "actor.");
    check.Verdict = GLASS_AS_ORDINARY;
  }
  return check.Verdict;
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
    this->SetDelegatePass(steps);
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
  this->SplitProps(s, glass, &others);
  if (glass.empty())
  {
    this->DelegatePass->Render(s);
    this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
    return;
  }
  vtkRenderState othersState(s->GetRenderer());
  othersState.SetFrameBuffer(s->GetFrameBuffer());
  othersState.SetRequiredKeys(s->GetRequiredKeys());
  othersState.SetPropArrayAndCount(others.data(), static_cast<int>(others.size()));
  this->DelegatePass->Render(&othersState);
  this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
  this->RenderGlass(s, glass);
}

//------------------------------------------------------------------------------
int vtkRefractionPass::RenderOpaqueAndGlass(const vtkRenderState* s, vtkRenderPass* opaque)
{
  std::vector<vtkProp*> glass;
  std::vector<vtkProp*> others;
  this->SplitProps(s, glass, &others);
  this->NumberOfRenderedProps = 0;
  if (glass.empty())
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
  this->RenderGlass(s, glass);
  return this->NumberOfRenderedProps;
}

//------------------------------------------------------------------------------
void vtkRefractionPass::RenderProps(vtkOpenGLRenderer* ren, const std::vector<vtkProp*>& props)
{
  for (vtkProp* prop : props)
  {
    this->NumberOfRenderedProps += prop->RenderOpaqueGeometry(ren);
  }
}

//------------------------------------------------------------------------------
void vtkRefractionPass::AllocateTextures(vtkOpenGLRenderWindow* renWin, int width, int height)
{
  if (!this->Framebuffer)
  {
    this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->Framebuffer->SetContext(renWin);
  }
  if (this->BackNormalTexture && this->Width == width && this->Height == height)
  {
    return;
  }
  this->Width = width;
  this->Height = height;
  // Normals are filtered (the paper: filtering reduces noise; empty texels are zero vectors,
  // which only shorten a filtered normal); depths never are. 32-bit floats: on the 256 px
  // sphere benchmark DIR (5 steps) gave 37.9 dB against the two-interface reference with half
  // floats, 38.1 dB with floats.
  this->BackNormalTexture =
    MakeTexture(renWin, width, height, 4, GL_RGBA32F, GL_RGBA, vtkTextureObject::Linear);
  this->BackDepthTexture =
    MakeTexture(renWin, width, height, 1, GL_R32F, GL_RED, vtkTextureObject::Nearest);
  this->BackZBuffer = vtkSmartPointer<vtkTextureObject>::New();
  this->BackZBuffer->SetContext(renWin);
  this->BackZBuffer->AllocateDepth(width, height, vtkTextureObject::Float32);

  this->ReductionLevels.clear();
  int w = width;
  int h = height;
  do
  {
    w = (w + 1) / 2;
    h = (h + 1) / 2;
    this->ReductionLevels.push_back(
      MakeTexture(renWin, w, h, 2, GL_RG32F, GL_RG, vtkTextureObject::Nearest));
  } while (w > 1 || h > 1);

  this->DebugTextures[0] = nullptr;
  this->DebugTextures[1] = nullptr;
  this->DebugZBuffer = nullptr;
}

//------------------------------------------------------------------------------
void vtkRefractionPass::RenderGlass(const vtkRenderState* s, std::vector<vtkProp*>& glass)
{
  this->NumberOfGlassProps = static_cast<int>(glass.size());
  if (glass.empty())
  {
    return;
  }
  vtkOpenGLRenderer* ren = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  vtkOpenGLRenderWindow* renWin =
    ren ? vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow()) : nullptr;
  if (!renWin)
  {
    vtkErrorMacro("vtkRefractionPass needs an OpenGL renderer and render window.");
    return;
  }
  int width = 0;
  int height = 0;
  ren->GetTiledSizeAndOrigin(&width, &height, this->ViewportOrigin, this->ViewportOrigin + 1);
  if (width < 1 || height < 1)
  {
    // Nothing to allocate or draw; say so once, until the viewport has pixels again.
    if (!this->WarnedEmptyViewport)
    {
      vtkWarningMacro("The viewport of renderer " << ren << " is " << width << " x " << height
                                                  << " pixels: the " << glass.size()
                                                  << " glass prop(s) are not drawn.");
      this->WarnedEmptyViewport = true;
    }
    return;
  }
  this->WarnedEmptyViewport = false;
  this->AllocateTextures(renWin, width, height);
  this->UpdateShaderDefines(ren);
  this->UpdateCameraUniforms(ren);

  vtkRenderState glassState(ren);
  glassState.SetFrameBuffer(s->GetFrameBuffer());
  glassState.SetPropArrayAndCount(glass.data(), static_cast<int>(glass.size()));
  this->PreRender(&glassState);

  if (this->Method == ISR)
  {
    for (vtkProp* prop : glass)
    {
      this->MapISRAttribute(prop);
    }
  }
  if (this->WindingCache.size() > 4 * glass.size() + 16)
  {
    this->WindingCache.clear(); // entries of polydata that went away
  }
  // Stages this method does not run report no time (not the last method's).
  if (!this->NeedsBackSurface())
  {
    this->StageMilliseconds[TIMED_BACK_CAPTURE] = -1.0;
    this->Timers[TIMED_BACK_CAPTURE].reset();
  }
  if (this->Method != DIR)
  {
    this->StageMilliseconds[TIMED_DEPTH_RANGE] = -1.0;
    this->Timers[TIMED_DEPTH_RANGE].reset();
  }
  if (this->NeedsBackSurface())
  {
    this->StartTimer(TIMED_BACK_CAPTURE);
    this->CaptureBackSurface(ren, glass);
    this->StopTimer(TIMED_BACK_CAPTURE);
  }
  if (this->Method == SSP)
  {
    this->CaptureSceneForSSP(ren, glass);
  }
  if (this->Method == DIR)
  {
    this->StartTimer(TIMED_DEPTH_RANGE);
    if (this->DepthRangeMode == DEPTH_RANGE_REDUCTION)
    {
      this->ReduceDepthRange(renWin);
    }
    else
    {
      this->ComputeBoundsDepthRange(ren, glass);
    }
    this->StopTimer(TIMED_DEPTH_RANGE);
  }

  vtkTexture* environment = ren->GetEnvironmentTexture();
  this->CurrentEnvironment = environment;
  if (this->UseEnvironmentCube)
  {
    environment->Render(ren);
  }
  this->BackNormalTexture->Activate();
  this->BackDepthTexture->Activate();
  this->ReductionLevels.back()->Activate();
  if (this->Method == SSP)
  {
    this->SceneColorTexture->Activate();
  }

  this->SetStage(STAGE_FRONT);
  this->StartTimer(TIMED_FRONT);
  this->RenderProps(ren, glass);
  this->StopTimer(TIMED_FRONT);
  if (this->DebugOutput)
  {
    this->RenderDebugImage(ren, glass);
  }
  this->SetStage(STAGE_NONE);

  if (this->Method == SSP)
  {
    this->SceneColorTexture->Deactivate();
  }
  this->ReductionLevels.back()->Deactivate();
  this->BackDepthTexture->Deactivate();
  this->BackNormalTexture->Deactivate();
  if (this->UseEnvironmentCube)
  {
    environment->PostRender(ren);
  }
  this->CurrentEnvironment = nullptr;
  this->PostRender(&glassState);
  vtkOpenGLCheckErrorMacro("failed after the refraction pass");
}

//------------------------------------------------------------------------------
void vtkRefractionPass::CaptureBackSurface(
  vtkOpenGLRenderer* ren, const std::vector<vtkProp*>& glass)
{
  const bool nearest = this->BackSurface == BACK_SURFACE_NEAREST;
  this->RenderIntoTargets(ren, glass, this->BackNormalTexture, this->BackDepthTexture,
    this->BackZBuffer, nearest ? 1.0 : 0.0, nearest ? GL_LESS : GL_GREATER, STAGE_BACK, nullptr);
}

//------------------------------------------------------------------------------
void vtkRefractionPass::RenderIntoTargets(vtkOpenGLRenderer* ren,
  const std::vector<vtkProp*>& glass, vtkTextureObject* colour0, vtkTextureObject* colour1,
  vtkTextureObject* depth, double clearDepth, unsigned int depthFunc, int stage,
  const std::function<void()>& whileBound)
{
  vtkOpenGLRenderWindow* renWin = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  vtkOpenGLState* ostate = renWin->GetState();
  this->Framebuffer->SaveCurrentBindingsAndBuffers();
  this->Framebuffer->Bind();
  this->Framebuffer->AddColorAttachment(0, colour0);
  this->Framebuffer->AddColorAttachment(1, colour1);
  this->Framebuffer->AddDepthAttachment(depth);
  this->Framebuffer->ActivateDrawBuffers(2);
  this->ActiveDrawBuffers = 2;
  {
    vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
    vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
    vtkOpenGLState::ScopedglClearColor clearColorSaver(ostate);
    vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(ostate);
    vtkOpenGLState::ScopedglDepthMask depthMaskSaver(ostate);
    vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable depthSaver(ostate, GL_DEPTH_TEST);
    ostate->vtkglViewport(0, 0, this->Width, this->Height);
    ostate->vtkglScissor(0, 0, this->Width, this->Height);
    ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
    ostate->vtkglDepthMask(GL_TRUE);
    ostate->vtkglClearDepth(clearDepth);
    ostate->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    ostate->vtkglClearDepth(1.0);
    ostate->vtkglEnable(GL_DEPTH_TEST);
    ostate->vtkglDepthFunc(depthFunc);
    ostate->vtkglDisable(GL_BLEND);
    const int previous = this->Stage;
    this->SetStage(stage);
    this->RenderProps(ren, glass);
    this->SetStage(previous);
    if (whileBound)
    {
      whileBound();
    }
  }
  this->ActiveDrawBuffers = 0;
  this->Framebuffer->RemoveColorAttachment(1);
  this->Framebuffer->UnBind();
  this->Framebuffer->RestorePreviousBindingsAndBuffers();
}

//------------------------------------------------------------------------------
void vtkRefractionPass::ReduceDepthRange(vtkOpenGLRenderWindow* renWin)
{
  vtkOpenGLState* ostate = renWin->GetState();
  if (!this->ReductionQuad)
  {
    this->ReductionQuad.reset(new vtkOpenGLQuadHelper(renWin,
      vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), rfReductionFSSource, ""));
  }
  else
  {
    renWin->GetShaderCache()->ReadyShaderProgram(this->ReductionQuad->Program);
  }
  vtkShaderProgram* program = this->ReductionQuad->Program;
  if (!program || !program->GetCompiled())
  {
    vtkErrorMacro("Could not build the depth-range reduction shader.");
    return;
  }
  this->Framebuffer->SaveCurrentBindingsAndBuffers();
  this->Framebuffer->Bind();
  {
    vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
    vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
    vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable depthSaver(ostate, GL_DEPTH_TEST);
    ostate->vtkglDisable(GL_BLEND);
    ostate->vtkglDisable(GL_DEPTH_TEST);
    vtkTextureObject* source = this->BackDepthTexture;
    for (size_t level = 0; level < this->ReductionLevels.size(); ++level)
    {
      vtkTextureObject* target = this->ReductionLevels[level];
      this->Framebuffer->AddColorAttachment(0, target);
      this->Framebuffer->ActivateDrawBuffers(1);
      const int w = static_cast<int>(target->GetWidth());
      const int h = static_cast<int>(target->GetHeight());
      ostate->vtkglViewport(0, 0, w, h);
      ostate->vtkglScissor(0, 0, w, h);
      source->Activate();
      program->SetUniformi("rfSource", source->GetTextureUnit());
      const int size[2] = { static_cast<int>(source->GetWidth()),
        static_cast<int>(source->GetHeight()) };
      program->SetUniform2i("rfSourceSize", size);
      program->SetUniformi("rfFirstLevel", level == 0 ? 1 : 0);
      const int targetSize[2] = { w, h };
      program->SetUniform2i("rfTargetSize", targetSize);
      this->ReductionQuad->Render();
      source->Deactivate();
      source = target;
    }
  }
  this->Framebuffer->UnBind();
  this->Framebuffer->RestorePreviousBindingsAndBuffers();
}

//------------------------------------------------------------------------------
void vtkRefractionPass::ComputeBoundsDepthRange(
  vtkOpenGLRenderer* ren, const std::vector<vtkProp*>& glass)
{
  vtkCamera* camera = ren->GetActiveCamera();
  vtkMatrix4x4* view = camera->GetViewTransformMatrix();
  double nearest = VTK_DOUBLE_MAX;
  double furthest = 0.0;
  for (vtkProp* prop : glass)
  {
    const double* b = prop->GetBounds();
    if (!b || !(b[0] <= b[1]))
    {
      continue;
    }
    for (int corner = 0; corner < 8; ++corner)
    {
      const double p[4] = { b[corner & 1], b[2 + ((corner >> 1) & 1)], b[4 + ((corner >> 2) & 1)],
        1.0 };
      double q[4];
      view->MultiplyPoint(p, q);
      nearest = std::min(nearest, -q[2]);
      furthest = std::max(furthest, -q[2]);
    }
  }
  double clipping[2];
  camera->GetClippingRange(clipping);
  // Parts of a box behind the near plane are never captured: the search starts there.
  this->BoundsDepthRange[0] = std::max(nearest, clipping[0]);
  this->BoundsDepthRange[1] = furthest;
}

//------------------------------------------------------------------------------
int vtkRefractionPass::GetWindingSign(vtkProp* prop)
{
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  vtkMapper* mapper = actor ? actor->GetMapper() : nullptr;
  vtkPolyData* poly = mapper ? vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0)) : nullptr;
  if (!poly)
  {
    return 1;
  }
  auto cached = this->WindingCache.find(poly);
  if (cached != this->WindingCache.end() && cached->second.first == poly->GetMTime())
  {
    return cached->second.second;
  }
  // The signed volume of a closed mesh is positive when its polygons wind counter-clockwise
  // seen from outside (the OpenGL front face). Measured about the bounds' centre so that far
  // offset coordinates keep their precision.
  double bounds[6];
  poly->GetBounds(bounds);
  const double centre[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  double volume = 0.0;
  vtkCellArray* polys = poly->GetPolys();
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  double a[3];
  double b[3];
  double c[3];
  for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
  {
    if (count < 3)
    {
      continue;
    }
    poly->GetPoint(ids[0], a);
    for (int k = 0; k < 3; ++k)
    {
      a[k] -= centre[k];
    }
    for (vtkIdType j = 1; j + 1 < count; ++j)
    {
      poly->GetPoint(ids[j], b);
      poly->GetPoint(ids[j + 1], c);
      for (int k = 0; k < 3; ++k)
      {
        b[k] -= centre[k];
        c[k] -= centre[k];
      }
      volume += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
        a[2] * (b[0] * c[1] - b[1] * c[0]);
    }
  }
  const int sign = volume < 0.0 ? -1 : 1;
  this->WindingCache[poly] = std::make_pair(poly->GetMTime(), sign);
  return sign;
}

//------------------------------------------------------------------------------
void vtkRefractionPass::MapISRAttribute(vtkProp* prop)
{
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  vtkOpenGLPolyDataMapper* mapper =
    actor ? vtkOpenGLPolyDataMapper::SafeDownCast(actor->GetMapper()) : nullptr;
  if (!mapper)
  {
    return;
  }
  for (const auto& mapped : this->ISRMappers)
  {
    if (mapped == mapper)
    {
      return;
    }
  }
  vtkPolyData* poly = vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0));
  if (!poly || !poly->GetPointData()->GetArray(GetISRDistanceArrayName()))
  {
    vtkWarningMacro("ISR: glass actor " << actor << " has no point array \""
                                        << GetISRDistanceArrayName()
                                        << "\" (vtkISRDistanceFilter adds it); using d_N = d_V.");
  }
  mapper->MapDataArrayToVertexAttribute("rfNormalDistance", GetISRDistanceArrayName(),
    vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  this->ISRMappers.erase(std::remove_if(this->ISRMappers.begin(), this->ISRMappers.end(),
                           [](const vtkWeakPointer<vtkMapper>& m) { return m == nullptr; }),
    this->ISRMappers.end());
  this->ISRMappers.emplace_back(mapper);
}

//------------------------------------------------------------------------------
void vtkRefractionPass::CaptureSceneForSSP(
  vtkOpenGLRenderer* ren, const std::vector<vtkProp*>& glass)
{
  vtkOpenGLRenderWindow* renWin = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  vtkOpenGLState* ostate = renWin->GetState();
  // The chapter's refraction mask, in the alpha channel of the opaque scene: where the glass
  // is the visible surface, alpha becomes 0.25 + 0.5 alpha (0.75 over an object, 0.25 over
  // the background); elsewhere it stays 1 (objects, including those in front) or 0.
  {
    vtkOpenGLState::ScopedglColorMask colorMaskSaver(ostate);
    vtkOpenGLState::ScopedglDepthMask depthMaskSaver(ostate);
    vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(ostate);
    vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(ostate);
    vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable depthSaver(ostate, GL_DEPTH_TEST);
    ostate->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
    ostate->vtkglDepthMask(GL_FALSE);
    ostate->vtkglEnable(GL_DEPTH_TEST);
    ostate->vtkglDepthFunc(GL_LEQUAL);
    ostate->vtkglEnable(GL_BLEND);
    ostate->vtkglBlendFuncSeparate(GL_ZERO, GL_ONE, GL_ONE, GL_CONSTANT_ALPHA);
    glBlendColor(0.f, 0.f, 0.f, 0.5f);
    this->SetStage(STAGE_MASK);
    this->RenderProps(ren, glass);
    this->SetStage(STAGE_NONE);
  }
  if (!this->SceneColorTexture || this->SceneColorTexture->GetWidth() != static_cast<unsigned>(this->Width) ||
    this->SceneColorTexture->GetHeight() != static_cast<unsigned>(this->Height))
  {
    this->SceneColorTexture = vtkSmartPointer<vtkTextureObject>::New();
    this->SceneColorTexture->SetContext(renWin);
    this->SceneColorTexture->SetInternalFormat(GL_RGBA8);
    this->SceneColorTexture->SetFormat(GL_RGBA);
    this->SceneColorTexture->SetDataType(GL_UNSIGNED_BYTE);
    this->SceneColorTexture->SetMinificationFilter(vtkTextureObject::Nearest);
    this->SceneColorTexture->SetMagnificationFilter(vtkTextureObject::Nearest);
    this->SceneColorTexture->SetWrapS(vtkTextureObject::ClampToEdge);
    this->SceneColorTexture->SetWrapT(vtkTextureObject::ClampToEdge);
    this->SceneColorTexture->Allocate2D(this->Width, this->Height, 4, VTK_UNSIGNED_CHAR);
  }
  // Copy the viewport of the scene (colour and mask) into the texture the glass samples.
  this->Framebuffer->SaveCurrentBindingsAndBuffers();
  this->Framebuffer->Bind(GL_DRAW_FRAMEBUFFER);
  this->Framebuffer->AddColorAttachment(0, this->SceneColorTexture);
  this->Framebuffer->ActivateDrawBuffers(1);
  {
    vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
    ostate->vtkglScissor(0, 0, this->Width, this->Height);
    ostate->vtkglBlitFramebuffer(this->ViewportOrigin[0], this->ViewportOrigin[1],
      this->ViewportOrigin[0] + this->Width, this->ViewportOrigin[1] + this->Height, 0, 0,
      this->Width, this->Height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  this->Framebuffer->UnBind(GL_DRAW_FRAMEBUFFER);
  this->Framebuffer->RestorePreviousBindingsAndBuffers();
}

//------------------------------------------------------------------------------
void vtkRefractionPass::RenderDebugImage(
  vtkOpenGLRenderer* ren, const std::vector<vtkProp*>& glass)
{
  vtkOpenGLRenderWindow* renWin = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  if (!this->DebugTextures[0])
  {
    for (auto& texture : this->DebugTextures)
    {
      texture = MakeTexture(
        renWin, this->Width, this->Height, 4, GL_RGBA32F, GL_RGBA, vtkTextureObject::Nearest);
    }
    this->DebugZBuffer = vtkSmartPointer<vtkTextureObject>::New();
    this->DebugZBuffer->SetContext(renWin);
    this->DebugZBuffer->AllocateDepth(this->Width, this->Height, vtkTextureObject::Float32);
  }
  const vtkIdType count = static_cast<vtkIdType>(this->Width) * this->Height;
  std::vector<float> pixels[2];
  this->RenderIntoTargets(ren, glass, this->DebugTextures[0], this->DebugTextures[1],
    this->DebugZBuffer, 1.0, GL_LEQUAL, STAGE_DEBUG, [&]() {
      for (int i = 0; i < 2; ++i)
      {
        pixels[i].resize(4 * count);
        this->Framebuffer->ActivateReadBuffer(i);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, this->Width, this->Height, GL_RGBA, GL_FLOAT, pixels[i].data());
      }
    });

  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(this->Width, this->Height, 1);
  vtkNew<vtkFloatArray> p2;
  vtkNew<vtkFloatArray> t2;
  vtkNew<vtkFloatArray> thickness;
  vtkNew<vtkFloatArray> flags;
  p2->SetName("P2");
  t2->SetName("T2");
  thickness->SetName("Thickness");
  flags->SetName("Flags");
  p2->SetNumberOfComponents(3);
  t2->SetNumberOfComponents(3);
  p2->SetNumberOfTuples(count);
  t2->SetNumberOfTuples(count);
  thickness->SetNumberOfTuples(count);
  flags->SetNumberOfTuples(count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    const float* a = &pixels[0][4 * i];
    const float* b = &pixels[1][4 * i];
    p2->SetTypedTuple(i, a);
    thickness->SetValue(i, a[3]);
    t2->SetTypedTuple(i, b);
    flags->SetValue(i, b[3]);
  }
  image->GetPointData()->AddArray(p2);
  image->GetPointData()->AddArray(t2);
  image->GetPointData()->AddArray(thickness);
  image->GetPointData()->AddArray(flags);
  this->DebugImage = image;
}

//------------------------------------------------------------------------------
void vtkRefractionPass::UpdateShaderDefines(vtkOpenGLRenderer* ren)
{
  vtkTexture* environment = ren->GetEnvironmentTexture();
  const bool cube = environment && environment->GetCubeMap() &&
    vtkOpenGLTexture::SafeDownCast(environment) != nullptr;
  if (environment && !cube && !this->UseEnvironmentCube)
  {
    vtkWarningMacro("The renderer's environment texture is not an OpenGL cube map (wrap a "
                    "lat-long image in vtkEquirectangularToCubeMapTexture); using the built-in "
                    "environment.");
  }
  this->UseEnvironmentCube = cube;
  std::ostringstream defines;
  defines << "#define RF_MAX_SEARCH_STEPS " << RF_CBS_MAX_STEPS << "\n";
  static const char* const methodDefines[] = { "RF_METHOD_SIR", "RF_METHOD_DIR",
    "RF_METHOD_ISR", "RF_METHOD_SSP" };
  defines << "#define " << methodDefines[this->Method] << "\n";
  if (this->AdaptiveSearch)
  {
    defines << "#define RF_ADAPTIVE_SEARCH\n";
  }
  if (this->BackSurface == BACK_SURFACE_NEAREST)
  {
    defines << "#define RF_BACK_NEAREST\n";
  }
  if (this->SecantRefinement)
  {
    defines << "#define RF_SECANT_REFINE\n";
  }
  if (this->TIRPolicy == TIR_CLAMP)
  {
    defines << "#define RF_TIR_CLAMP\n";
  }
  if (this->Fresnel)
  {
    defines << "#define RF_FRESNEL\n";
  }
  if (cube)
  {
    defines << "#define RF_ENV_CUBEMAP\n";
  }
  if (this->DepthRangeMode == DEPTH_RANGE_BOUNDS)
  {
    defines << "#define RF_DEPTH_RANGE_BOUNDS\n";
  }
  if (defines.str() != this->ShaderDefines)
  {
    this->ShaderDefines = defines.str();
    this->ShaderDefinesTime.Modified();
  }
}

//------------------------------------------------------------------------------
vtkMTimeType vtkRefractionPass::GetShaderStageMTime()
{
  return std::max(this->ShaderDefinesTime.GetMTime(), this->StageProgramTime.GetMTime());
}

//------------------------------------------------------------------------------
void vtkRefractionPass::SetStage(int stage)
{
  // The back capture and the shading get programs of their own: one program holding both
  // (switched by a uniform) ran every stage at the speed of the largest (measured on
  // llvmpipe: the capture alone took longer than a whole plain frame). Switching costs the
  // mapper a rebuild of the shader source, which the shader cache then finds compiled.
  this->Stage = stage;
  const bool back = stage == STAGE_BACK;
  if (stage != STAGE_NONE && back != this->ProgramIsBack)
  {
    this->ProgramIsBack = back;
    this->StageProgramTime.Modified();
  }
}

//------------------------------------------------------------------------------
bool vtkRefractionPass::PreReplaceShaderValues(std::string&, std::string&,
  std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop)
{
  if (!vtkOpenGLPolyDataMapper::SafeDownCast(mapper) || !IsGlass(prop))
  {
    return true;
  }
  // Every stage overwrites the colour: VTK's lighting would be computed per fragment and
  // thrown away, so it is left out of the glass's shader (the normal and position stay).
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::Light::Impl",
    "gl_FragData[0] = vec4(1.0);\n", false);
  return true;
}

//------------------------------------------------------------------------------
bool vtkRefractionPass::PostReplaceShaderValues(std::string& vertexShader, std::string&,
  std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop)
{
  if (!vtkOpenGLPolyDataMapper::SafeDownCast(mapper) || !IsGlass(prop))
  {
    return true;
  }
  const std::string source = rfRefractionFSSource;
  const size_t marker = source.find(kImplMarker);
  std::string declarations = source.substr(0, marker);
  const std::string refractionBody = source.substr(marker + std::string(kImplMarker).size());
  vtkShaderProgram::Substitute(declarations, kEnvironmentMarker, rfEnvironmentSource);

  // The mapper declares vertexVC only with lighting, and normalVCVSOutput only with normals
  // or lighting; otherwise rebuild them from the fragment's coordinates.
  const bool haveVertexVC = fragmentShader.find("vec4 vertexVC") != std::string::npos;
  const bool haveNormal = fragmentShader.find("normalVCVSOutput") != std::string::npos;
  std::ostringstream prelude;
  prelude << this->ShaderDefines;
  if (this->Method == ISR)
  {
    prelude << "in float rfNormalDistanceVSOut;\n";
  }
  std::ostringstream body;
  body << "  {\n"
       << "    vec3 rfP = " << (haveVertexVC ? "vertexVC.xyz" : "rfReconstructPositionVC()")
       << ";\n"
       // rfSafeNormal: zero or non-finite normals fall back to the face normal (no NaN).
       << "    vec3 rfN = rfSafeNormal("
       << (haveNormal ? "normalVCVSOutput" : "vec3(0.0)") << ", rfP);\n"
       << (this->ProgramIsBack ? rfBackCaptureFSSource : refractionBody.c_str()) << "  }\n";

  // Glass is opaque: VTK's alpha test would only keep the rasterizer from testing depth
  // before shading (early depth), which saves the refraction of hidden fragments.
  vtkShaderProgram::Substitute(
    fragmentShader, "if (gl_FragData[0].a <= 0.0)", "if (false)", false);
  const size_t mainPos = fragmentShader.find("void main()");
  const size_t endPos = fragmentShader.rfind('}');
  if (mainPos == std::string::npos || endPos == std::string::npos || endPos < mainPos)
  {
    vtkErrorMacro("Unexpected fragment shader layout; the glass is drawn unrefracted.");
    return false;
  }
  fragmentShader.insert(endPos, body.str());
  fragmentShader.insert(mainPos, prelude.str() + declarations);

  if (this->Method == ISR)
  {
    // d_N travels as a generic vertex attribute (MapISRAttribute) to a varying.
    const size_t vsMain = vertexShader.find("void main()");
    const size_t vsOpen = vsMain == std::string::npos ? vsMain : vertexShader.find('{', vsMain);
    if (vsOpen == std::string::npos)
    {
      vtkErrorMacro("Unexpected vertex shader layout; ISR falls back to d_N = d_V.");
      return false;
    }
    vertexShader.insert(vsOpen + 1, "\n  rfNormalDistanceVSOut = rfNormalDistance;\n");
    vertexShader.insert(vsMain, "in float rfNormalDistance;\nout float rfNormalDistanceVSOut;\n");
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkRefractionPass::UpdateCameraUniforms(vtkOpenGLRenderer* ren)
{
  vtkOpenGLCamera* camera = vtkOpenGLCamera::SafeDownCast(ren->GetActiveCamera());
  vtkMatrix4x4* wcvc = nullptr;
  vtkMatrix3x3* normalMatrix = nullptr;
  vtkMatrix4x4* vcdc = nullptr;
  vtkMatrix4x4* wcdc = nullptr;
  camera->GetKeyMatrices(ren, wcvc, normalMatrix, vcdc, wcdc);
  // VTK's key matrices are already laid out for glUniformMatrix: pass them as VTK does.
  this->ProjectionGL->DeepCopy(vcdc);
  vtkMatrix4x4::Invert(vcdc, this->InverseProjectionGL);
  // Row-major R (world to view) read as column-major by GLSL is R^T, view to world.
  vtkMatrix4x4* view = camera->GetViewTransformMatrix();
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      this->ViewToWorld[r * 3 + c] = static_cast<float>(view->GetElement(r, c));
    }
  }
  // The environment's frame, laid out as vtkOpenGLRenderer lays out envMatrix.
  double up[3];
  double right[3];
  double front[3];
  ren->GetEnvironmentUp(up);
  ren->GetEnvironmentRight(right);
  vtkMath::Cross(right, up, front);
  for (int i = 0; i < 3; ++i)
  {
    this->EnvironmentMatrix[i * 3 + 0] = static_cast<float>(right[i]);
    this->EnvironmentMatrix[i * 3 + 1] = static_cast<float>(up[i]);
    this->EnvironmentMatrix[i * 3 + 2] = static_cast<float>(front[i]);
  }
  this->Parallel = camera->GetParallelProjection() ? 1 : 0;
}

//------------------------------------------------------------------------------
bool vtkRefractionPass::SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper,
  vtkProp* prop, vtkOpenGLVertexArrayObject*)
{
  if (!vtkOpenGLPolyDataMapper::SafeDownCast(mapper) || !IsGlass(prop) ||
    this->Stage == STAGE_NONE)
  {
    return true;
  }
  auto setSampler = [program](const char* name, vtkTextureObject* texture) {
    if (texture && program->IsUniformUsed(name))
    {
      program->SetUniformi(name, texture->GetTextureUnit());
    }
  };
  auto setMatrix3 = [program](const char* name, float* values) {
    if (program->IsUniformUsed(name))
    {
      program->SetUniformMatrix3x3(name, values);
    }
  };
  auto setMatrix4 = [program](const char* name, vtkMatrix4x4* values) {
    if (program->IsUniformUsed(name))
    {
      program->SetUniformMatrix(name, values);
    }
  };
  if (program->IsUniformUsed("rfStage"))
  {
    program->SetUniformi("rfStage", this->Stage);
  }
  if (program->IsUniformUsed("rfIOR"))
  {
    program->SetUniformf("rfIOR", static_cast<float>(GetIndexOfRefraction(prop)));
  }
  if (program->IsUniformUsed("rfSearchSteps"))
  {
    program->SetUniformi("rfSearchSteps", this->SearchSteps);
  }
  if (program->IsUniformUsed("rfParallel"))
  {
    program->SetUniformi("rfParallel", this->Parallel);
  }
  setMatrix4("rfVCDC", this->ProjectionGL);
  setMatrix4("rfDCVC", this->InverseProjectionGL);
  setMatrix3("rfViewToWorld", this->ViewToWorld);
  setMatrix3("rfEnvMatrix", this->EnvironmentMatrix);
  if (program->IsUniformUsed("rfViewport"))
  {
    // gl_FragCoord counts from the window's corner on screen, from the texture's in our FBOs.
    const bool onScreen = this->Stage == STAGE_FRONT;
    const float viewport[4] = { onScreen ? static_cast<float>(this->ViewportOrigin[0]) : 0.f,
      onScreen ? static_cast<float>(this->ViewportOrigin[1]) : 0.f,
      static_cast<float>(this->Width), static_cast<float>(this->Height) };
    program->SetUniform4f("rfViewport", viewport);
  }
  bool environmentBound = false;
  if (this->Stage != STAGE_BACK)
  {
    setSampler("rfBackNormal", this->BackNormalTexture);
    setSampler("rfBackDepth", this->BackDepthTexture);
    setSampler("rfDepthRangeTex",
      this->ReductionLevels.empty() ? nullptr : this->ReductionLevels.back().Get());
    if (this->UseEnvironmentCube && this->CurrentEnvironment &&
      program->IsUniformUsed("rfEnvironmentCube"))
    {
      program->SetUniformi("rfEnvironmentCube",
        static_cast<vtkOpenGLTexture*>(this->CurrentEnvironment)->GetTextureUnit());
      environmentBound = true;
    }
  }
  // The cube map is bound for the shading stages only (the back capture and SSP's mask stage
  // run before it is, and sample nothing), but a draw fails (GL_INVALID_OPERATION) while
  // sampler uniforms of different types share a unit, and on a new program they all say
  // unit 0. Point the cube map at the highest unit, which VTK's unit manager (lowest first)
  // leaves free; the 2D samplers keep 0 or the distinct units of the last front stage.
  if (!environmentBound && program->IsUniformUsed("rfEnvironmentCube"))
  {
    GLint units = 0;
    glGetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &units);
    program->SetUniformi("rfEnvironmentCube", std::max(units - 1, 1));
  }
  if (program->IsUniformUsed("rfWindingSign"))
  {
    program->SetUniformi("rfWindingSign", this->GetWindingSign(prop));
  }
  if (program->IsUniformUsed("rfHaveNormalDistance"))
  {
    vtkActor* actor = vtkActor::SafeDownCast(prop);
    vtkPolyData* poly = vtkPolyData::SafeDownCast(
      vtkOpenGLPolyDataMapper::SafeDownCast(mapper)->GetInputDataObject(0, 0));
    const bool have = poly && poly->GetPointData()->GetArray(GetISRDistanceArrayName());
    program->SetUniformi("rfHaveNormalDistance", have ? 1 : 0);
    // d_N is measured in model coordinates: scale it with the actor.
    double scale = 1.0;
    if (actor)
    {
      vtkMatrix4x4* m = actor->GetMatrix();
      double columns[3] = { 0.0, 0.0, 0.0 };
      for (int c = 0; c < 3; ++c)
      {
        columns[c] = std::sqrt(m->GetElement(0, c) * m->GetElement(0, c) +
          m->GetElement(1, c) * m->GetElement(1, c) + m->GetElement(2, c) * m->GetElement(2, c));
      }
      scale = std::cbrt(columns[0] * columns[1] * columns[2]);
    }
    program->SetUniformf("rfModelScale", static_cast<float>(scale));
  }
  if (program->IsUniformUsed("rfSceneColor") && this->SceneColorTexture)
  {
    // SSP's mask stage draws before the scene colour is bound: unit -1 is GL_INVALID_VALUE.
    if (this->SceneColorTexture->GetTextureUnit() >= 0)
    {
      program->SetUniformi("rfSceneColor", this->SceneColorTexture->GetTextureUnit());
    }
    program->SetUniformf("rfSSPStrength", static_cast<float>(this->SSPStrength));
    program->SetUniformf("rfSSPFresnelBias", static_cast<float>(this->SSPFresnelBias));
    program->SetUniformf("rfSSPFresnelPower", static_cast<float>(this->SSPFresnelPower));
    program->SetUniformf("rfChromaticAberration", static_cast<float>(this->ChromaticAberration));
    program->SetUniformi("rfSSPMask", this->SSPRefractionMask ? 1 : 0);
  }
  if (program->IsUniformUsed("rfDepthRangeBounds"))
  {
    const float range[2] = { static_cast<float>(this->BoundsDepthRange[0]),
      static_cast<float>(this->BoundsDepthRange[1]) };
    program->SetUniform2f("rfDepthRangeBounds", range);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkRefractionPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  if (this->DelegatePass)
  {
    this->DelegatePass->ReleaseGraphicsResources(w);
  }
  if (this->ReductionQuad)
  {
    this->ReductionQuad->ReleaseGraphicsResources(w);
    this->ReductionQuad.reset();
  }
  for (auto* texture : { this->BackNormalTexture.Get(), this->BackDepthTexture.Get(),
         this->BackZBuffer.Get(), this->DebugTextures[0].Get(), this->DebugTextures[1].Get(),
         this->DebugZBuffer.Get() })
  {
    if (texture)
    {
      texture->ReleaseGraphicsResources(w);
    }
  }
  for (auto& level : this->ReductionLevels)
  {
    level->ReleaseGraphicsResources(w);
  }
  this->ReductionLevels.clear();
  this->BackNormalTexture = nullptr;
  this->BackDepthTexture = nullptr;
  this->BackZBuffer = nullptr;
  this->DebugTextures[0] = nullptr;
  this->DebugTextures[1] = nullptr;
  this->DebugZBuffer = nullptr;
  if (this->SceneColorTexture)
  {
    this->SceneColorTexture->ReleaseGraphicsResources(w);
    this->SceneColorTexture = nullptr;
  }
  if (this->Framebuffer)
  {
    this->Framebuffer->ReleaseGraphicsResources(w);
    this->Framebuffer = nullptr;
  }
  for (auto& timer : this->Timers)
  {
    if (timer)
    {
      timer->ReleaseGraphicsResources();
      timer.reset();
    }
  }
  this->Width = 0;
  this->Height = 0;
}
