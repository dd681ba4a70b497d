/**
 * @class   vtkRefractionLayerPack
 * @brief   PEEL: the peeled layers laid out for the shading's reads.
 *
 * An image-space stage of vtkRefractionPass run after the peeling. It copies each layer found
 * (the front G-buffer and PEEL_1 .. PEEL_{K-1}) into its place in PEEL_STACK (a blit per
 * layer), so that the shading reads a layer's whole texel (normal, depth, material) in one
 * fetch: through a sampler per layer, llvmpipe (and a GPU's warp whose pixels want different
 * layers) fetched every layer's. It then reads the depth of each layer from the stack and
 * writes them into PEEL_DEPTHS_A (layers 0-3) and PEEL_DEPTHS_B (4-7)
 * (shaders/rfLayerPackFS.glsl), so that each step of PEEL's ray march reads one or two texels
 * instead of K.
 */
#ifndef vtkRefractionLayerPack_h
#define vtkRefractionLayerPack_h

#include "vtkObject.h"
#include "vtkSmartPointer.h" // For members

#include <array>  // For members
#include <memory> // For members

class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkRefractionTargets;
class vtkTextureObject;
class vtkWindow;

class vtkRefractionLayerPack : public vtkObject
{
public:
  static vtkRefractionLayerPack* New();
  vtkTypeMacro(vtkRefractionLayerPack, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Packs the depths of `layers` layers (2..8), of which the first `found` were drawn this
  /// frame (the others are written empty, whatever their targets hold), and stacks the layers
  /// found; false when a shader cannot be built. glassRectangle (x, y, width, height) bounds
  /// the glass on screen: outside it every depth is written empty.
  bool Pack(vtkOpenGLRenderWindow* renWin, vtkRefractionTargets* targets, int layers, int found,
    const int glassRectangle[4]);

  void ReleaseGraphicsResources(vtkWindow* w);

protected:
  vtkRefractionLayerPack();
  ~vtkRefractionLayerPack() override;

private:
  vtkRefractionLayerPack(const vtkRefractionLayerPack&) = delete;
  void operator=(const vtkRefractionLayerPack&) = delete;

  // Copies the layers found (each width x height) into `stack`, layer k at origins[2k],
  // [2k + 1].
  void Stack(vtkOpenGLRenderWindow* renWin, vtkRefractionTargets* targets,
    vtkTextureObject* stack, int width, int height, int found, const int origins[16]);

  void ReleaseQuads(vtkWindow* w);

  // The packing's programs by the count of layers found (1..8), for QuadLayers layers.
  std::array<std::unique_ptr<vtkOpenGLQuadHelper>, 8> Quads;
  int QuadLayers = 0;
  vtkSmartPointer<vtkOpenGLFramebufferObject> LayerReader; // the stacking's read framebuffer
};

#endif
