#include "vtkRefractionSampleComposite.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLState.h"
#include "vtkRefractionGeometryStage.h"
#include "vtkRefractionTargets.h"
#include "vtkTextureObject.h"

#include "vtk_glew.h"

#include <string>

vtkStandardNewMacro(vtkRefractionSampleComposite);

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
  vtkRefractionGeometryStage* geometry, vtkRefractionTargets* targets, bool corners)
{
  vtkTextureObject* surface = targets->Get(vtkRefractionTargets::FRONT_SURFACE);
  vtkTextureObject* colour = targets->Get(vtkRefractionTargets::GLASS_COLOR);
  if (!surface || !colour)
  {
    return;
  }
  vtkOpenGLState* ostate = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow())->GetState();
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
    vtkRefractionTargets::ScopedMipmaps levels(targets, vtkRefractionTargets::GLASS_COLOR,
      vtkTextureObject::LinearMipmapNearest, vtkTextureObject::Linear, 2);
    geometry->SetCompositeInputs(surface->GetTextureUnit(), colour->GetTextureUnit(), corners);
    geometry->DrawOnScreen(ren, vtkRefractionGeometryStage::STAGE_COMPOSITE);
  }
  surface->Deactivate();
}
