#include "vtkRefractionSampleComposite.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLState.h"
#include "vtkRefractionGeometryStage.h"
#include "vtkRefractionQuad.h"
#include "vtkRefractionShadeStage.h"
#include "vtkRefractionTargetDraw.h"
#include "vtkRefractionTargets.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "rfShaders.h"
#include "vtk_glew.h"

#include <string>

vtkStandardNewMacro(vtkRefractionSampleComposite);

//------------------------------------------------------------------------------
vtkRefractionSampleComposite::vtkRefractionSampleComposite() = default;

//------------------------------------------------------------------------------
vtkRefractionSampleComposite::~vtkRefractionSampleComposite() = default;

//------------------------------------------------------------------------------
void vtkRefractionSampleComposite::ReleaseGraphicsResources(vtkWindow* w)
{
  if (this->FillQuad)
  {
    this->FillQuad->ReleaseGraphicsResources(w);
    this->FillQuad.reset();
  }
}

//------------------------------------------------------------------------------
int vtkRefractionSampleComposite::GetDrawFramebufferSamples()
{
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  return samples;
}

//------------------------------------------------------------------------------
bool vtkRefractionSampleComposite::IsSoftwareRasterizer()
{
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (!renderer)
  {
    return false;
  }
  const std::string name = renderer;
  return name.find("llvmpipe") != std::string::npos ||
    name.find("softpipe") != std::string::npos || name.find("SWR") != std::string::npos;
}

//------------------------------------------------------------------------------
void vtkRefractionSampleComposite::Render(vtkOpenGLRenderer* ren,
  vtkRefractionGeometryStage* geometry, vtkRefractionTargets* targets, bool corners,
  const int rectangle[4])
{
  vtkTextureObject* surface = targets->Get(vtkRefractionTargets::FRONT_SURFACE);
  vtkTextureObject* colour = targets->Get(vtkRefractionTargets::GLASS_COLOR);
  if (!surface || !colour)
  {
    return;
  }
  vtkOpenGLRenderWindow* renWin = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  vtkOpenGLState* ostate = renWin->GetState();
  // As an opaque actor is drawn: the scene's depth test per sample, the glass's depth written
  // per sample (what later passes and translucent actors test against), its colour replacing
  // the scene's.
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(ostate);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(ostate);
  vtkOpenGLState::ScopedglColorMask colorMaskSaver(ostate);
  vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(ostate, GL_DEPTH_TEST);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_LEQUAL);
  ostate->vtkglDepthMask(GL_TRUE);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  ostate->vtkglDisable(GL_BLEND);
  surface->Activate();
  {
    // The silhouette's fragments whose pixel centre is off the glass take the glass colour
    // around their pixel from mipmap levels 1 and 2 (rfGeometryFS.glsl, rfSampleComposite),
    // filtered; the shading stage cleared the texels without glass to 0. Only for this draw.
    // Without corners those texels are filled from the levels first, at those pixels only.
    vtkRefractionTargets::ScopedMipmaps levels(targets, vtkRefractionTargets::GLASS_COLOR,
      vtkTextureObject::LinearMipmapNearest, vtkTextureObject::Linear, 2);
    if (!corners)
    {
      this->FillSilhouette(renWin, targets, rectangle);
    }
    geometry->SetCompositeInputs(surface->GetTextureUnit(), colour->GetTextureUnit(), corners);
    geometry->DrawOnScreen(ren, vtkRefractionGeometryStage::STAGE_COMPOSITE);
  }
  surface->Deactivate();
}

//------------------------------------------------------------------------------
void vtkRefractionSampleComposite::FillSilhouette(
  vtkOpenGLRenderWindow* renWin, vtkRefractionTargets* targets, const int rectangle[4])
{
  vtkTextureObject* colour = targets->Get(vtkRefractionTargets::GLASS_COLOR);
  vtkTextureObject* frontDepth = targets->Get(vtkRefractionTargets::FRONT_DEPTH);
  if (!colour || !frontDepth)
  {
    return;
  }
  std::string fragmentShader;
  if (!this->FillQuad) // the source only when the program is made
  {
    fragmentShader = rfSilhouetteFillFSSource;
    vtkShaderProgram::Substitute(fragmentShader, "//RF::GlassAround", rfGlassAroundSource);
  }
  vtkShaderProgram* program = vtkRefractionQuad::Ready(renWin, this->FillQuad,
    vtkRefractionShadeStage::GetFarPlaneQuadVertexShader().c_str(), fragmentShader.c_str());
  if (!program)
  {
    vtkErrorMacro("Could not build the glass silhouette's fill; the glass's silhouette at the "
                  "window's samples covers only the pixels whose centre is glass.");
    return;
  }
  vtkOpenGLState* ostate = renWin->GetState();
  {
    vtkRefractionTargetDraw draw(renWin, targets, { colour }, frontDepth);
    ostate->vtkglScissor(rectangle[0], rectangle[1], rectangle[2], rectangle[3]);
    ostate->vtkglEnable(GL_SCISSOR_TEST);
    ostate->vtkglDisable(GL_BLEND);
    ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    // The pixels without glass only (the quad at the far plane against depth 1), and llvmpipe
    // skips the blocks inside the glass before the program runs.
    ostate->vtkglEnable(GL_DEPTH_TEST);
    ostate->vtkglDepthFunc(GL_LEQUAL);
    ostate->vtkglDepthMask(GL_FALSE);
    // Level 0 is written: the draw reads levels 1 and 2 only, as lod 0 and 1 from base level
    // 1, so that the level written is not one the program can read.
    colour->SetBaseLevel(1);
    colour->Activate();
    program->SetUniformi("rfGlassColour", colour->GetTextureUnit());
    const float size[2] = { static_cast<float>(colour->GetWidth()),
      static_cast<float>(colour->GetHeight()) };
    program->SetUniform2f("rfSize", size);
    this->FillQuad->Render();
    colour->SetBaseLevel(0);
    colour->Activate(); // sends the base level again; left active for the composite's draw
  }
}
