#include "vtkRefractionGeometryStage.h"

#include "vtkActor.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLState.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRefractionGlassKeys.h"
#include "vtkRefractionMeshes.h"
#include "vtkRefractionModelMatrix.h"
#include "vtkRefractionTargetDraw.h"
#include "vtkRefractionTargets.h"
#include "vtkRenderState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "rfShaders.h"
#include "rf_peel.h"
#include "vtk_glew.h"

#include <algorithm>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkRefractionGeometryStage);

namespace
{
const char* const kImplMarker = "//RF::Impl";
const char* const kDecTag = "//RF::Geometry::Dec";
const char* const kImplTag = "//RF::Geometry::Impl";

bool IsGlassMapper(vtkAbstractMapper* mapper, vtkProp* prop)
{
  return vtkOpenGLPolyDataMapper::SafeDownCast(mapper) && vtkRefractionGlassKeys::IsGlass(prop);
}

// Peeled by facing (GetPeelByFacing), whether layer `layer` holds surfaces the ray leaves the
// glass through: odd layers behind the front, and the furthest; even ones it enters through.
bool PeelLayerIsLeft(int layer, bool furthest)
{
  return furthest || layer % 2 == 1;
}
}

//------------------------------------------------------------------------------
vtkRefractionGeometryStage::vtkRefractionGeometryStage() = default;
vtkRefractionGeometryStage::~vtkRefractionGeometryStage() = default;

//------------------------------------------------------------------------------
void vtkRefractionGeometryStage::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Glass props: " << this->Glass.size() << "\n";
  os << indent << "NormalDistance: " << this->NormalDistance << "\n";
  os << indent << "BackNearest: " << this->BackNearest << "\n";
}

//------------------------------------------------------------------------------
void vtkRefractionGeometryStage::Render(const vtkRenderState*)
{
  // Drawn through DrawFront, DrawBack, DrawPeel, DrawMask and DrawOnScreen only.
}

//------------------------------------------------------------------------------
void vtkRefractionGeometryStage::Configure(const std::vector<vtkProp*>& glass,
  bool normalDistance, bool dataColour, bool backNearest, bool peel, bool shTransfer,
  vtkMatrix4x4* inverseProjection, bool parallel)
{
  this->Glass = glass;
  this->MaterialIndex.clear();
  this->SheetMaterialIndex.clear();
  std::vector<vtkPolyData*> perPiece;
  for (size_t i = 0; i < glass.size(); ++i)
  {
    this->MaterialIndex[glass[i]] = static_cast<int>(i);
    vtkPolyData* mesh = i < this->SheetPieceMaterial.size() && this->SheetPieceMaterial[i] >= 0
      ? this->SurfaceModel->GetProp(glass[i]).PerPiece
      : nullptr;
    if (mesh)
    {
      this->SheetMaterialIndex[glass[i]] = this->SheetPieceMaterial[i];
      perPiece.push_back(mesh);
    }
  }
  this->UsePieceSheets = !perPiece.empty();
  this->PieceSheets->Retain(perPiece);
  this->NormalDistance = normalDistance;
  this->DataColour = dataColour;
  this->BackNearest = backNearest;
  this->InverseProjection->DeepCopy(inverseProjection);
  this->Parallel = parallel;
  std::ostringstream defines;
  // The front stage's outputs, in the order DrawFront attaches the targets.
  if (dataColour)
  {
    defines << "#define RF_GBUFFER_COLOUR 1\n";
  }
  if (normalDistance)
  {
    defines << "#define RF_GBUFFER_NORMAL_DISTANCE " << (dataColour ? 2 : 1) << "\n";
  }
  if (backNearest)
  {
    defines << "#define RF_BACK_NEAREST\n";
  }
  if (this->UsePieceSheets)
  {
    defines << "#define RF_PIECE_SHEETS\n";
  }
  if (glass.size() > 1 || this->UsePieceSheets)
  {
    // The composite at the samples tells the glass materials apart at their silhouettes.
    defines << "#define RF_COMPOSITE_MATERIALS\n";
  }
  this->Peel = peel;
  if (peel)
  {
    defines << "#define RF_PEEL_CAPTURE\n";
    if (this->SignedFront)
    {
      defines << "#define RF_SIGNED_FRONT\n";
    }
  }
  this->PeelKBufferConfigured = peel && this->PeelKBuffer > 2 ? this->PeelKBuffer : 0;
  if (this->PeelKBufferConfigured)
  {
    defines << "#define RF_PEEL_KBUFFER\n#define RF_PEEL_KBUFFER_LAYERS " << this->PeelKBufferConfigured
            << "\n";
  }
  this->UseSHTransfer = shTransfer;
  this->SHTransfer->Retain(shTransfer ? glass : std::vector<vtkProp*>());
  if (shTransfer)
  {
    defines << "#define RF_GBUFFER_SH " << (dataColour ? 2 : 1) << "\n";
    for (vtkProp* prop : glass)
    {
      this->SHTransfer->MapVertexIds(prop);
    }
  }
  if (defines.str() != this->Defines)
  {
    this->Defines = defines.str();
    this->DefinesTime.Modified();
  }
  this->SurfaceModel->Prune(4 * glass.size() + 16); // entries of polydata that went away
  if (normalDistance)
  {
    for (vtkProp* prop : glass)
    {
      this->MapNormalDistance(prop);
    }
  }
}

