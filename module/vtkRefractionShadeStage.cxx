#include "vtkRefractionShadeStage.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLTexture.h"
#include "vtkPointData.h"
#include "vtkRefractionLights.h"
#include "vtkRefractionMethod.h"
#include "vtkRefractionPass.h"
#include "vtkRefractionQuad.h"
#include "vtkRefractionTargetDraw.h"
#include "vtkRefractionTargets.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "rfShaders.h"
#include "vtk_glew.h"

#include <algorithm>
#include <sstream>

vtkStandardNewMacro(vtkRefractionShadeStage);

//------------------------------------------------------------------------------
std::string vtkRefractionShadeStage::GetFarPlaneQuadVertexShader()
{
  std::string source = vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader();
  vtkShaderProgram::Substitute(
    source, "gl_Position = ndCoordIn;", "gl_Position = vec4(ndCoordIn.xy, 1.0, 1.0);");
  return source;
}

struct vtkRefractionShadeStage::Program
{
  std::string Defines;
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
};

namespace
{
// The sampler each target is bound to when the shading program reads it.
struct TargetSampler
{
  int Target;
  const char* Name;
};
const TargetSampler kSamplers[] = {
  { vtkRefractionTargets::FRONT_SURFACE, "rfFrontSurface" },
  { vtkRefractionTargets::FRONT_AUX, "rfFrontAux" },
  { vtkRefractionTargets::FRONT_COLOR, "rfFrontColour" },
  { vtkRefractionTargets::BACK_SURFACE, "rfBackSurface" },
  { vtkRefractionTargets::SCENE_COLOR, "rfSceneColor" },
  { vtkRefractionTargets::SCENE_DEPTH, "rfSceneDepth" },
  { vtkRefractionTargets::PEEL_STACK, "rfPeelStack" },
  { vtkRefractionTargets::PEEL_DEPTHS_A, "rfPeelDepthsA" },
  { vtkRefractionTargets::PEEL_DEPTHS_B, "rfPeelDepthsB" },
  { vtkRefractionTargets::FRONT_SH, "rfFrontSH" },
  { vtkRefractionTargets::COARSE_COLOR, "rfCoarseColour" },
  { vtkRefractionTargets::COARSE_RAY, "rfCoarseRay" },
};
}

namespace
{
// Binds every allocated target whose sampler the program reads; returns them, to deactivate.
std::vector<vtkTextureObject*> BindTargets(vtkShaderProgram* program, vtkRefractionTargets* targets)
{
  std::vector<vtkTextureObject*> bound;
  for (const TargetSampler& sampler : kSamplers)
  {
    vtkTextureObject* texture = targets->Get(sampler.Target);
    if (texture && program->IsUniformUsed(sampler.Name))
    {
      texture->Activate();
      program->SetUniformi(sampler.Name, texture->GetTextureUnit());
      bound.push_back(texture);
    }
  }
  return bound;
}
}

//------------------------------------------------------------------------------
vtkRefractionShadeStage::vtkRefractionShadeStage() = default;
vtkRefractionShadeStage::~vtkRefractionShadeStage() = default;

//------------------------------------------------------------------------------
void vtkRefractionShadeStage::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Shading program: " << (this->Shade ? "built" : "none") << "\n";
  os << indent << "Debug program: " << (this->Debug ? "built" : "none") << "\n";
  os << indent << "Coarse shading programs: "
     << (this->CoarseSamples && this->CoarseDepthQuad && this->CoarseResolveQuad ? "built"
                                                                                : "none")
     << "\n";
  os << indent << "Composite program: " << (this->CompositeQuad ? "built" : "none") << "\n";
  os << indent << "Anti-aliasing composite program: "
     << (this->CornerCompositeQuad ? "built" : "none") << "\n";
  os << indent << "Program smoothing internal reflections: "
     << (this->SmoothQuad ? "built" : "none") << "\n";
  os << indent << "Corner depth program: " << (this->CornerDepthQuad ? "built" : "none") << "\n";
}

//------------------------------------------------------------------------------
vtkRefractionShadeStage::Program* vtkRefractionShadeStage::GetProgram(int kind)
{
  std::unique_ptr<Program>& program = kind == PROGRAM_DEBUG ? this->Debug
    : kind == PROGRAM_COARSE_SAMPLES                        ? this->CoarseSamples
                                                            : this->Shade;
  if (!program)
  {
    program.reset(new Program);
  }
  return program.get();
}

