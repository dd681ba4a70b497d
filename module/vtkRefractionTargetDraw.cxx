#include "vtkRefractionTargetDraw.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRefractionTargets.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

//------------------------------------------------------------------------------
vtkRefractionTargetDraw::vtkRefractionTargetDraw(vtkOpenGLRenderWindow* renWin,
  vtkRefractionTargets* targets, const std::vector<vtkTextureObject*>& colours,
  vtkTextureObject* depth)
  : State(renWin->GetState())
  , Framebuffer(targets->GetFramebuffer())
  , Viewport(renWin->GetState())
  , Scissor(renWin->GetState())
  , ClearColour(renWin->GetState())
  , DepthFunc(renWin->GetState())
  , DepthMask(renWin->GetState())
  , ColourMask(renWin->GetState())
  , Blend(renWin->GetState(), GL_BLEND)
  , DepthTest(renWin->GetState(), GL_DEPTH_TEST)
  , ScissorTest(renWin->GetState(), GL_SCISSOR_TEST)
{
  this->Framebuffer->SaveCurrentBindingsAndBuffers();
  this->Framebuffer->Bind();
  this->Attach(colours, depth);
}

//------------------------------------------------------------------------------
vtkRefractionTargetDraw::~vtkRefractionTargetDraw()
{
  // Attachment 0 stays: the next draw replaces it. The others would be drawn into by a draw
  // that activates more buffers than it attached.
  for (unsigned int i = this->Colours; i > 1; --i)
  {
    this->Framebuffer->RemoveColorAttachment(i - 1);
  }
  if (this->Framebuffer->GetDepthAttachmentAsTextureObject())
  {
    this->Framebuffer->RemoveDepthAttachment();
  }
  this->Framebuffer->UnBind();
  this->Framebuffer->RestorePreviousBindingsAndBuffers();
  // The saved state is set back by the members' destructors.
}

//------------------------------------------------------------------------------
void vtkRefractionTargetDraw::Attach(
  const std::vector<vtkTextureObject*>& colours, vtkTextureObject* depth)
{
  const unsigned int count = static_cast<unsigned int>(colours.size());
  for (unsigned int i = 0; i < count; ++i)
  {
    this->Framebuffer->AddColorAttachment(i, colours[i]);
  }
  for (unsigned int i = this->Colours; i > count && i > 1; --i)
  {
    this->Framebuffer->RemoveColorAttachment(i - 1);
  }
  this->Colours = count;
  if (depth)
  {
    this->Framebuffer->AddDepthAttachment(depth);
  }
  else if (this->Framebuffer->GetDepthAttachmentAsTextureObject())
  {
    this->Framebuffer->RemoveDepthAttachment();
  }
  if (count > 0)
  {
    this->Framebuffer->ActivateDrawBuffers(count);
  }
  vtkTextureObject* sized = count > 0 ? colours.front() : depth;
  if (sized)
  {
    this->Width = static_cast<int>(sized->GetWidth());
    this->Height = static_cast<int>(sized->GetHeight());
    this->State->vtkglViewport(0, 0, this->Width, this->Height);
  }
}

//------------------------------------------------------------------------------
void vtkRefractionTargetDraw::ClearColours()
{
  vtkOpenGLState::ScopedglClearColor clearColour(this->State);
  vtkOpenGLState::ScopedglEnableDisable scissorTest(this->State, GL_SCISSOR_TEST);
  this->State->vtkglDisable(GL_SCISSOR_TEST);
  this->State->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
  this->State->vtkglClear(GL_COLOR_BUFFER_BIT);
}