//------------------------------------------------------------------------------
void vtkRefractionGeometryStage::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  // As VTK's own GL objects (vtkOpenGLRenderTimer): the window made its context current.
  if (this->PeelQuery != 0 && w)
  {
    glDeleteQueries(1, &this->PeelQuery);
  }
  this->PeelQuery = 0;
  this->PeelCount->ReleaseGraphicsResources(w);
  this->SHTransfer->ReleaseGraphicsResources(w);
  this->PieceSheets->ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
vtkMTimeType vtkRefractionGeometryStage::GetShaderStageMTime()
{
  return this->DefinesTime.GetMTime();
}

//------------------------------------------------------------------------------
void vtkRefractionGeometryStage::DrawProps(vtkOpenGLRenderer* ren, int stage)
{
  vtkRenderState state(ren);
  state.SetPropArrayAndCount(this->Glass.data(), static_cast<int>(this->Glass.size()));
  vtkOpenGLState* ostate = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow())->GetState();
  vtkOpenGLState::ScopedglEnableDisable cullSaver(ostate, GL_CULL_FACE);
  int cullMode = GL_BACK;
  ostate->vtkglGetIntegerv(GL_CULL_FACE_MODE, &cullMode);
  this->PreRender(&state);
  // With a separate composite program its code is in the mapper's program only while the
  // composite is drawn (SetSeparateCompositeProgram): switching rebuilds the mapper's shader
  // source, and VTK's shader cache hands back the program already compiled for it.
  const bool compositeProgram =
    this->SampleComposite && (!this->SeparateCompositeProgram || stage == STAGE_COMPOSITE);
  if (compositeProgram != this->CompositeProgram)
  {
    this->CompositeProgram = compositeProgram;
    this->DefinesTime.Modified();
  }
  this->Stage = stage;
  this->State = ostate;
  this->Renderer = ren;
  this->NumberOfRenderedProps = 0;
  for (vtkProp* prop : this->Glass)
  {
    this->NumberOfRenderedProps += prop->RenderOpaqueGeometry(ren);
  }
  this->State = nullptr;
  this->Renderer = nullptr;
  this->Stage = STAGE_NONE;
  this->SHTransfer->Unbind();
  this->PieceSheets->Unbind();
  this->PostRender(&state);
  ostate->vtkglCullFace(static_cast<unsigned int>(cullMode));
}

//------------------------------------------------------------------------------
void vtkRefractionGeometryStage::DrawIntoTargets(vtkOpenGLRenderer* ren,
  vtkRefractionTargets* targets, const std::vector<int>& colours, int depth, double clearDepth,
  unsigned int depthFunc, int stage, unsigned int anyKeptQuery, bool* keptTwice)
{
  vtkOpenGLRenderWindow* renWin = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  vtkOpenGLState* ostate = renWin->GetState();
  std::vector<vtkTextureObject*> textures;
  for (int colour : colours)
  {
    textures.push_back(targets->Get(colour));
  }
  {
    vtkRefractionTargetDraw draw(renWin, targets, textures, targets->Get(depth));
    this->Width = draw.GetWidth();
    this->Height = draw.GetHeight();
    this->Origin[0] = 0;
    this->Origin[1] = 0;
    this->ActiveDrawBuffers = static_cast<int>(textures.size());
    ostate->vtkglScissor(0, 0, this->Width, this->Height);
    ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
    ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    ostate->vtkglDepthMask(GL_TRUE);
    ostate->vtkglClearDepth(clearDepth);
    ostate->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    ostate->vtkglClearDepth(1.0);
    ostate->vtkglEnable(GL_DEPTH_TEST);
    ostate->vtkglDepthFunc(depthFunc);
    ostate->vtkglDisable(GL_BLEND);
    const bool counting = keptTwice && this->PeelCount->Start(renWin, targets->Get(depth));
    if (anyKeptQuery != 0)
    {
      glBeginQuery(GL_ANY_SAMPLES_PASSED, anyKeptQuery);
    }
    this->DrawProps(ren, stage);
    if (anyKeptQuery != 0)
    {
      glEndQuery(GL_ANY_SAMPLES_PASSED); // before the count's own query
    }
    if (keptTwice)
    {
      *keptTwice = counting ? this->PeelCount->Finish(renWin) : true;
    }
  }
  this->ActiveDrawBuffers = 0;
}

//------------------------------------------------------------------------------
void vtkRefractionGeometryStage::DrawFront(vtkOpenGLRenderer* ren, vtkRefractionTargets* targets)
{
  std::vector<int> colours{ vtkRefractionTargets::FRONT_SURFACE };
  if (this->DataColour)
  {
    colours.push_back(vtkRefractionTargets::FRONT_COLOR);
  }
  if (this->NormalDistance)
  {
    colours.push_back(vtkRefractionTargets::FRONT_AUX);
  }
  if (this->UseSHTransfer)
  {
    colours.push_back(vtkRefractionTargets::FRONT_SH);
  }
  this->DrawIntoTargets(
    ren, targets, colours, vtkRefractionTargets::FRONT_DEPTH, 1.0, GL_LESS, STAGE_FRONT);
}

