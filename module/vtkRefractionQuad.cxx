#include "vtkRefractionQuad.h"

#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"

//------------------------------------------------------------------------------
vtkShaderProgram* vtkRefractionQuad::Ready(vtkOpenGLRenderWindow* renWin,
  std::unique_ptr<vtkOpenGLQuadHelper>& quad, const char* vertexSource,
  const char* fragmentSource)
{
  if (!renWin)
  {
    return nullptr;
  }
  if (!quad)
  {
    quad = std::make_unique<vtkOpenGLQuadHelper>(renWin, vertexSource, fragmentSource, "");
  }
  else if (quad->Program)
  {
    renWin->GetShaderCache()->ReadyShaderProgram(quad->Program);
  }
  vtkShaderProgram* program = quad->Program;
  if (!program || !program->GetCompiled())
  {
    quad.reset();
    return nullptr;
  }
  return program;
}
