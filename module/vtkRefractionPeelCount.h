/**
 * @class   vtkRefractionPeelCount
 * @brief   PEEL: whether a layer can follow the one just peeled, without drawing it.
 *
 * Peeling stops at the first layer that comes out empty, and learning that took a draw of
 * all the glass: on convex glass (a ball, a lens) the second layer behind the front is always
 * empty and was drawn only to find so. While a layer is peeled, this counts in the stencil of
 * the peeling's depth target (PEEL_Z, depth and stencil) the fragments the draw keeps at each
 * pixel (those behind the layer it peels: INCR on depth pass and on depth fail); the layer
 * after it can hold a surface only where two or more were kept. A full-screen quad under the
 * stencil test "at least two" inside an occlusion query (shaders/rfKeptTwiceFS.glsl) then
 * answers for the whole image. It errs only one way: fragments at one depth (coplanar
 * duplicates) count twice and cost the draw that finds the next layer empty, as before.
 */
#ifndef vtkRefractionPeelCount_h
#define vtkRefractionPeelCount_h

#include "vtkObject.h"

#include <memory> // For members

class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class vtkRefractionPeelCount : public vtkObject
{
public:
  static vtkRefractionPeelCount* New();
  vtkTypeMacro(vtkRefractionPeelCount, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// With the peeling's framebuffer bound and `depthStencil` (a depth-stencil texture)
  /// attached as its depth: attaches it as the stencil too, clears the stencil and counts
  /// every fragment that passes the fragment shader until Finish. False (and nothing changed)
  /// where the texture holds no stencil.
  bool Start(vtkOpenGLRenderWindow* renWin, vtkTextureObject* depthStencil);

  /// After the peeling's draw: the quad and its query, then the stencil detached and the
  /// stencil state set back. Returns whether any pixel kept two fragments or more (read at
  /// once, as the peeling's own query is: the next draw depends on it).
  bool Finish(vtkOpenGLRenderWindow* renWin);

  void ReleaseGraphicsResources(vtkWindow* w);

protected:
  vtkRefractionPeelCount();
  ~vtkRefractionPeelCount() override;

private:
  vtkRefractionPeelCount(const vtkRefractionPeelCount&) = delete;
  void operator=(const vtkRefractionPeelCount&) = delete;

  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  unsigned int Query = 0;
  bool Counting = false;
  bool StencilTestWas = false;
  int SavedFunc[3] = { 0, 0, 0 }; // func, ref, mask
  int SavedOp[3] = { 0, 0, 0 };   // sfail, dpfail, dppass
  int SavedWriteMask = 0;
};

#endif