//------------------------------------------------------------------------------
void vtkRefractionGeometryStage::DrawBack(vtkOpenGLRenderer* ren, vtkRefractionTargets* targets)
{
  this->DrawIntoTargets(ren, targets, { vtkRefractionTargets::BACK_SURFACE },
    vtkRefractionTargets::BACK_Z, this->BackNearest ? 1.0 : 0.0,
    this->BackNearest ? GL_LESS : GL_GREATER, STAGE_BACK);
}

//------------------------------------------------------------------------------
bool vtkRefractionGeometryStage::DrawPeel(vtkOpenGLRenderer* ren, vtkRefractionTargets* targets,
  int layer, int layers, bool askWhetherEmpty, bool* behind)
{
  if (behind)
  {
    *behind = true;
  }
  if (!this->Peel || layer < 1 || layer > 7)
  {
    return false;
  }
  if (askWhetherEmpty && this->PeelQuery == 0)
  {
    glGenQueries(1, &this->PeelQuery);
  }
  this->PeelPrevious = targets->Get(
    layer == 1 ? vtkRefractionTargets::FRONT_SURFACE : vtkRefractionTargets::PEEL_1 + layer - 2);
  this->PeelPrevious->Activate();
  // The furthest surface behind the previous layer where rf_peel_last_is_furthest says so (the
  // peeling test of rfGeometryFS.glsl, GL_GREATER as DIR's back capture): with two layers the
  // nearest one behind the front, on glass of more than two surfaces an inner surface, sent
  // the rays out into the environment from inside the glass (the isosurface 19.3 -> 20.0 dB,
  // the nested contours 10.9 -> 11.7 against the 2 x 2 truth).
  const bool furthest = layer == layers - 1 && rf_peel_last_is_furthest(layers);
  this->PeelLayer = layer;
  this->PeelFurthest = furthest;
  // Drawn by facing, a layer the ray enters through (even) draws no surface it leaves
  // through, so its count cannot see the next layer; but wherever it holds glass, a surface
  // to leave through lies behind it: the next layer is there if this one is. A layer left
  // through (odd) keeps two surfaces at a pixel exactly where one is entered between them.
  const bool entered = this->PeelByFacing && !PeelLayerIsLeft(layer, furthest);
  this->DrawIntoTargets(ren, targets, { vtkRefractionTargets::PEEL_1 + layer - 1 },
    vtkRefractionTargets::PEEL_Z, furthest ? 0.0 : 1.0, furthest ? GL_GREATER : GL_LESS,
    STAGE_PEEL, askWhetherEmpty ? this->PeelQuery : 0, entered ? nullptr : behind);
  this->PeelLayer = 0;
  this->PeelPrevious->Deactivate();
  this->PeelPrevious = nullptr;
  if (!askWhetherEmpty)
  {
    return true;
  }
  // Read now: the next layer would be drawn for nothing. On llvmpipe the wait is the layer's
  // own rasterization, which the next draw waited for anyway (it reads this layer).
  GLuint anyKept = 1;
  glGetQueryObjectuiv(this->PeelQuery, GL_QUERY_RESULT, &anyKept);
  return anyKept != 0;
}

//------------------------------------------------------------------------------
int vtkRefractionGeometryStage::DrawPeelLayers(
  vtkOpenGLRenderer* ren, vtkRefractionTargets* targets, int layers, bool stopAtEmpty)
{
  this->PeelDraws = 0;
  this->PeelByFacing = false;
  // Several props may overlap or nest (a ball in a ball is entered twice in a row). Asked with
  // the k-buffer too, so that AUTO can leave it for peeling by facing.
  this->PeelFacingPossible =
    this->Glass.size() == 1 && this->SurfaceModel->Alternates(this->Glass[0]);
  if (this->PeelKBufferConfigured == layers && targets->Get(vtkRefractionTargets::PEEL_SLOTS))
  {
    this->PeelDraws = 2;
    return this->DrawPeelKBuffer(ren, targets, layers);
  }
  this->PeelByFacing = this->PeelFacingPossible;
  for (int layer = 1; layer < layers; ++layer)
  {
    ++this->PeelDraws;
    // Whether a layer can follow this one, asked where one more would be drawn.
    bool behind = true;
    if (!this->DrawPeel(ren, targets, layer, layers, stopAtEmpty,
          stopAtEmpty && layer + 1 < layers ? &behind : nullptr))
    {
      // Nothing behind this layer's (empty) texels either: the layers from here on are left
      // as they are, and the packing and the shading read them as empty.
      return layer;
    }
    if (!behind)
    {
      // No pixel kept two surfaces behind the layer before: the next would come out empty
      // (on a convex glass the draw that learnt so was about half the layers' capture).
      return layer + 1;
    }
  }
  return layers;
}