//------------------------------------------------------------------------------
bool vtkRefractionShadeStage::Prepare(vtkOpenGLRenderer* ren, vtkRefractionMethod* method,
  vtkRefractionPass* settings, const Frame& frame, bool debug)
{
  std::ostringstream defines;
  method->AppendDefines(defines, settings);
  defines << "#define RF_MAX_MATERIALS " << MaximumMaterials << "\n";
  // The back surface keeps its depth in alpha, beside the normal (vtkRefractionTargets).
  defines << "#define RF_DEPTH_CHANNEL a\n";
  if (settings->GetTIRPolicy() == vtkRefractionPass::TIR_CLAMP)
  {
    defines << "#define RF_TIR_CLAMP\n";
  }
  if (settings->GetFresnel())
  {
    defines << "#define RF_FRESNEL\n";
  }
  if (settings->GetFilteredLookups())
  {
    defines << "#define RF_FILTERED_LOOKUPS\n";
  }
  if (frame.EnvironmentCube)
  {
    defines << "#define RF_ENV_CUBEMAP\n";
  }
  else if (frame.EnvironmentBackground)
  {
    defines << "#define RF_ENV_BACKGROUND\n";
  }
  if (frame.AbsorptionDistance > 0.0)
  {
    defines << "#define RF_TINT\n";
  }
  if (frame.RedIndex && frame.BlueIndex)
  {
    defines << "#define RF_DISPERSION\n";
  }
  if (frame.Highlights && frame.Lights && frame.Lights->GetNumberOfLights() > 0)
  {
    // The lights' loop runs to a constant, their number: llvmpipe runs every pass of a loop
    // bounded by a constant and left by a break (up to RF_MAX_LIGHTS: 8), and a loop bounded by
    // a uniform costs more than its passes there (rf_kernel_dir.h, RF_FIXED_SEARCH_STEPS). A
    // change in the number of lights builds the program again.
    defines << "#define RF_HIGHLIGHTS\n#define RF_MAX_LIGHTS "
            << vtkRefractionLights::MaximumLights << "\n#define RF_LIGHT_COUNT "
            << frame.Lights->GetNumberOfLights() << "\n";
  }
  if (frame.SceneRefraction)
  {
    // March steps of the scene behind the glass: on the benchmark's scene (sphere before a
    // checkerboard and axes, 512 px) 24 steps gave 16.1 dB against the reference, 16 steps
    // 16.0 dB, 12 steps 15.5 dB.
    defines << "#define RF_SCENE_REFRACTION\n#define RF_SCENE_STEPS 16\n";
  }
  if (settings->GetAntiAliasing() && !debug)
  {
    defines << "#define RF_CORNER_SAMPLES\n";
  }
  if (debug)
  {
    defines << "#define RF_DEBUG_OUTPUT\n";
  }
  else if (frame.SmoothInternalReflections)
  {
    defines << "#define RF_SMOOTH_INTERNAL_REFLECTIONS\n";
  }
  // Coarse shading: the blocks' rays too (the pixels they do not stand for are shaded as
  // without it).
  if (!debug && frame.CoarseShading &&
    !this->Build(
      ren, method, PROGRAM_COARSE_SAMPLES, defines.str() + "#define RF_COARSE_SAMPLES\n"))
  {
    return false;
  }
  return this->Build(ren, method, debug ? PROGRAM_DEBUG : PROGRAM_SHADE, defines.str());
}

