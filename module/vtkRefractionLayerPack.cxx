#include "vtkRefractionLayerPack.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRefractionQuad.h"
#include "vtkRefractionShadeStage.h"
#include "vtkRefractionTargetDraw.h"
#include "vtkRefractionTargets.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "rfShaders.h"
#include "vtk_glew.h"

#include <algorithm>
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
  int built = 0;
  for (const std::unique_ptr<vtkOpenGLQuadHelper>& quad : this->Quads)
  {
    built += quad ? 1 : 0;
  }
  os << indent << "Packing shaders: " << built << " built (one per count of layers found) for "
     << this->QuadLayers << " layers\n";
  os << indent << "Layer reader (the stacking's blits): "
     << (this->LayerReader ? "made" : "not made") << "\n";
}

//------------------------------------------------------------------------------
bool vtkRefractionLayerPack::Pack(vtkOpenGLRenderWindow* renWin, vtkRefractionTargets* targets,
  int layers, int found, const int glassRectangle[4])
{
  if (layers < 2 || layers > 8)
  {
    return false;
  }
  found = std::max(1, std::min(found, layers)); // the front G-buffer is always there
  vtkTextureObject* stack = targets->Get(vtkRefractionTargets::PEEL_STACK);
  vtkTextureObject* front = targets->Get(vtkRefractionTargets::FRONT_SURFACE);
  const int width = front ? static_cast<int>(front->GetWidth()) : 0;
  const int height = front ? static_cast<int>(front->GetHeight()) : 0;
  // Layers side by side as the stack is wide (vtkRefractionTargets), as the shading reads it.
  const int columns = stack && width > 0 ? static_cast<int>(stack->GetWidth()) / width : 0;
  if (columns < 1)
  {
    vtkErrorMacro("PEEL's layer stack is not allocated; the glass is not refracted.");
    return false;
  }
  // Where each layer lies in the stack, for the blits and, as uniforms, for the packing: a
  // shader's integer division by the columns is a division per pixel on llvmpipe (its vectors
  // have none).
  int origins[16] = { 0 };
  for (int layer = 0; layer < found; ++layer)
  {
    origins[2 * layer] = (layer % columns) * width;
    origins[2 * layer + 1] = (layer / columns) * height;
  }
  // Stacked first: the depths are then read from the stack, a fetch per layer found, where a
  // sampler per layer read all K (llvmpipe runs every branch).
  this->Stack(renWin, targets, stack, width, height, found, origins);
  if (this->QuadLayers != layers)
  {
    this->ReleaseQuads(renWin);
    this->QuadLayers = layers;
  }
  // A program for each count found, its loop of constant bound: llvmpipe unrolls it and
  // fetches only the layers found. Bounded by min(the count found, K), the loop was unrolled K
  // times under a mask, each fetching (K = 8 with 2 found: 14 ms at 512 x 512 against 5).
  std::unique_ptr<vtkOpenGLQuadHelper>& quad = this->Quads[found - 1];
  std::string source;
  if (!quad) // the source only when the program is made
  {
    source = rfLayerPackFSSource;
    vtkShaderProgram::Substitute(source, "in vec2 texCoord;",
      "in vec2 texCoord;\n#define RF_PEEL_LAYERS " + std::to_string(layers) +
        "\n#define RF_PEEL_LAYERS_FOUND " + std::to_string(found) + "\n");
  }
  vtkShaderProgram* program = vtkRefractionQuad::Ready(renWin, quad,
    vtkRefractionShadeStage::GetFarPlaneQuadVertexShader().c_str(), source.c_str());
  if (!program)
  {
    vtkErrorMacro("Could not build the layer packing shader; the glass is not refracted.");
    return false;
  }
  stack->Activate();
  program->SetUniformi("rfStack", stack->GetTextureUnit());
  program->SetUniform1iv("rfLayerOrigins", 2 * found, origins);
  const int layerSize[2] = { width, height };
  program->SetUniform2i("rfLayerSize", layerSize);
  vtkOpenGLState* ostate = renWin->GetState();
  std::vector<vtkTextureObject*> packed{ targets->Get(vtkRefractionTargets::PEEL_DEPTHS_A) };
  if (layers > 4)
  {
    packed.push_back(targets->Get(vtkRefractionTargets::PEEL_DEPTHS_B));
  }
  {
    // Packed where the front capture holds glass only (every layer lies behind the front), as
    // the shading is: within the glass's rectangle, the quad at the far plane against the
    // front's depth (1 where no glass), GL_GREATER tested before the program, so llvmpipe
    // skips the blocks without glass, where it ran the fetches for every pixel of the window.
    // The rest is cleared to empty: the march reads texels outside the rectangle too.
    vtkRefractionTargetDraw draw(
      renWin, targets, packed, targets->Get(vtkRefractionTargets::FRONT_DEPTH));
    ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    draw.ClearColours();
    ostate->vtkglScissor(
      glassRectangle[0], glassRectangle[1], glassRectangle[2], glassRectangle[3]);
    ostate->vtkglEnable(GL_SCISSOR_TEST);
    ostate->vtkglDisable(GL_BLEND);
    ostate->vtkglEnable(GL_DEPTH_TEST);
    ostate->vtkglDepthFunc(GL_GREATER);
    ostate->vtkglDepthMask(GL_FALSE);
    quad->Render();
  }
  stack->Deactivate();
  return true;
}