//------------------------------------------------------------------------------
bool vtkRefractionGeometryStage::SupportsPeelKBuffer(
  vtkOpenGLRenderWindow* renWin, int height, int layers)
{
  if (!renWin || layers < 3 || layers > 8 || height < 1)
  {
    return false;
  }
  // The program is GLSL 1.50 (VTK's) with the extensions: floatBitsToUint is GLSL 3.30's.
  const bool images = (GLEW_VERSION_4_2 || GLEW_ARB_shader_image_load_store) &&
    (GLEW_VERSION_3_3 || GLEW_ARB_shader_bit_encoding);
  if (!images)
  {
    return false;
  }
  GLint imageUniforms = 0;
  GLint imageUnits = 0;
  GLint textureSize = 0;
  glGetIntegerv(GL_MAX_FRAGMENT_IMAGE_UNIFORMS, &imageUniforms);
  glGetIntegerv(GL_MAX_IMAGE_UNITS, &imageUnits);
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &textureSize);
  // The slots, and one row more for the count of layers found.
  return imageUniforms >= layers && imageUnits >= layers &&
    static_cast<long long>(height) * (layers - 1) + 1 <= textureSize;
}

//------------------------------------------------------------------------------
void vtkRefractionGeometryStage::BindPeelImages(vtkRefractionTargets* targets, int layers)
{
  for (int unit = 0; unit < layers; ++unit)
  {
    vtkTextureObject* texture = !targets ? nullptr
      : unit == 0                        ? targets->Get(vtkRefractionTargets::PEEL_SLOTS)
                                         : targets->Get(vtkRefractionTargets::PEEL_1 + unit - 1);
    glBindImageTexture(static_cast<GLuint>(unit), texture ? texture->GetHandle() : 0, 0,
      GL_FALSE, 0, unit == 0 ? GL_READ_WRITE : GL_WRITE_ONLY,
      unit == 0 ? GL_R32UI : GL_RGBA32F);
  }
}

//------------------------------------------------------------------------------
int vtkRefractionGeometryStage::DrawPeelKBuffer(
  vtkOpenGLRenderer* ren, vtkRefractionTargets* targets, int layers)
{
  vtkOpenGLRenderWindow* renWin = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  vtkOpenGLState* ostate = renWin->GetState();
  vtkTextureObject* slots = targets->Get(vtkRefractionTargets::PEEL_SLOTS);
  vtkTextureObject* front = targets->Get(vtkRefractionTargets::FRONT_SURFACE);
  this->Width = static_cast<int>(front->GetWidth());
  this->Height = static_cast<int>(front->GetHeight());
  this->Origin[0] = 0;
  this->Origin[1] = 0;
  const GLuint emptySlot = 0xFFFFFFFFu;
  // The clears are the framebuffer's (glClearTexImage took about 4 ms a layer at 512 x 512 on
  // llvmpipe). The last frame's draws wrote these textures through the images.
  glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT);
  vtkRefractionTargetDraw draw(renWin, targets, { slots }, nullptr);
  ostate->vtkglDisable(GL_SCISSOR_TEST);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glClearBufferuiv(GL_COLOR, 0, &emptySlot);
  std::vector<vtkTextureObject*> peeled;
  for (int layer = 1; layer < layers; ++layer)
  {
    peeled.push_back(targets->Get(vtkRefractionTargets::PEEL_1 + layer - 1));
  }
  draw.Attach(peeled, nullptr);
  ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
  ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
  // The draws write through the images only: a framebuffer of the targets' size whose colour
  // (the packed depths, written after) is masked and whose depth is not tested.
  draw.Attach({ targets->Get(vtkRefractionTargets::PEEL_DEPTHS_A) },
    targets->Get(vtkRefractionTargets::PEEL_Z));
  ostate->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  ostate->vtkglDepthMask(GL_FALSE);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglDisable(GL_BLEND);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  this->BindPeelImages(targets, layers);
  this->PeelPrevious = front;
  this->PeelPrevious->Activate();
  this->DrawProps(ren, STAGE_PEEL_DEPTHS);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  this->DrawProps(ren, STAGE_PEEL_LAYERS);
  // The layers are read next as textures (the packing, the shading), the count below.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
  this->BindPeelImages(nullptr, layers);
  this->PeelPrevious->Deactivate();
  this->PeelPrevious = nullptr;
  // How many layers hold glass anywhere: the first draw took the minimum of ~(slots filled)
  // over the pixels into the texel past the last slot (rfPeelInsertDepth). Read now, as the
  // peeling's occlusion queries are: the shading follows only the layers found.
  GLuint count = emptySlot;
  draw.Attach({ slots }, nullptr);
  draw.GetFramebuffer()->ActivateReadBuffer(0);
  glReadPixels(0, this->Height * (layers - 1), 1, 1, GL_RED_INTEGER, GL_UNSIGNED_INT, &count);
  const int behindFront = static_cast<int>(emptySlot - count);
  return 1 + std::min(std::max(behindFront, 0), layers - 1);
}

