/**
 * @class   vtkRefractionTargetDraw
 * @brief   A scope whose draws go into vtkRefractionTargets' textures.
 *
 * Every off-screen stage of the pass draws the same way: the framebuffer's bindings saved,
 * the targets' framebuffer bound with the stage's textures attached, the viewport at their
 * size, and the state the stage changes set back afterwards. This scope does all of it:
 * when it begins it saves the bindings and the state below and binds; Attach changes the
 * textures inside it; when it ends it detaches what it attached beyond colour attachment 0
 * (and the depth), and sets the bindings and the state back.
 *
 * The state saved: viewport, scissor box, clear colour, depth function, depth mask, colour
 * mask, and the blend, depth and scissor tests (VTK's cached vtkOpenGLState, so saving costs
 * no GL call and setting back only the calls for what changed).
 */
#ifndef vtkRefractionTargetDraw_h
#define vtkRefractionTargetDraw_h

#include "vtkOpenGLState.h" // For members

#include <vector> // For Attach

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkRefractionTargets;
class vtkTextureObject;

class vtkRefractionTargetDraw
{
public:
  /// Binds the framebuffer with these textures attached (Attach).
  vtkRefractionTargetDraw(vtkOpenGLRenderWindow* renWin, vtkRefractionTargets* targets,
    const std::vector<vtkTextureObject*>& colours, vtkTextureObject* depth);
  ~vtkRefractionTargetDraw();
  vtkRefractionTargetDraw(const vtkRefractionTargetDraw&) = delete;
  vtkRefractionTargetDraw& operator=(const vtkRefractionTargetDraw&) = delete;

  /// Draw into `colours` (draw buffers 0 .. n - 1; the others attached before are detached)
  /// with `depth` as the depth attachment (nullptr: none), and set the viewport to the first
  /// colour's size (the depth's without colours).
  void Attach(const std::vector<vtkTextureObject*>& colours, vtkTextureObject* depth);

  /// Clear the colours attached now to 0 over their whole size, whatever the scissor box:
  /// stages that draw within the glass's rectangle and read past it (mipmaps, filters, the
  /// layers' march) need 0 there, not what an earlier frame left. The scissor test and the
  /// clear colour are as they were after.
  void ClearColours();

  vtkOpenGLFramebufferObject* GetFramebuffer() const { return this->Framebuffer; }
  /// The viewport's size that the last Attach set.
  int GetWidth() const { return this->Width; }
  int GetHeight() const { return this->Height; }

private:
  vtkOpenGLState* State;
  vtkOpenGLFramebufferObject* Framebuffer;
  unsigned int Colours = 0;
  int Width = 0;
  int Height = 0;
  vtkOpenGLState::ScopedglViewport Viewport;
  vtkOpenGLState::ScopedglScissor Scissor;
  vtkOpenGLState::ScopedglClearColor ClearColour;
  vtkOpenGLState::ScopedglDepthFunc DepthFunc;
  vtkOpenGLState::ScopedglDepthMask DepthMask;
  vtkOpenGLState::ScopedglColorMask ColourMask;
  vtkOpenGLState::ScopedglEnableDisable Blend;
  vtkOpenGLState::ScopedglEnableDisable DepthTest;
  vtkOpenGLState::ScopedglEnableDisable ScissorTest;
};

#endif
