#include "vtkRefractionDepthRange.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkProp.h"
#include "vtkRefractionTargets.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "rfShaders.h"
#include "vtk_glew.h"

#include <algorithm>

vtkStandardNewMacro(vtkRefractionDepthRange);

//------------------------------------------------------------------------------
vtkRefractionDepthRange::vtkRefractionDepthRange() = default;
vtkRefractionDepthRange::~vtkRefractionDepthRange() = default;

//------------------------------------------------------------------------------
void vtkRefractionDepthRange::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Reduction shader: " << (this->Quad ? "built" : "not built") << "\n";
}

//------------------------------------------------------------------------------
bool vtkRefractionDepthRange::Reduce(vtkOpenGLRenderWindow* renWin, vtkRefractionTargets* targets)
{
  vtkOpenGLState* ostate = renWin->GetState();
  if (!this->Quad)
  {
    this->Quad.reset(new vtkOpenGLQuadHelper(renWin,
      vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), rfReductionFSSource, ""));
  }
  else
  {
    renWin->GetShaderCache()->ReadyShaderProgram(this->Quad->Program);
  }
  vtkShaderProgram* program = this->Quad->Program;
  if (!program || !program->GetCompiled())
  {
    vtkErrorMacro("Could not build the depth-range reduction shader.");
    return false;
  }
  vtkOpenGLFramebufferObject* fbo = targets->GetFramebuffer();
  fbo->SaveCurrentBindingsAndBuffers();
  fbo->Bind();
  {
    vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
    vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
    vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable depthSaver(ostate, GL_DEPTH_TEST);
    ostate->vtkglDisable(GL_BLEND);
    ostate->vtkglDisable(GL_DEPTH_TEST);
    fbo->RemoveDepthAttachment();
    vtkTextureObject* source = targets->Get(vtkRefractionTargets::BACK_SURFACE);
    const auto& levels = targets->GetReductionLevels();
    for (size_t level = 0; level < levels.size(); ++level)
    {
      vtkTextureObject* target = levels[level];
      fbo->AddColorAttachment(0, target);
      fbo->ActivateDrawBuffers(1);
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
      this->Quad->Render();
      source->Deactivate();
      source = target;
    }
  }
  fbo->UnBind();
  fbo->RestorePreviousBindingsAndBuffers();
  return true;
}

//------------------------------------------------------------------------------
void vtkRefractionDepthRange::ComputeBounds(
  vtkRenderer* ren, const std::vector<vtkProp*>& props, double range[2])
{
  vtkCamera* camera = ren->GetActiveCamera();
  vtkMatrix4x4* view = camera->GetViewTransformMatrix();
  double nearest = VTK_DOUBLE_MAX;
  double furthest = 0.0;
  for (vtkProp* prop : props)
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
  range[0] = std::max(nearest, clipping[0]);
  range[1] = furthest;
}

//------------------------------------------------------------------------------
void vtkRefractionDepthRange::ReleaseGraphicsResources(vtkWindow* w)
{
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(w);
    this->Quad.reset();
  }
}
