/**
 * @class   vtkRefractionSampleComposite
 * @brief   Puts the shaded glass into a multisampled framebuffer at the window's samples.
 *
 * The shading stage shades the glass once per pixel (or per pixel corner) from single-sampled
 * G-buffers; the full-screen composite (shaders/rfCompositeFS.glsl) then covers whole pixels,
 * so in a multisampled window (VTK's default) the glass's silhouette is stair-stepped while
 * every opaque actor beside it is resolved from the window's samples. Here the glass's front
 * surface is drawn again through VTK's mappers (vtkRefractionGeometryStage, STAGE_COMPOSITE)
 * into the framebuffer bound now, with the depth test of an opaque actor: the rasterizer
 * covers exactly the samples it covers for an opaque actor of the same mesh, each fragment
 * takes the colour the shading stage gave its pixel (at the silhouette, where its pixel's centre
 * is off the glass, the glass colour around the pixel from two mipmap levels of the shading's
 * output, which Render makes for the draw and, without corners, fills into the texels off
 * the glass first: shaders/rfSilhouetteFillFS.glsl), and
 * the window's resolve blends the silhouette as it blends VTK's own edges. In a
 * single-sampled framebuffer the full-screen composite is used (the same picture, cheaper).
 */
#ifndef vtkRefractionSampleComposite_h
#define vtkRefractionSampleComposite_h

#include "vtkObject.h"

#include <memory> // For std::unique_ptr

class vtkOpenGLQuadHelper;
class vtkOpenGLRenderer;
class vtkOpenGLRenderWindow;
class vtkRefractionGeometryStage;
class vtkRefractionTargets;
class vtkWindow;

class vtkRefractionSampleComposite : public vtkObject
{
public:
  static vtkRefractionSampleComposite* New();
  vtkTypeMacro(vtkRefractionSampleComposite, vtkObject);

  /// Samples per pixel of the framebuffer bound for drawing now (0 or 1: single-sampled).
  static int GetDrawFramebufferSamples();

  /// Whether the current context renders on the CPU (GL_RENDERER names llvmpipe, softpipe or
  /// SWR): such rasterizers run both sides of every branch in every fragment.
  static bool IsSoftwareRasterizer();

  /// The glass (GLASS_COLOR, shaded; at the pixels' corners when `corners`) into the
  /// framebuffer bound now, drawn by `geometry` with the glass props it was configured with.
  /// `rectangle` (x, y, width, height in the targets' pixels) holds every pixel the glass
  /// touches.
  void Render(vtkOpenGLRenderer* ren, vtkRefractionGeometryStage* geometry,
    vtkRefractionTargets* targets, bool corners, const int rectangle[4]);

  void ReleaseGraphicsResources(vtkWindow* w);

protected:
  vtkRefractionSampleComposite();
  ~vtkRefractionSampleComposite() override;

private:
  /// GLASS_COLOR's texels off the glass inside `rectangle` get the glass colour around them
  /// (its mipmap levels 1 and 2, made already). Where its program cannot be built, an error
  /// says so and the texels stay 0: the silhouette is then the pixel-by-pixel one.
  void FillSilhouette(
    vtkOpenGLRenderWindow* renWin, vtkRefractionTargets* targets, const int rectangle[4]);

  std::unique_ptr<vtkOpenGLQuadHelper> FillQuad;

  vtkRefractionSampleComposite(const vtkRefractionSampleComposite&) = delete;
  void operator=(const vtkRefractionSampleComposite&) = delete;
};

#endif
