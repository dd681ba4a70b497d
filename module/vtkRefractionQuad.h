/**
 * @class   vtkRefractionQuad
 * @brief   An image-space stage's program on a vtkOpenGLQuadHelper, made ready to draw.
 *
 * The pass's image-space stages (packing PEEL's layers and counting them, the composites, the
 * smoothing of internal reflections, the corner depth, the coarse shading, the depth range)
 * keep their programs on vtkOpenGLQuadHelpers that they build on first use and make current
 * on every later one (the shading keeps its own, by its defines: vtkRefractionShadeStage).
 * Ready does both, and drops a quad whose program did not compile, so that the next frame
 * builds it again (rather than asking VTK's shader cache to make a program current that is
 * not there). What a stage leaves undone when its program is missing differs, so the stage
 * reports it.
 */
#ifndef vtkRefractionQuad_h
#define vtkRefractionQuad_h

#include <memory> // For std::unique_ptr

class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;

class vtkRefractionQuad
{
public:
  /// The quad's program, current: built from the two sources where `quad` is empty (VTK's
  /// shader cache hands back a program built before from the same sources), else the one it
  /// holds. nullptr where it does not compile; `quad` is then emptied.
  static vtkShaderProgram* Ready(vtkOpenGLRenderWindow* renWin,
    std::unique_ptr<vtkOpenGLQuadHelper>& quad, const char* vertexSource,
    const char* fragmentSource);

  vtkRefractionQuad() = delete;
};

#endif
