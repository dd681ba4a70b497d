#include "vtkRefractionLayerPack.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRefractionQuad.h"
#include "vtkRefractionTargetDraw.h"
#include "vtkRefractionTargets.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "rfShaders.h"
#include "vtk_glew.h"

#include <string>
#include <vector>

vtkStandardNewMacro(vtkRefractionLayerPack);

//------------------------------------------------------------------------------
vtkRefractionLayerPack::vtkRefractionLayerPack() = default;
vtkRefractionLayerPack::~vtkRefractionLayerPack() = default;

//------------------------------------------------------------------------------
void vtkRefractionLayerPack::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Packing shader: " << (this->Quad ? "built" : "not built") << " for "
     << this->QuadLayers << " layers\n";
}

//------------------------------------------------------------------------------
bool vtkRefractionLayerPack::Pack(
  vtkOpenGLRenderWindow* renWin, vtkRefractionTargets* targets, int layers, int found)
{
  if (layers < 2 || layers > 8)
  {
    return false;
  }
  if (this->Quad && this->QuadLayers != layers)
  {
    this->Quad->ReleaseGraphicsResources(renWin);
    this->Quad.reset();
  }
  std::string source;
  if (!this->Quad) // the source only when the program is made
  {
    source = rfLayerPackFSSource;
    vtkShaderProgram::Substitute(source, "in vec2 texCoord;",
      "in vec2 texCoord;\n#define RF_PEEL_LAYERS " + std::to_string(layers) + "\n");
  }
  this->QuadLayers = layers;
  vtkShaderProgram* program = vtkRefractionQuad::Ready(renWin, this->Quad,
    vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), source.c_str());
  if (!program)
  {
    vtkErrorMacro("Could not build the layer packing shader; the glass is not refracted.");
    return false;
  }
  program->SetUniformi("rfLayersFound", found);
  std::vector<vtkTextureObject*> sources;
  for (int layer = 0; layer < layers; ++layer)
  {
    vtkTextureObject* texture = targets->Get(
      layer == 0 ? vtkRefractionTargets::FRONT_SURFACE : vtkRefractionTargets::PEEL_1 + layer - 1);
    texture->Activate();
    program->SetUniformi(("rfLayer" + std::to_string(layer)).c_str(), texture->GetTextureUnit());
    sources.push_back(texture);
  }
  vtkOpenGLState* ostate = renWin->GetState();
  std::vector<vtkTextureObject*> packed{ targets->Get(vtkRefractionTargets::PEEL_DEPTHS_A) };
  if (layers > 4)
  {
    packed.push_back(targets->Get(vtkRefractionTargets::PEEL_DEPTHS_B));
  }
  {
    vtkRefractionTargetDraw draw(renWin, targets, packed, nullptr);
    ostate->vtkglScissor(0, 0, draw.GetWidth(), draw.GetHeight());
    ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    ostate->vtkglDisable(GL_BLEND);
    ostate->vtkglDisable(GL_DEPTH_TEST);
    this->Quad->Render();
  }
  for (vtkTextureObject* texture : sources)
  {
    texture->Deactivate();
  }
  return this->Stack(renWin, targets, found);
}

//------------------------------------------------------------------------------
bool vtkRefractionLayerPack::Stack(
  vtkOpenGLRenderWindow* renWin, vtkRefractionTargets* targets, int found)
{
  vtkShaderProgram* program = vtkRefractionQuad::Ready(renWin, this->StackQuad,
    vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), rfLayerStackFSSource);
  vtkTextureObject* stack = targets->Get(vtkRefractionTargets::PEEL_STACK);
  vtkTextureObject* front = targets->Get(vtkRefractionTargets::FRONT_SURFACE);
  const int width = front ? static_cast<int>(front->GetWidth()) : 0;
  const int height = front ? static_cast<int>(front->GetHeight()) : 0;
  // Layers side by side as the stack is wide (vtkRefractionTargets), as the shading reads it.
  const int columns = stack && width > 0 ? static_cast<int>(stack->GetWidth()) / width : 0;
  if (!program || columns < 1)
  {
    vtkErrorMacro("Could not build the layer stacking shader or its target; the glass is not "
                  "refracted.");
    return false;
  }
  vtkOpenGLState* ostate = renWin->GetState();
  vtkRefractionTargetDraw draw(renWin, targets, { stack }, nullptr);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  for (int layer = 0; layer < found; ++layer)
  {
    vtkTextureObject* texture = targets->Get(
      layer == 0 ? vtkRefractionTargets::FRONT_SURFACE : vtkRefractionTargets::PEEL_1 + layer - 1);
    const int x = (layer % columns) * width;
    const int y = (layer / columns) * height;
    ostate->vtkglViewport(x, y, width, height);
    ostate->vtkglScissor(x, y, width, height);
    texture->Activate();
    program->SetUniformi("rfLayer", texture->GetTextureUnit());
    this->StackQuad->Render();
    texture->Deactivate();
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkRefractionLayerPack::ReleaseGraphicsResources(vtkWindow* w)
{
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(w);
    this->Quad.reset();
  }
  this->QuadLayers = 0;
  if (this->StackQuad)
  {
    this->StackQuad->ReleaseGraphicsResources(w);
    this->StackQuad.reset();
  }
}
