/**
 * @class   vtkRefractionLayerPack
 * @brief   PEEL: the depths of the peeled layers packed four to a texel.
 *
 * An image-space stage of vtkRefractionPass (shaders/rfLayerPackFS.glsl) run after the
 * peeling: it reads the depth of each of the K layers (the front G-buffer and PEEL_1 ..
 * PEEL_{K-1}) and writes them into PEEL_DEPTHS_A (layers 0-3) and PEEL_DEPTHS_B (4-7), so that
 * each step of PEEL's ray march reads one or two texels instead of K.
 */
#ifndef vtkRefractionLayerPack_h
#define vtkRefractionLayerPack_h

#include "vtkObject.h"

#include <memory> // For members

class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkRefractionTargets;
class vtkWindow;

class vtkRefractionLayerPack : public vtkObject
{
public:
  static vtkRefractionLayerPack* New();
  vtkTypeMacro(vtkRefractionLayerPack, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Packs the depths of `layers` layers (2..8), of which the first `found` were drawn this
  /// frame (the others are written empty, whatever their targets hold); false when the
  /// shader cannot be built.
  bool Pack(vtkOpenGLRenderWindow* renWin, vtkRefractionTargets* targets, int layers, int found);

  void ReleaseGraphicsResources(vtkWindow* w);

protected:
  vtkRefractionLayerPack();
  ~vtkRefractionLayerPack() override;

private:
  vtkRefractionLayerPack(const vtkRefractionLayerPack&) = delete;
  void operator=(const vtkRefractionLayerPack&) = delete;

  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  int QuadLayers = 0;
};

#endif
