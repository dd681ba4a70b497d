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
 * output, which Render makes for the draw), and
 * the window's resolve blends the silhouette as it blends VTK's own edges. In a
 * single-sampled framebuffer the full-screen composite is used (the same picture, cheaper).
 */
#ifndef vtkRefractionSampleComposite_h
#define vtkRefractionSampleComposite_h

#include "vtkObject.h"

class vtkOpenGLRenderer;
class vtkRefractionGeometryStage;
class vtkRefractionTargets;

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
  void Render(vtkOpenGLRenderer* ren, vtkRefractionGeometryStage* geometry,
    vtkRefractionTargets* targets, bool corners);

protected:
  vtkRefractionSampleComposite() = default;
  ~vtkRefractionSampleComposite() override = default;

private:
  vtkRefractionSampleComposite(const vtkRefractionSampleComposite&) = delete;
  void operator=(const vtkRefractionSampleComposite&) = delete;
};

#endif
