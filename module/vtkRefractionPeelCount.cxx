#include "vtkRefractionPeelCount.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRefractionQuad.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "rfShaders.h"
#include "vtk_glew.h"

vtkStandardNewMacro(vtkRefractionPeelCount);

//------------------------------------------------------------------------------
vtkRefractionPeelCount::vtkRefractionPeelCount() = default;
vtkRefractionPeelCount::~vtkRefractionPeelCount() = default;

//------------------------------------------------------------------------------
void vtkRefractionPeelCount::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Quad: " << (this->Quad ? "built" : "not built") << "\n";
  os << indent << "Counting: " << this->Counting << "\n";
}

//------------------------------------------------------------------------------
bool vtkRefractionPeelCount::Start(vtkOpenGLRenderWindow* renWin, vtkTextureObject* depthStencil)
{
  this->Counting = false;
  if (!renWin || !depthStencil || depthStencil->GetHandle() == 0)
  {
    return false;
  }
  glFramebufferTexture2D(
    GL_DRAW_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_TEXTURE_2D, depthStencil->GetHandle(), 0);
  if (glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
  {
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_TEXTURE_2D, 0, 0);
    return false;
  }
  // The state VTK's own passes may have left, set back by Finish (vtkOpenGLState keeps no
  // scoped stencil state in VTK 9.1).
  vtkOpenGLState* ostate = renWin->GetState();
  this->StencilTestWas = glIsEnabled(GL_STENCIL_TEST) == GL_TRUE;
  glGetIntegerv(GL_STENCIL_FUNC, &this->SavedFunc[0]);
  glGetIntegerv(GL_STENCIL_REF, &this->SavedFunc[1]);
  glGetIntegerv(GL_STENCIL_VALUE_MASK, &this->SavedFunc[2]);
  glGetIntegerv(GL_STENCIL_FAIL, &this->SavedOp[0]);
  glGetIntegerv(GL_STENCIL_PASS_DEPTH_FAIL, &this->SavedOp[1]);
  glGetIntegerv(GL_STENCIL_PASS_DEPTH_PASS, &this->SavedOp[2]);
  glGetIntegerv(GL_STENCIL_WRITEMASK, &this->SavedWriteMask);
  ostate->vtkglStencilMask(0xFF);
  glClearStencil(0);
  ostate->vtkglClear(GL_STENCIL_BUFFER_BIT);
  ostate->vtkglEnable(GL_STENCIL_TEST);
  ostate->vtkglStencilFunc(GL_ALWAYS, 0, 0xFF);
  // Every fragment the peeling's shader keeps, nearer than the pixel's nearest so far or not.
  ostate->vtkglStencilOp(GL_KEEP, GL_INCR, GL_INCR);
  this->Counting = true;
  return true;
}

//------------------------------------------------------------------------------
bool vtkRefractionPeelCount::Finish(vtkOpenGLRenderWindow* renWin)
{
  if (!this->Counting)
  {
    return true; // not counted: a layer may follow
  }
  this->Counting = false;
  vtkOpenGLState* ostate = renWin->GetState();
  GLuint anyTwice = 1;
  const bool built = vtkRefractionQuad::Ready(renWin, this->Quad,
                       vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(),
                       rfKeptTwiceFSSource) != nullptr;
  if (built)
  {
    if (this->Query == 0)
    {
      glGenQueries(1, &this->Query);
    }
    // Passes where 2 <= the count. The caller's draw scope sets the masks and tests back.
    ostate->vtkglStencilFunc(GL_LEQUAL, 2, 0xFF);
    ostate->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    ostate->vtkglStencilMask(0x00);
    ostate->vtkglDisable(GL_DEPTH_TEST);
    ostate->vtkglDepthMask(GL_FALSE);
    ostate->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glBeginQuery(GL_ANY_SAMPLES_PASSED, this->Query);
    this->Quad->Render();
    glEndQuery(GL_ANY_SAMPLES_PASSED);
  }
  else
  {
    vtkErrorMacro("Could not build PEEL's layer count shader; every layer is peeled.");
  }
  ostate->vtkglStencilFunc(this->SavedFunc[0], this->SavedFunc[1],
    static_cast<unsigned int>(this->SavedFunc[2]));
  ostate->vtkglStencilOp(this->SavedOp[0], this->SavedOp[1], this->SavedOp[2]);
  ostate->vtkglStencilMask(static_cast<unsigned int>(this->SavedWriteMask));
  if (!this->StencilTestWas)
  {
    ostate->vtkglDisable(GL_STENCIL_TEST);
  }
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_TEXTURE_2D, 0, 0);
  if (built)
  {
    glGetQueryObjectuiv(this->Query, GL_QUERY_RESULT, &anyTwice);
  }
  return anyTwice != 0;
}

//------------------------------------------------------------------------------
void vtkRefractionPeelCount::ReleaseGraphicsResources(vtkWindow* w)
{
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(w);
    this->Quad.reset();
  }
  if (this->Query != 0 && w)
  {
    glDeleteQueries(1, &this->Query);
  }
  this->Query = 0;
  this->Counting = false;
}