//------------------------------------------------------------------------------
void vtkRefractionLayerPack::Stack(vtkOpenGLRenderWindow* renWin, vtkRefractionTargets* targets,
  vtkTextureObject* stack, int width, int height, int found, const int origins[16])
{
  if (!this->LayerReader)
  {
    this->LayerReader = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->LayerReader->SetContext(renWin);
  }
  vtkOpenGLState* ostate = renWin->GetState();
  vtkRefractionTargetDraw draw(renWin, targets, { stack }, nullptr);
  // Copied by blits, not drawn: llvmpipe copies the texels as memory (about 0.7 ms a layer at
  // 512 x 512, where a quad fetching them took 1.5). Each layer is read through a framebuffer
  // of its own: attached beside the stack in one framebuffer, it would shrink that framebuffer
  // to the layer's size, and the blit would clip every layer but the first away. The scissor
  // box clips blits too.
  ostate->vtkglDisable(GL_SCISSOR_TEST);
  this->LayerReader->SaveCurrentBindingsAndBuffers(GL_READ_FRAMEBUFFER);
  this->LayerReader->Bind(GL_READ_FRAMEBUFFER);
  for (int layer = 0; layer < found; ++layer)
  {
    vtkTextureObject* texture = targets->Get(
      layer == 0 ? vtkRefractionTargets::FRONT_SURFACE : vtkRefractionTargets::PEEL_1 + layer - 1);
    const int x = origins[2 * layer];
    const int y = origins[2 * layer + 1];
    this->LayerReader->AddColorAttachment(0, texture);
    this->LayerReader->ActivateReadBuffer(0);
    glBlitFramebuffer(
      0, 0, width, height, x, y, x + width, y + height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  this->LayerReader->RemoveColorAttachment(0);
  this->LayerReader->UnBind(GL_READ_FRAMEBUFFER);
  this->LayerReader->RestorePreviousBindingsAndBuffers(GL_READ_FRAMEBUFFER);
}

//------------------------------------------------------------------------------
void vtkRefractionLayerPack::ReleaseQuads(vtkWindow* w)
{
  for (std::unique_ptr<vtkOpenGLQuadHelper>& quad : this->Quads)
  {
    if (quad)
    {
      quad->ReleaseGraphicsResources(w);
      quad.reset();
    }
  }
  this->QuadLayers = 0;
}

//------------------------------------------------------------------------------
void vtkRefractionLayerPack::ReleaseGraphicsResources(vtkWindow* w)
{
  this->ReleaseQuads(w);
  if (this->LayerReader)
  {
    this->LayerReader->ReleaseGraphicsResources(w);
    this->LayerReader = nullptr;
  }
}