//------------------------------------------------------------------------------
bool vtkRefractionShadeStage::Build(
  vtkOpenGLRenderer* ren, vtkRefractionMethod* method, int kind, const std::string& defines)
{
  // The defines name the method and every variant, so they are the program's key: the source
  // (the kernel and the stage, tens of kilobytes) is put together only when they change, not
  // every frame.
  Program& program = *this->GetProgram(kind);
  if (program.Quad && program.Defines == defines)
  {
    return true;
  }
  std::string source = rfShadeFSSource;
  vtkShaderProgram::Substitute(source, "in vec2 texCoord;", "in vec2 texCoord;\n" + defines);
  vtkShaderProgram::Substitute(
    source, "//RF::Common", std::string(rfKernelSource) + rfCommonSource);
  vtkShaderProgram::Substitute(source, "//RF::Environment", rfEnvironmentSource);
  vtkShaderProgram::Substitute(source, "//RF::ReflectedFilter", rfReflectedFilterSource);
  vtkShaderProgram::Substitute(source, "//RF::Method", method->GetShaderSource());
  // VTK's shader cache finds a program it built before by its source.
  vtkOpenGLRenderWindow* renWin = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  program.Quad.reset(
    new vtkOpenGLQuadHelper(renWin, GetFarPlaneQuadVertexShader().c_str(), source.c_str(), ""));
  program.Defines = defines;
  if (!program.Quad->Program || !program.Quad->Program->GetCompiled())
  {
    vtkErrorMacro("Could not build the refraction shading program; the glass is not drawn.");
    program.Quad.reset();
    program.Defines.clear();
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkRefractionShadeStage::Draw(vtkOpenGLRenderer* ren, vtkRefractionMethod* method,
  vtkRefractionPass* settings, vtkRefractionTargets* targets, const Frame& frame,
  const std::vector<float>& materialIOR, const std::vector<float>& materialSheet, int kind)
{
  Program* program = this->GetProgram(kind);
  if (!program->Quad)
  {
    return;
  }
  vtkShaderProgram* shader = program->Quad->Program;
  // The cube map first: a vtkEquirectangularToCubeMapTexture renders its faces with a program
  // of its own the first time, which must not be bound when our uniforms are set.
  vtkOpenGLTexture* cube = vtkOpenGLTexture::SafeDownCast(frame.EnvironmentCube);
  const bool useCube = cube && shader->IsUniformUsed("rfEnvironmentCube");
  if (useCube)
  {
    cube->Render(ren);
    if (settings->GetFilteredLookups())
    {
      vtkRefractionShadeStage::AddEnvironmentMipmaps(cube);
    }
  }
  static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow())
    ->GetShaderCache()
    ->ReadyShaderProgram(shader);
  vtkTextureObject* front = targets->Get(vtkRefractionTargets::FRONT_SURFACE);
  std::vector<vtkTextureObject*> bound = BindTargets(shader, targets);
  const auto& levels = targets->GetReductionLevels();
  if (!levels.empty() && shader->IsUniformUsed("rfDepthRangeTex"))
  {
    levels.back()->Activate();
    shader->SetUniformi("rfDepthRangeTex", levels.back()->GetTextureUnit());
    bound.push_back(levels.back());
  }
  if (useCube)
  {
    shader->SetUniformi("rfEnvironmentCube", cube->GetTextureUnit());
    shader->SetUniformMatrix3x3("rfEnvMatrix", const_cast<float*>(frame.EnvironmentMatrix));
  }
  if (frame.EnvironmentBackground && shader->IsUniformUsed("rfBackground"))
  {
    const float bottom[3] = { static_cast<float>(frame.Background[0]),
      static_cast<float>(frame.Background[1]), static_cast<float>(frame.Background[2]) };
    const float top[3] = { static_cast<float>(frame.Background2[0]),
      static_cast<float>(frame.Background2[1]), static_cast<float>(frame.Background2[2]) };
    shader->SetUniform3f("rfBackground", bottom);
    shader->SetUniform3f("rfBackground2", top);
  }
  if (shader->IsUniformUsed("rfGlassDiagonal"))
  {
    // The view matrix is a rotation and translation (VTK's cameras): world lengths are view
    // lengths.
    shader->SetUniformf("rfGlassDiagonal", static_cast<float>(frame.GlassDiagonal));
  }
  if (shader->IsUniformUsed("rfGlassExtent"))
  {
    shader->SetUniformf("rfGlassExtent", static_cast<float>(frame.GlassExtent));
  }
  if (shader->IsUniformUsed("rfAbsorptionDistance"))
  {
    shader->SetUniformf("rfAbsorptionDistance", static_cast<float>(frame.AbsorptionDistance));
  }
  std::vector<float> ior(materialIOR);
  ior.resize(MaximumMaterials, ior.empty() ? 1.5f : ior.back());
  shader->SetUniform1fv("rfMaterialIOR", MaximumMaterials, ior.data());
  if (frame.RedIndex && frame.BlueIndex && shader->IsUniformUsed("rfMaterialIORRed"))
  {
    for (const auto& channel : { std::make_pair("rfMaterialIORRed", frame.RedIndex),
           std::make_pair("rfMaterialIORBlue", frame.BlueIndex) })
    {
      std::vector<float> values(*channel.second);
      values.resize(MaximumMaterials, values.empty() ? 1.5f : values.back());
      shader->SetUniform1fv(channel.first, MaximumMaterials, values.data());
    }
  }
  std::vector<float> sheet(materialSheet);
  sheet.resize(MaximumMaterials, sheet.empty() ? 0.f : sheet.back());
  if (shader->IsUniformUsed("rfMaterialSheet"))
  {
    shader->SetUniform1fv("rfMaterialSheet", MaximumMaterials, sheet.data());
  }
  if (frame.Highlights && frame.Lights && shader->IsUniformUsed("rfMaterialHighlight"))
  {
    std::vector<float> highlights(*frame.Highlights);
    highlights.resize(4 * MaximumMaterials, 0.f);
    shader->SetUniform4fv("rfMaterialHighlight", MaximumMaterials, highlights.data());
    std::vector<float> positions(frame.Lights->GetPositions());
    std::vector<float> colours(frame.Lights->GetColours());
    positions.resize(4 * vtkRefractionLights::MaximumLights, 0.f);
    colours.resize(3 * vtkRefractionLights::MaximumLights, 0.f);
    shader->SetUniform4fv("rfLightPosition", vtkRefractionLights::MaximumLights, positions.data());
    shader->SetUniform3fv("rfLightColour", vtkRefractionLights::MaximumLights, colours.data());
  }
  shader->SetUniformf("rfSampleCeiling", frame.SampleCeiling);
  shader->SetUniformi("rfParallel", frame.Parallel ? 1 : 0);
  shader->SetUniformMatrix("rfVCDC", frame.Projection);
  shader->SetUniformMatrix("rfDCVC", frame.InverseProjection);
  shader->SetUniformMatrix3x3("rfViewToWorld", const_cast<float*>(frame.ViewToWorld));
  const float viewport[4] = { 0.f, 0.f, static_cast<float>(front->GetWidth()),
    static_cast<float>(front->GetHeight()) };
  shader->SetUniform4f("rfViewport", viewport);
  method->SetUniforms(shader, settings, frame.BoundsDepthRange);

  program->Quad->Render();

  if (useCube)
  {
    cube->PostRender(ren);
  }
  for (vtkTextureObject* texture : bound)
  {
    texture->Deactivate();
  }
}

//------------------------------------------------------------------------------
void vtkRefractionShadeStage::Render(vtkOpenGLRenderer* ren, vtkRefractionMethod* method,
  vtkRefractionPass* settings, vtkRefractionTargets* targets, const Frame& frame,
  const std::vector<float>& materialIOR, const std::vector<float>& materialSheet)
{
  vtkOpenGLRenderWindow* renWin = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  vtkOpenGLState* ostate = renWin->GetState();
  const bool corners = settings->GetAntiAliasing();
  vtkTextureObject* glassColour = targets->Get(vtkRefractionTargets::GLASS_COLOR);
  vtkTextureObject* frontDepth = targets->Get(vtkRefractionTargets::FRONT_DEPTH);
  vtkTextureObject* cornerDepth = targets->Get(vtkRefractionTargets::CORNER_Z);
  if (!glassColour || !frontDepth || (corners && !cornerDepth))
  {
    return;
  }
  // The scene captured behind the glass with all its mip levels while the shading reads it,
  // for lookups averaged over the rays' footprint (rfSceneLevel in rfShadeFS.glsl). The
  // magnification filter stays: a footprint within a texel reads the texel, as without them.
  vtkTextureObject* scene = frame.SceneRefraction && settings->GetFilteredLookups()
    ? targets->Get(vtkRefractionTargets::SCENE_COLOR)
    : nullptr;
  int sceneLevels = 0;
  for (unsigned int size = scene ? std::max(scene->GetWidth(), scene->GetHeight()) : 0; size > 1;
       size /= 2)
  {
    ++sceneLevels;
  }
  vtkRefractionTargets::ScopedMipmaps sceneMipmaps(targets,
    scene ? vtkRefractionTargets::SCENE_COLOR : -1, vtkTextureObject::LinearMipmapLinear,
    scene ? scene->GetMagnificationFilter() : 0, sceneLevels);
  // The refraction into the glass colour target, with a depth buffer attached that holds 1
  // where there is nothing to shade and the quad at the far plane: GL_GREATER passes only
  // where there is, and the test runs before the program (which writes no depth), so the
  // blocks without glass cost nothing. Pixels: the front capture's depth buffer. Corners
  // (anti-aliasing): a corner lies between four pixels and is shaded when any of them is
  // glass, so the corner depth buffer takes the nearest of the four first.
  // Smoothing the pixels reflected inside: the shading goes into GLASS_COLOR_SHADED, and the
  // smoothing draws the glass colour target from it (SmoothReflectedPixels).
  vtkTextureObject* shaded = frame.SmoothInternalReflections && !corners
    ? targets->Get(vtkRefractionTargets::GLASS_COLOR_SHADED)
    : nullptr;
  // Coarse shading: the blocks' rays first; then the pixels they stand for are written from
  // them, and TRACE_Z gets 0 at the glass pixels they do not stand for and 1 elsewhere, so
  // that the shading's test (GL_GREATER at the far plane) traces only those.
  vtkTextureObject* traceDepth =
    frame.CoarseShading ? targets->Get(vtkRefractionTargets::TRACE_Z) : nullptr;
  if (traceDepth &&
    !this->DrawCoarseSamples(ren, method, settings, targets, frame, materialIOR, materialSheet))
  {
    traceDepth = nullptr; // every pixel traces its own ray
  }
  {
    vtkTextureObject* depth = traceDepth ? traceDepth : corners ? cornerDepth : frontDepth;
    vtkRefractionTargetDraw draw(renWin, targets, { shaded ? shaded : glassColour }, depth);
    // Only where the glass can be: llvmpipe visits every 4x4 block a quad covers, glass or not.
    const int* r = frame.GlassRectangle;
    ostate->vtkglScissor(r[0], r[1], r[2], r[3]);
    ostate->vtkglEnable(GL_SCISSOR_TEST);
    ostate->vtkglDisable(GL_BLEND);
    ostate->vtkglEnable(GL_DEPTH_TEST);
    ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    if (frame.SampleComposite || shaded)
    {
      // The composite at the window's samples fills the silhouette from the glass colour's
      // mipmaps (vtkRefractionSampleComposite), and the smoothing of internal reflections
      // averages the glass around a pixel (rfReflectedFilter.glsl): texels without glass must
      // hold 0, not what an earlier frame left there. The whole target: a mipmap block reaches
      // past the rectangle, and the smoothing reads a texel beyond it.
      draw.ClearColours();
    }
    if (corners)
    {
      this->DrawCornerDepth(ren, frontDepth);
    }
    ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    ostate->vtkglDepthFunc(GL_GREATER);
    if (traceDepth)
    {
      ostate->vtkglDepthFunc(GL_ALWAYS);
      ostate->vtkglDepthMask(GL_TRUE);
      if (!this->ResolveCoarseSamples(ren, targets, frame))
      {
        // No resolve: depth 0 everywhere, so that every pixel traces its own ray.
        double clearDepth = 1.0;
        ostate->vtkglGetDoublev(GL_DEPTH_CLEAR_VALUE, &clearDepth);
        ostate->vtkglClearDepth(0.0);
        ostate->vtkglClear(GL_DEPTH_BUFFER_BIT);
        ostate->vtkglClearDepth(clearDepth);
      }
      ostate->vtkglDepthFunc(GL_GREATER);
    }
    ostate->vtkglDepthMask(GL_FALSE);
    this->Draw(
      ren, method, settings, targets, frame, materialIOR, materialSheet, PROGRAM_SHADE);
    if (shaded)
    {
      // Every glass pixel again, not only the traced ones.
      draw.Attach({ glassColour }, traceDepth ? frontDepth : depth);
      if (frame.SampleComposite)
      {
        draw.ClearColours();
      }
      this->SmoothReflectedPixels(ren, shaded);
    }
  }
  if (!frame.SampleComposite)
  {
    this->Composite(ren, targets, corners, frame.GlassRectangle);
  }
}

//------------------------------------------------------------------------------
bool vtkRefractionShadeStage::DrawCoarseSamples(vtkOpenGLRenderer* ren,
  vtkRefractionMethod* method, vtkRefractionPass* settings, vtkRefractionTargets* targets,
  const Frame& frame, const std::vector<float>& materialIOR,
  const std::vector<float>& materialSheet)
{
  vtkOpenGLRenderWindow* renWin = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  vtkOpenGLState* ostate = renWin->GetState();
  vtkTextureObject* colour = targets->Get(vtkRefractionTargets::COARSE_COLOR);
  vtkTextureObject* ray = targets->Get(vtkRefractionTargets::COARSE_RAY);
  vtkTextureObject* coarseDepth = targets->Get(vtkRefractionTargets::COARSE_Z);
  vtkTextureObject* frontDepth = targets->Get(vtkRefractionTargets::FRONT_DEPTH);
  vtkShaderProgram* depthProgram = this->ReadyCoarseQuad(renWin, this->CoarseDepthQuad,
    rfCoarseDepthFSSource, vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader());
  if (!colour || !ray || !coarseDepth || !frontDepth || !depthProgram ||
    !this->GetProgram(PROGRAM_COARSE_SAMPLES)->Quad)
  {
    return false;
  }
  const int width = static_cast<int>(colour->GetWidth());
  const int height = static_cast<int>(colour->GetHeight());
  {
    vtkRefractionTargetDraw draw(renWin, targets, { colour, ray }, coarseDepth);
    ostate->vtkglDisable(GL_BLEND);
    ostate->vtkglEnable(GL_DEPTH_TEST);
    // Every block's texel holds 0 (no glass) unless this frame traces it: the pixels read the
    // blocks around theirs, one beyond the glass's rectangle too.
    ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    draw.ClearColours();
    // The blocks of the glass's rectangle.
    const int* r = frame.GlassRectangle;
    const int x0 = r[0] / 2;
    const int y0 = r[1] / 2;
    ostate->vtkglScissor(x0, y0, (r[0] + r[2] + 1) / 2 - x0, (r[1] + r[3] + 1) / 2 - y0);
    ostate->vtkglEnable(GL_SCISSOR_TEST);
    // Their depth: the front's at each block's traced pixel.
    ostate->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    ostate->vtkglDepthFunc(GL_ALWAYS);
    ostate->vtkglDepthMask(GL_TRUE);
    frontDepth->Activate();
    depthProgram->SetUniformi("rfFrontDepth", frontDepth->GetTextureUnit());
    const float size[2] = { static_cast<float>(width), static_cast<float>(height) };
    depthProgram->SetUniform2f("rfSize", size);
    this->CoarseDepthQuad->Render();
    frontDepth->Deactivate();
    // Their rays, where that pixel is glass.
    ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    ostate->vtkglDepthFunc(GL_GREATER);
    ostate->vtkglDepthMask(GL_FALSE);
    this->Draw(ren, method, settings, targets, frame, materialIOR, materialSheet,
      PROGRAM_COARSE_SAMPLES);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkRefractionShadeStage::ResolveCoarseSamples(
  vtkOpenGLRenderer* ren, vtkRefractionTargets* targets, const Frame& frame)
{
  vtkOpenGLRenderWindow* renWin = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  const std::string defines = frame.AbsorptionDistance > 0.0 ? "#define RF_TINT\n" : "";
  if (this->CoarseResolveQuad && this->CoarseResolveDefines != defines)
  {
    this->CoarseResolveQuad->ReleaseGraphicsResources(renWin);
    this->CoarseResolveQuad.reset();
  }
  this->CoarseResolveDefines = defines;
  std::string source;
  if (!this->CoarseResolveQuad) // the source only when the program is made
  {
    source = rfCoarseResolveFSSource;
    vtkShaderProgram::Substitute(source, "in vec2 texCoord;", "in vec2 texCoord;\n" + defines);
  }
  vtkShaderProgram* program = this->ReadyCoarseQuad(renWin, this->CoarseResolveQuad, source,
    vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader());
  if (!program)
  {
    return false;
  }
  const std::vector<vtkTextureObject*> bound = BindTargets(program, targets);
  vtkTextureObject* front = targets->Get(vtkRefractionTargets::FRONT_SURFACE);
  const float size[2] = { static_cast<float>(front->GetWidth()),
    static_cast<float>(front->GetHeight()) };
  program->SetUniform2f("rfSize", size);
  this->CoarseResolveQuad->Render();
  for (vtkTextureObject* texture : bound)
  {
    texture->Deactivate();
  }
  return true;
}

//------------------------------------------------------------------------------
vtkShaderProgram* vtkRefractionShadeStage::ReadyCoarseQuad(vtkOpenGLRenderWindow* renWin,
  std::unique_ptr<vtkOpenGLQuadHelper>& quad, const std::string& fragmentSource,
  const std::string& vertexSource)
{
  vtkShaderProgram* program =
    vtkRefractionQuad::Ready(renWin, quad, vertexSource.c_str(), fragmentSource.c_str());
  if (!program)
  {
    vtkErrorMacro("Could not build a program of the coarse shading; the glass is traced at "
                  "every pixel.");
  }
  return program;
}

//------------------------------------------------------------------------------
void vtkRefractionShadeStage::SmoothReflectedPixels(
  vtkOpenGLRenderer* ren, vtkTextureObject* shaded)
{
  vtkOpenGLRenderWindow* renWin = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  std::string source;
  if (!this->SmoothQuad) // the source only when the program is made
  {
    source = rfSmoothReflectedFSSource;
    vtkShaderProgram::Substitute(source, "//RF::ReflectedFilter", rfReflectedFilterSource);
  }
  vtkShaderProgram* program = vtkRefractionQuad::Ready(
    renWin, this->SmoothQuad, GetFarPlaneQuadVertexShader().c_str(), source.c_str());
  if (!program)
  {
    vtkErrorMacro("Could not build the program smoothing internal reflections; the glass is "
                  "not drawn.");
    return;
  }
  shaded->Activate();
  program->SetUniformi("rfShadedColour", shaded->GetTextureUnit());
  const float size[2] = { static_cast<float>(shaded->GetWidth()),
    static_cast<float>(shaded->GetHeight()) };
  program->SetUniform2f("rfSize", size);
  this->SmoothQuad->Render();
  shaded->Deactivate();
}

//------------------------------------------------------------------------------
void vtkRefractionShadeStage::DrawCornerDepth(
  vtkOpenGLRenderer* ren, vtkTextureObject* frontDepth)
{
  vtkOpenGLRenderWindow* renWin = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  vtkOpenGLState* ostate = renWin->GetState();
  vtkShaderProgram* program = vtkRefractionQuad::Ready(renWin, this->CornerDepthQuad,
    vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), rfCornerDepthFSSource);
  if (!program)
  {
    // Nothing culled: the depth buffer of every corner at 0, so the shading test passes.
    vtkErrorMacro("Could not build the corner depth shader; every corner is shaded.");
    double clearDepth = 1.0;
    ostate->vtkglGetDoublev(GL_DEPTH_CLEAR_VALUE, &clearDepth);
    ostate->vtkglClearDepth(0.0);
    ostate->vtkglClear(GL_DEPTH_BUFFER_BIT);
    ostate->vtkglClearDepth(clearDepth);
    return;
  }
  frontDepth->Activate();
  program->SetUniformi("rfFrontDepth", frontDepth->GetTextureUnit());
  const float size[2] = { static_cast<float>(frontDepth->GetWidth()),
    static_cast<float>(frontDepth->GetHeight()) };
  program->SetUniform2f("rfSize", size);
  ostate->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  ostate->vtkglDepthFunc(GL_ALWAYS);
  ostate->vtkglDepthMask(GL_TRUE);
  this->CornerDepthQuad->Render();
  frontDepth->Deactivate();
}

//------------------------------------------------------------------------------
void vtkRefractionShadeStage::AddEnvironmentMipmaps(vtkOpenGLTexture* cube)
{
  vtkTextureObject* texture = cube->GetTextureObject();
  if (!texture || texture->GetTarget() != GL_TEXTURE_CUBE_MAP ||
    texture->GetMinificationFilter() != vtkTextureObject::Linear)
  {
    return; // already mipmapped, or nearest on purpose
  }

  // Its levels down to 1 x 1 (VTK leaves the texture's last level at 0, which also stops
  // glGenerateMipmap at the base level).
  int levels = 0;
  for (unsigned int side = texture->GetWidth(); side > 1; side /= 2)
  {
    ++levels;
  }
  texture->SetMaxLevel(levels);
  texture->SetMinificationFilter(vtkTextureObject::LinearMipmapLinear);
  texture->Activate(); // the unit cube->Render gave it: made active and bound again
  texture->SendParameters();
  glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
}

//------------------------------------------------------------------------------
void vtkRefractionShadeStage::Composite(vtkOpenGLRenderer* ren, vtkRefractionTargets* targets,
  bool corners, const int rectangle[4])
{
  vtkOpenGLRenderWindow* renWin = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  vtkOpenGLState* ostate = renWin->GetState();
  std::unique_ptr<vtkOpenGLQuadHelper>& quad =
    corners ? this->CornerCompositeQuad : this->CompositeQuad;
  std::string source;
  if (!quad) // the source only when the program is made
  {
    source = rfCompositeFSSource;
    if (corners)
    {
      vtkShaderProgram::Substitute(
        source, "in vec2 texCoord;", "in vec2 texCoord;\n#define RF_CORNER_SAMPLES\n");
    }
  }
  vtkShaderProgram* program = vtkRefractionQuad::Ready(renWin, quad,
    vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), source.c_str());
  if (!program)
  {
    vtkErrorMacro("Could not build the glass composite shader; the glass is not drawn.");
    return;
  }
  vtkTextureObject* textures[2] = { targets->Get(vtkRefractionTargets::FRONT_DEPTH),
    targets->Get(vtkRefractionTargets::GLASS_COLOR) };
  const char* names[2] = { "rfFrontDepth", "rfGlassColour" };
  for (int i = 0; i < 2; ++i)
  {
    textures[i]->Activate();
    program->SetUniformi(names[i], textures[i]->GetTextureUnit());
  }
  const float size[2] = { static_cast<float>(textures[1]->GetWidth()),
    static_cast<float>(textures[1]->GetHeight()) };
  program->SetUniform2f("rfSize", size);
  // The glass is opaque: its colour replaces the scene's (with anti-aliasing, blends over it
  // at the silhouette), its depth goes into the scene's depth buffer, and the depth test
  // keeps the glass behind opaque actors hidden.
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(ostate);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(ostate);
  vtkOpenGLState::ScopedglColorMask colorMaskSaver(ostate);
  vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(ostate);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
  vtkOpenGLState::ScopedglEnableDisable scissorTestSaver(ostate, GL_SCISSOR_TEST);
  // The glass's rectangle in the renderer's viewport, inside the scissor box VTK set (if on).
  int viewport[4];
  ostate->vtkglGetIntegerv(GL_VIEWPORT, viewport);
  int box[4] = { viewport[0] + rectangle[0], viewport[1] + rectangle[1], rectangle[2],
    rectangle[3] };
  if (ostate->GetEnumState(GL_SCISSOR_TEST))
  {
    int scissor[4];
    ostate->vtkglGetIntegerv(GL_SCISSOR_BOX, scissor);
    const int x0 = std::max(box[0], scissor[0]);
    const int y0 = std::max(box[1], scissor[1]);
    const int x1 = std::min(box[0] + box[2], scissor[0] + scissor[2]);
    const int y1 = std::min(box[1] + box[3], scissor[1] + scissor[3]);
    box[0] = x0;
    box[1] = y0;
    box[2] = std::max(x1 - x0, 0);
    box[3] = std::max(y1 - y0, 0);
  }
  ostate->vtkglScissor(box[0], box[1], box[2], box[3]);
  ostate->vtkglEnable(GL_SCISSOR_TEST);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_LEQUAL);
  ostate->vtkglDepthMask(GL_TRUE);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  if (corners)
  {
    // The share of the pixel's corners on the glass (alpha) over what is behind it.
    ostate->vtkglEnable(GL_BLEND);
    ostate->vtkglBlendFuncSeparate(
      GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  }
  else
  {
    ostate->vtkglDisable(GL_BLEND);
  }
  quad->Render();
  for (vtkTextureObject* texture : textures)
  {
    texture->Deactivate();
  }
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> vtkRefractionShadeStage::RenderDebug(vtkOpenGLRenderer* ren,
  vtkRefractionMethod* method, vtkRefractionPass* settings, vtkRefractionTargets* targets,
  const Frame& frame, const std::vector<float>& materialIOR, const std::vector<float>& materialSheet)
{
  vtkOpenGLRenderWindow* renWin = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  vtkOpenGLState* ostate = renWin->GetState();
  vtkTextureObject* first = targets->Get(vtkRefractionTargets::DEBUG_0);
  const int width = static_cast<int>(first->GetWidth());
  const int height = static_cast<int>(first->GetHeight());
  const vtkIdType count = static_cast<vtkIdType>(width) * height;
  std::vector<float> pixels[2];
  {
    vtkRefractionTargetDraw draw(
      renWin, targets, { first, targets->Get(vtkRefractionTargets::DEBUG_1) }, nullptr);
    ostate->vtkglScissor(0, 0, width, height);
    ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
    ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
    ostate->vtkglDisable(GL_BLEND);
    ostate->vtkglDisable(GL_DEPTH_TEST);
    this->Draw(
      ren, method, settings, targets, frame, materialIOR, materialSheet, PROGRAM_DEBUG);
    for (int i = 0; i < 2; ++i)
    {
      pixels[i].resize(4 * count);
      draw.GetFramebuffer()->ActivateReadBuffer(i);
      // Rows are whole floats: no row padding whatever GL_PACK_ALIGNMENT says.
      glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, pixels[i].data());
    }
  }

  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
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
  return image;
}

//------------------------------------------------------------------------------
void vtkRefractionShadeStage::ReleaseGraphicsResources(vtkWindow* w)
{
  for (std::unique_ptr<Program>* program : { &this->Shade, &this->Debug, &this->CoarseSamples })
  {
    if (*program && (*program)->Quad)
    {
      (*program)->Quad->ReleaseGraphicsResources(w);
    }
    program->reset();
  }
  for (std::unique_ptr<vtkOpenGLQuadHelper>* quad :
    { &this->CompositeQuad, &this->CornerCompositeQuad, &this->SmoothQuad,
      &this->CornerDepthQuad, &this->CoarseDepthQuad, &this->CoarseResolveQuad })
  {
    if (*quad)
    {
      (*quad)->ReleaseGraphicsResources(w);
    }
    quad->reset();
  }
}
