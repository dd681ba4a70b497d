/**
 * @class   vtkRefractionDepthRange
 * @brief   DIR pass 2: the range [Zmin, Zmax] of the captured back depths.
 *
 * Either a min/max reduction on the GPU by full-screen passes over blocks of
 * vtkRefractionTargets::ReductionBlock texels a side (GLSL 1.50 has no compute shaders here)
 * into the targets' RG32F chain, down to 1x1 (R = min, G = max), or,
 * as the paper's section 5 suggests, the range of the glass props' bounding boxes on the CPU.
 * The same boxes bound the glass on screen (ComputeScreenRectangle): the full-screen stages
 * after the captures run only there.
 */
#ifndef vtkRefractionDepthRange_h
#define vtkRefractionDepthRange_h

#include "vtkObject.h"

#include <memory> // For members
#include <vector> // For ComputeBounds

class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkProp;
class vtkRefractionTargets;
class vtkRenderer;
class vtkShaderProgram;
class vtkWindow;

class vtkRefractionDepthRange : public vtkObject
{
public:
  static vtkRefractionDepthRange* New();
  vtkTypeMacro(vtkRefractionDepthRange, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Reduces the depths of BACK_SURFACE inside `rectangle` (x, y, width, height in its texels:
  /// where the glass can be, ComputeScreenRectangle; the back surface is empty elsewhere) into
  /// the targets' reduction chain. Each level is written and read only over the blocks that
  /// rectangle reaches. Returns false on a shader error.
  bool Reduce(vtkOpenGLRenderWindow* renWin, vtkRefractionTargets* targets, const int rectangle[4]);

  /// The depth range (positive distances) of the props' bounding boxes, clipped to the near
  /// plane (parts of a box behind it are never captured: the search starts there).
  static void ComputeBounds(vtkRenderer* ren, const std::vector<vtkProp*>& props, double range[2]);

  /// The pixels of a width x height viewport the props can cover: the rectangle (x, y, width,
  /// height) around their bounding boxes' projections, grown by margin pixels on each side.
  /// The whole viewport where that cannot be bounded: a box reaching behind the eye plane, a
  /// prop without finite bounds, no camera. The same camera matrices VTK's mappers draw with.
  static void ComputeScreenRectangle(vtkRenderer* ren, const std::vector<vtkProp*>& props,
    int width, int height, int margin, int rectangle[4]);

  void ReleaseGraphicsResources(vtkWindow* w);

protected:
  vtkRefractionDepthRange();
  ~vtkRefractionDepthRange() override;

private:
  // The program of the first pass or of the later ones, built on first use; nullptr when it
  // does not compile.
  vtkShaderProgram* ReadyProgram(
    vtkOpenGLRenderWindow* renWin, std::unique_ptr<vtkOpenGLQuadHelper>& quad, bool firstLevel);

  vtkRefractionDepthRange(const vtkRefractionDepthRange&) = delete;
  void operator=(const vtkRefractionDepthRange&) = delete;

  // The first pass (reads the back capture's depths) and the later ones (read min and max).
  std::unique_ptr<vtkOpenGLQuadHelper> FirstQuad;
  std::unique_ptr<vtkOpenGLQuadHelper> LaterQuad;
};

#endif