//------------------------------------------------------------------------------
void vtkRefractionGeometryStage::DrawMask(vtkOpenGLRenderer* ren)
{
  vtkOpenGLRenderWindow* renWin = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  vtkOpenGLState* ostate = renWin->GetState();
  // The chapter's refraction mask, in the alpha channel of the opaque scene: where the glass
  // is the visible surface, alpha becomes 0.25 + 0.5 alpha (0.75 over an object, 0.25 over
  // the background); elsewhere it stays 1 (objects, including those in front) or 0.
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
  // The stage writes alpha 0.5: 0.5 * 0.5 + (1 - 0.5) * alpha, with no blend colour to set.
  ostate->vtkglBlendFuncSeparate(GL_ZERO, GL_ONE, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  this->DrawOnScreen(ren, STAGE_MASK);
}

//------------------------------------------------------------------------------
void vtkRefractionGeometryStage::DrawOnScreen(vtkOpenGLRenderer* ren, int stage)
{
  if (stage == STAGE_COMPOSITE && !this->SampleComposite)
  {
    // The program would run the G-buffer's code and write it onto the screen.
    vtkErrorMacro("The composite at the samples was not configured for this frame "
                  "(SetSampleComposite before Configure); the glass is not drawn there.");
    return;
  }
  ren->GetTiledSizeAndOrigin(&this->Width, &this->Height, this->Origin, this->Origin + 1);
  this->DrawProps(ren, stage);
}

//------------------------------------------------------------------------------
bool vtkRefractionGeometryStage::PreReplaceShaderValues(std::string& vertexShader,
  std::string& geometryShader, std::string& fragmentShader, vtkAbstractMapper* mapper,
  vtkProp* prop)
{
  if (!IsGlassMapper(mapper, prop))
  {
    return true;
  }
  // VTK's lighting would be computed per fragment and thrown away: the geometry stage writes
  // every output itself. The tags stay for the mapper; ours follow them.
  // What VTK's colour code leaves (the actor's colour or the scalars through the lookup table,
  // and a colour texture applied after it) stays in gl_FragData[0] for the G-buffer to keep.
  vtkShaderProgram::Substitute(
    fragmentShader, "//VTK::Light::Impl", "gl_FragData[0] = RF_DATA_COLOUR;\n", false);
  if (this->PeelKBufferConfigured)
  {
    // Before any declaration: after the #version that replaces the tag.
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::System::Dec",
      "//VTK::System::Dec\n#extension GL_ARB_shader_image_load_store : require\n"
      "#extension GL_ARB_shader_bit_encoding : require\n",
      false);
  }
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::Output::Dec",
    std::string("//VTK::Output::Dec\n") + kDecTag + "\n", false);
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::Coincident::Impl",
    std::string("//VTK::Coincident::Impl\n") + kImplTag + "\n", false);
  if (this->UseSHTransfer)
  {
    // The SH method's exit direction and length, per vertex (rfSHTransferVS.glsl).
    std::string source = rfSHTransferVSSource;
    const size_t marker = source.find(kImplMarker);
    std::string declarations = source.substr(0, marker);
    const std::string body = source.substr(marker + std::string(kImplMarker).size());
    vtkShaderProgram::Substitute(declarations, "//RF::Kernel", rfKernelSource);
    vtkShaderProgram::Substitute(
      vertexShader, "//VTK::Normal::Dec", "//VTK::Normal::Dec\n" + declarations, false);
    vtkShaderProgram::Substitute(
      vertexShader, "//VTK::Normal::Impl", "//VTK::Normal::Impl\n" + body, false);
  }
  if (this->UsePieceSheets)
  {
    vtkRefractionPieceSheets::ReplaceShaderValues(vertexShader, geometryShader);
  }
  if (this->NormalDistance)
  {
    // d_N travels as a generic vertex attribute (MapNormalDistance) to a varying.
    vtkShaderProgram::Substitute(vertexShader, "//VTK::Normal::Dec",
      "//VTK::Normal::Dec\nin float rfNormalDistance;\nout float rfNormalDistanceVSOut;\n", false);
    vtkShaderProgram::Substitute(vertexShader, "//VTK::Normal::Impl",
      "//VTK::Normal::Impl\n  rfNormalDistanceVSOut = rfNormalDistance;\n", false);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkRefractionGeometryStage::PostReplaceShaderValues(std::string& vertexShader,
  std::string& geometryShader, std::string& fragmentShader, vtkAbstractMapper* mapper,
  vtkProp* prop)
{
  if (!IsGlassMapper(mapper, prop))
  {
    return true;
  }
  const bool replaced = this->ReplaceGlassShaderValues(fragmentShader);
  // Last: VTK 9.1's mapper crashes on a program its cache cannot build.
  vtkOpenGLRenderWindow* renWin = this->Renderer
    ? vtkOpenGLRenderWindow::SafeDownCast(this->Renderer->GetRenderWindow())
    : nullptr;
  const bool builds =
    this->ProgramGuard->Check(renWin, prop, vertexShader, geometryShader, fragmentShader);
  this->BuildFailures.erase(std::remove_if(this->BuildFailures.begin(),
                               this->BuildFailures.end(),
                               [](const vtkWeakPointer<vtkProp>& p) { return !p; }),
    this->BuildFailures.end());
  auto reported = std::find(this->BuildFailures.begin(), this->BuildFailures.end(), prop);
  if (builds && reported != this->BuildFailures.end())
  {
    this->BuildFailures.erase(reported);
  }
  else if (!builds && reported == this->BuildFailures.end())
  {
    this->BuildFailures.push_back(prop);
    vtkErrorMacro("Glass prop " << prop->GetClassName() << " " << prop
                                << ": its glass shader does not build (the shader program's "
                                   "error above): the prop is not drawn.");
  }
  return replaced; // a program that does not build is reported above
}

//------------------------------------------------------------------------------
bool vtkRefractionGeometryStage::ReplaceGlassShaderValues(std::string& fragmentShader)
{
  const std::string source = rfGeometryFSSource;
  const size_t marker = source.find(kImplMarker);
  std::string declarations = source.substr(0, marker);
  const std::string body = source.substr(marker + std::string(kImplMarker).size());
  vtkShaderProgram::Substitute(
    declarations, "//RF::Common", std::string(rfKernelSource) + rfCommonSource);
  vtkShaderProgram::Substitute(declarations, "//RF::GlassAround", rfGlassAroundSource);
  // The mapper declares vertexVC only with lighting, and normalVCVSOutput only with normals
  // or lighting; otherwise rebuild them from the fragment's coordinates.
  const bool haveVertexVC = fragmentShader.find("vec4 vertexVC") != std::string::npos;
  const bool haveNormal = fragmentShader.find("normalVCVSOutput") != std::string::npos;
  std::ostringstream defines;
  // The data's colour as VTK's colour code leaves it: with EdgeVisibility, VTK has already
  // mixed the edge colour in by `emix` (into ambient and diffuse, or ambient alone unlit), and
  // the G-buffer keeps emix too, so that the shading stage draws the edges over the glass.
  // Its alpha is 1, not the actor's opacity: VTK discards fragments of alpha 0 after the
  // colour code, and glass is drawn only where the actor is opaque. With a backface property
  // VTK takes the back faces' opacity from a uniform it sets only while the program uses the
  // back faces' colour, which a G-buffer draw that keeps no colour does not: the uniform stayed
  // 0, and every back face of the capture was discarded.
  const bool haveColour = fragmentShader.find("vec3 diffuseColor") != std::string::npos &&
    fragmentShader.find("vec3 ambientColor") != std::string::npos;
  // A composite program of its own draws nothing else: without the G-buffer's code, which
  // llvmpipe would run beside the composite's for every fragment.
  defines << this->Defines << (this->CompositeProgram ? "#define RF_SAMPLE_COMPOSITE\n" : "")
          << (this->CompositeProgram && this->SeparateCompositeProgram
                 ? "#define RF_COMPOSITE_ONLY\n"
                 : "")
          << (this->CompositeProgram && this->CompositeInputs[2] ? "#define RF_COMPOSITE_CORNERS\n"
                                                                : "")
          << "#define RF_DATA_COLOUR "
          << (haveColour ? "vec4(ambientColor + diffuseColor, 1.0)" : "vec4(1.0)")
          << "\n#define RF_EDGE_MIX "
          << (fragmentShader.find("float emix") != std::string::npos ? "emix" : "0.0")
          << "\n#define RF_POSITION_VC "
          << (haveVertexVC ? "vertexVC.xyz" : "rfReconstructPositionVC()") << "\n"
          << "#define RF_NORMAL_VC " << (haveNormal ? "normalVCVSOutput" : "vec3(0.0)") << "\n"
          // A position rebuilt from gl_FragCoord spans two directions on a line's pixels too.
          << (haveVertexVC ? "#define RF_SURFACES_ONLY\n" : "");
  if (fragmentShader.find(kDecTag) == std::string::npos ||
    fragmentShader.find(kImplTag) == std::string::npos)
  {
    vtkErrorMacro("The mapper's fragment shader has no //VTK::Output::Dec or "
                  "//VTK::Coincident::Impl tag; the glass cannot be drawn.");
    return false;
  }
  vtkShaderProgram::Substitute(fragmentShader, kDecTag, defines.str() + declarations, false);
  vtkShaderProgram::Substitute(fragmentShader, kImplTag, body, false);
  return true;
}

//------------------------------------------------------------------------------
bool vtkRefractionGeometryStage::SetShaderParameters(vtkShaderProgram* program,
  vtkAbstractMapper* mapper, vtkProp* prop, vtkOpenGLVertexArrayObject*)
{
  if (!IsGlassMapper(mapper, prop) || this->Stage == STAGE_NONE)
  {
    return true;
  }
  auto material = this->MaterialIndex.find(prop);
  program->SetUniformi("rfGeometryStage", this->Stage);
  if (this->Stage == STAGE_MASK && this->Renderer)
  {
    // vtkOpenGLActor::Render turns depth writes on for an opaque actor just before this call.
    // The mask must leave the scene's depth alone: in a multisampled window the glass's
    // per-sample depths would otherwise lie behind the per-pixel depth the composite writes
    // at about half the samples, and the glass would come out half dark.
    static_cast<vtkOpenGLRenderWindow*>(this->Renderer->GetRenderWindow())
      ->GetState()
      ->vtkglDepthMask(GL_FALSE);
  }
  if (program->IsUniformUsed("rfCompositeColour"))
  {
    // Outside the composite stage the samplers point at the last texture unit, which the unit
    // manager (it hands out units from 0) leaves free: left at 0 they could share a unit with
    // a sampler of another type (a mapper's cell-scalar buffer), a GL error at the draw.
    int units = 1;
    glGetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &units);
    const bool composite = this->Stage == STAGE_COMPOSITE;
    if (program->IsUniformUsed("rfCompositeSurface")) // not by one material's pixels
    {
      program->SetUniformi(
        "rfCompositeSurface", composite ? this->CompositeInputs[0] : units - 1);
    }
    program->SetUniformi("rfCompositeColour", composite ? this->CompositeInputs[1] : units - 1);
  }
  if (program->IsUniformUsed("rfMaterial"))
  {
    program->SetUniformf("rfMaterial",
      material == this->MaterialIndex.end() ? 1.f : static_cast<float>(material->second + 1));
  }
  if (this->UsePieceSheets && this->State && this->Renderer)
  {
    // A mesh whose pieces disagree: its sheet pieces' flags and material.
    auto sheetMaterial = this->SheetMaterialIndex.find(prop);
    vtkPolyData* mesh = sheetMaterial == this->SheetMaterialIndex.end()
      ? nullptr
      : this->SurfaceModel->GetProp(prop).PerPiece;
    const int own = material == this->MaterialIndex.end() ? 1 : material->second + 1;
    this->PieceSheets->Bind(program, mesh, mesh ? &this->SurfaceModel->GetMesh(mesh) : nullptr,
      mesh ? sheetMaterial->second + 1 : own,
      static_cast<vtkOpenGLRenderWindow*>(this->Renderer->GetRenderWindow()));
  }
  if (program->IsUniformUsed("rfParallel"))
  {
    program->SetUniformi("rfParallel", this->Parallel ? 1 : 0);
  }
  if (program->IsUniformUsed("rfSurfacesOnly"))
  {
    // With the wireframe or points representation the lines or points are the glass.
    program->SetUniformi("rfSurfacesOnly", vtkRefractionMeshes::DrawsSurfaces(prop) ? 1 : 0);
  }
  if (program->IsUniformUsed("rfDCVC"))
  {
    program->SetUniformMatrix("rfDCVC", this->InverseProjection);
  }
  if (program->IsUniformUsed("rfViewport"))
  {
    // gl_FragCoord counts from the window's corner on screen (the mask), from the texture's
    // in the targets.
    const float viewport[4] = { static_cast<float>(this->Origin[0]),
      static_cast<float>(this->Origin[1]), static_cast<float>(this->Width),
      static_cast<float>(this->Height) };
    program->SetUniform4f("rfViewport", viewport);
  }
  if (this->UseSHTransfer && this->State)
  {
    this->SHTransfer->Bind(program, prop, this->Renderer,
      static_cast<vtkOpenGLRenderWindow*>(this->Renderer->GetRenderWindow()));
  }
  const bool peelStage = this->Stage == STAGE_PEEL || this->Stage == STAGE_PEEL_DEPTHS ||
    this->Stage == STAGE_PEEL_LAYERS;
  if (peelStage && this->PeelPrevious && program->IsUniformUsed("rfPeelPrevious"))
  {
    program->SetUniformi("rfPeelPrevious", this->PeelPrevious->GetTextureUnit());
    program->SetUniformi("rfOutwardFront", this->IsOutwardFront(prop) ? 1 : 0);
  }
  else if (this->Stage == STAGE_FRONT && program->IsUniformUsed("rfOutwardFront"))
  {
    program->SetUniformi("rfOutwardFront", this->IsOutwardFront(prop) ? 1 : 0);
  }
  if (program->IsUniformUsed("rfPeelSlots"))
  {
    // Image units 0 .. K - 1 (BindPeelImages); outside the k-buffer's draws nothing reads them.
    program->SetUniformi("rfPeelSlots", 0);
    // One slot's rows: the targets' height, which the k-buffer's draws set (DrawPeelKBuffer).
    program->SetUniformi("rfPeelSlotRows", this->Height);
    for (int layer = 1; layer < this->PeelKBufferConfigured; ++layer)
    {
      const std::string name = "rfPeelLayer" + std::to_string(layer);
      if (program->IsUniformUsed(name.c_str()))
      {
        program->SetUniformi(name.c_str(), layer);
      }
    }
  }
  if (program->IsUniformUsed("rfWindingSign"))
  {
    program->SetUniformi("rfWindingSign", this->SurfaceModel->GetProp(prop).WindingSign);
  }
  this->CullHiddenFaces(prop);
  if (program->IsUniformUsed("rfHaveNormalDistance"))
  {
    const bool have = this->HasNormalDistance(prop);
    program->SetUniformi("rfHaveNormalDistance", have ? 1 : 0);
    // d_N is measured in model coordinates: scale it with the actor.
    const double scale = vtkRefractionModelMatrix::GetScale(prop);
    program->SetUniformf("rfModelScale", static_cast<float>(scale));
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkRefractionGeometryStage::CullHiddenFaces(vtkProp* prop)
{
  // vtkOpenGLProperty::Render has just set the actor's own culling; this runs after it, just
  // before the draw. On a closed mesh the nearest surface always faces the camera and the
  // furthest faces away, so the other faces need neither rasterizing nor shading (about half
  // the fragments of each stage). Open meshes keep both: their back side can be the nearest.
  // Peeling keeps every face, whatever the actor's own culling, but where every sight line
  // enters and leaves the glass by turns (PeelByFacing): there the surface behind layer k - 1
  // faces away from the viewer for odd k, and the furthest always does, so the other faces
  // would only be rasterized and shaded to be discarded (on llvmpipe, whose depth test is late
  // under the peeling's stencil count, a third to a half of the layers' capture: the sphere,
  // torus and isosurface of the benchmark, docs/benchmark.md). The composite at the
  // window's samples culls as the front stage does (on llvmpipe in a 4-sample window it took
  // 190 ms a frame on the benchmark's sphere unculled, 48 culled), but not with edges shown:
  // VTK's edges of the back faces show at the silhouette, and an opaque actor shows them.
  if (this->State && this->Stage == STAGE_PEEL && this->PeelByFacing && this->PeelLayer > 0)
  {
    const bool leaving = PeelLayerIsLeft(this->PeelLayer, this->PeelFurthest);
    this->State->vtkglEnable(GL_CULL_FACE);
    this->State->vtkglCullFace(leaving == this->IsOutwardFront(prop) ? GL_FRONT : GL_BACK);
    return;
  }
  if (this->State &&
    (this->Stage == STAGE_PEEL || this->Stage == STAGE_PEEL_DEPTHS ||
      this->Stage == STAGE_PEEL_LAYERS))
  {
    this->State->vtkglDisable(GL_CULL_FACE);
    return;
  }
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  if (this->Stage == STAGE_COMPOSITE && actor && actor->GetProperty()->GetEdgeVisibility())
  {
    return;
  }
  const vtkRefractionSurfaceModel::Prop surface = this->SurfaceModel->GetProp(prop);
  if (!this->State || !surface.Closed ||
    (this->Stage != STAGE_FRONT && this->Stage != STAGE_BACK && this->Stage != STAGE_COMPOSITE))
  {
    return;
  }
  const bool cullFront = (this->Stage == STAGE_BACK) == this->IsOutwardFront(prop);
  this->State->vtkglEnable(GL_CULL_FACE);
  this->State->vtkglCullFace(cullFront ? GL_FRONT : GL_BACK);
}

//------------------------------------------------------------------------------
bool vtkRefractionGeometryStage::IsOutwardFront(vtkProp* prop)
{
  // A mirroring actor matrix turns the winding seen on screen.
  const double mirror = vtkRefractionModelMatrix::GetDeterminant(prop);
  return (this->SurfaceModel->GetProp(prop).WindingSign > 0) == (mirror >= 0.0);
}

//------------------------------------------------------------------------------
bool vtkRefractionGeometryStage::HasNormalDistance(vtkProp* prop)
{
  if (vtkRefractionMeshes::IsComposite(prop))
  {
    return false; // the composite mapper's helpers upload no extra attributes (VTK 9.1)
  }
  const std::vector<vtkRefractionMeshes::Block> blocks = vtkRefractionMeshes::GetBlocks(prop);
  for (const auto& block : blocks)
  {
    if (!block.Mesh->GetPointData()->GetArray(vtkRefractionGlassKeys::GetISRDistanceArrayName()))
    {
      return false;
    }
  }
  return !blocks.empty();
}

//------------------------------------------------------------------------------
void vtkRefractionGeometryStage::MapNormalDistance(vtkProp* prop)
{
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  vtkOpenGLPolyDataMapper* mapper =
    actor ? vtkOpenGLPolyDataMapper::SafeDownCast(actor->GetMapper()) : nullptr;
  if (!mapper)
  {
    return;
  }
  for (const auto& mapped : this->NormalDistanceMappers)
  {
    if (mapped == mapper)
    {
      return;
    }
  }
  const char* name = vtkRefractionGlassKeys::GetISRDistanceArrayName();
  if (vtkRefractionMeshes::IsComposite(prop))
  {
    vtkWarningMacro("ISR: glass actor " << actor
                                        << " draws composite data: VTK's (9.1, 9.2) "
                                           "vtkCompositePolyDataMapper2 uploads no extra vertex "
                                           "attributes, so d_N cannot reach the shader; using "
                                           "d_N = d_V (SIR's distance).");
  }
  else if (!this->HasNormalDistance(prop))
  {
    vtkWarningMacro("ISR: glass actor " << actor << " has no point array \"" << name
                                        << "\" (vtkISRDistanceFilter adds it); using d_N = d_V.");
  }
  mapper->MapDataArrayToVertexAttribute(
    "rfNormalDistance", name, vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  this->NormalDistanceMappers.erase(
    std::remove_if(this->NormalDistanceMappers.begin(), this->NormalDistanceMappers.end(),
      [](const vtkWeakPointer<vtkMapper>& m) { return m == nullptr; }),
    this->NormalDistanceMappers.end());
  this->NormalDistanceMappers.emplace_back(mapper);
}
