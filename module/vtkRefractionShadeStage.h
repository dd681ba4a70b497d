/**
 * @class   vtkRefractionShadeStage
 * @brief   The refraction, once per pixel of the glass: a full-screen stage.
 *
 * Builds shaders/rfShadeFS.glsl with the method's defines and GLSL, binds the render targets
 * the method reads (by sampler name), the environment and the camera, and draws a full-screen
 * quad (vtkOpenGLQuadHelper) into the glass colour target, culled by the front capture's depth
 * buffer to the pixels of the glass; a composite quad (shaders/rfCompositeFS.glsl) then puts
 * that colour and the glass's depth into the framebuffer bound before. With anti-aliasing the
 * pixels' corners are shaded instead and the composite averages each pixel's four. For the
 * debug output it writes P2/T2/thickness/flags into two float targets read back as a
 * vtkImageData. GL state goes through vtkOpenGLState and is restored afterwards.
 */
#ifndef vtkRefractionShadeStage_h
#define vtkRefractionShadeStage_h

#include "vtkObject.h"
#include "vtkSmartPointer.h" // For members

#include <memory> // For members
#include <string> // For members
#include <vector> // For SetMaterials

class vtkImageData;
class vtkMatrix4x4;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkOpenGLRenderer;
class vtkOpenGLState;
class vtkOpenGLTexture;
class vtkRefractionLights;
class vtkRefractionMethod;
class vtkRefractionPass;
class vtkRefractionTargets;
class vtkShaderProgram;
class vtkTexture;
class vtkTextureObject;
class vtkWindow;

class vtkRefractionShadeStage : public vtkObject
{
public:
  static vtkRefractionShadeStage* New();
  vtkTypeMacro(vtkRefractionShadeStage, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The most glass materials (props) one frame distinguishes; the rest share the last.
  static constexpr int MaximumMaterials = 64;

  /// VTK's full-screen quad at the far plane (window depth 1): against the front capture's
  /// depth buffer (cleared to 1) GL_GREATER passes exactly where the glass is, GL_LEQUAL
  /// exactly where it is not.
  static std::string GetFarPlaneQuadVertexShader();

  /// The camera and environment of this frame (GL layouts, as vtkRefractionPass computes them).
  struct Frame
  {
    vtkMatrix4x4* Projection = nullptr;
    vtkMatrix4x4* InverseProjection = nullptr;
    const float* ViewToWorld = nullptr;       // 3x3
    const float* EnvironmentMatrix = nullptr; // 3x3
    bool Parallel = false;
    vtkTexture* EnvironmentCube = nullptr;    // the renderer's cube map, or nullptr
    bool EnvironmentBackground = false;       // the renderer's background (no cube map)
    bool SceneRefraction = false;             // the captured scene is followed
    bool SampleComposite = false;             // the caller composites (at the samples)
    // Pixels near one whose ray was totally reflected inside show their neighbourhood's glass
    // (vtkRefractionPass::SetSmoothInternalReflections; not with anti-aliasing's corners).
    bool SmoothInternalReflections = false;
    // One ray per 2x2 block where the glass is smooth (vtkRefractionPass::SetCoarseShading; not
    // with anti-aliasing's corners): the blocks' rays into the coarse targets first, then each
    // pixel interpolates them or traces its own.
    bool CoarseShading = false;
    double AbsorptionDistance = 0.0;          // > 0: the data's colour tints the glass
    const std::vector<float>* RedIndex = nullptr;  // dispersion: red indices per material
    const std::vector<float>* BlueIndex = nullptr; // and blue ones (nullptr: no dispersion)
    double GlassDiagonal = 0.0;               // the largest glass prop's bounding-box diagonal
    double GlassExtent = 0.0;                 // the diagonal of all the glass's bounds
    double Background[3] = { 0.0, 0.0, 0.0 };
    double Background2[3] = { 0.0, 0.0, 0.0 }; // = Background when it is not a gradient
    const double* BoundsDepthRange = nullptr;
    const std::vector<float>* Highlights = nullptr; // 4 per material (nullptr: none)
    const vtkRefractionLights* Lights = nullptr;     // the renderer's, in view space
    // The pixels the glass can cover (x, y, width, height in the targets): the shading and the
    // full-screen composite run only there (vtkRefractionDepthRange::ComputeScreenRectangle).
    int GlassRectangle[4] = { 0, 0, 0, 0 };
    // The brightest colour a shaded sample keeps before samples are averaged: 1 where the
    // framebuffer the glass goes into holds display values (fixed point), none (FLT_MAX) where
    // it holds radiance (a float target: tone mapping follows).
    float SampleCeiling = 1.f;
  };

  /// The shading program for the method and the pass's settings (with coarse shading, also
  /// the program of the blocks' rays); false when it does not build.
  bool Prepare(vtkOpenGLRenderer* ren, vtkRefractionMethod* method, vtkRefractionPass* settings,
    const Frame& frame, bool debug);

  /// Shades the glass and puts it into the framebuffer bound now (the renderer's viewport),
  /// unless frame.SampleComposite (vtkRefractionSampleComposite puts it there).
  void Render(vtkOpenGLRenderer* ren, vtkRefractionMethod* method, vtkRefractionPass* settings,
    vtkRefractionTargets* targets, const Frame& frame, const std::vector<float>& materialIOR, const std::vector<float>& materialSheet);

  /// Renders the debug output into DEBUG_0/DEBUG_1 and returns it as an image.
  vtkSmartPointer<vtkImageData> RenderDebug(vtkOpenGLRenderer* ren, vtkRefractionMethod* method,
    vtkRefractionPass* settings, vtkRefractionTargets* targets, const Frame& frame,
    const std::vector<float>& materialIOR, const std::vector<float>& materialSheet);

  void ReleaseGraphicsResources(vtkWindow* w);

protected:
  vtkRefractionShadeStage();
  ~vtkRefractionShadeStage() override;

private:
  vtkRefractionShadeStage(const vtkRefractionShadeStage&) = delete;
  void operator=(const vtkRefractionShadeStage&) = delete;

  struct Program;
  enum ProgramKind
  {
    PROGRAM_SHADE,          // every pixel (coarse shading: those the blocks do not stand for)
    PROGRAM_DEBUG,          // the debug output
    PROGRAM_COARSE_SAMPLES, // coarse shading: one ray per 2x2 block
  };
  Program* GetProgram(int kind);
  // Builds the program of that kind from the shading source and the defines, unless it was
  // built from the same defines before.
  bool Build(vtkOpenGLRenderer* ren, vtkRefractionMethod* method, int kind,
    const std::string& defines);
  // Frame::CoarseShading: the rays of the 2x2 blocks whose traced pixel is glass into
  // COARSE_COLOR and COARSE_RAY, culled by COARSE_Z (made first, shaders/rfCoarseDepthFS.glsl).
  // False when a program or target is missing (then every pixel traces its own ray).
  bool DrawCoarseSamples(vtkOpenGLRenderer* ren, vtkRefractionMethod* method,
    vtkRefractionPass* settings, vtkRefractionTargets* targets, const Frame& frame,
    const std::vector<float>& materialIOR, const std::vector<float>& materialSheet);
  // Frame::CoarseShading, into the colour attached now with TRACE_Z attached (depth test
  // GL_ALWAYS, depth writes on), over the glass's rectangle: the pixels the blocks' rays stand
  // for take their colour, and the depth is 0 where a glass pixel must trace its own ray, 1
  // elsewhere (shaders/rfCoarseResolveFS.glsl). False when its program does not build.
  bool ResolveCoarseSamples(
    vtkOpenGLRenderer* ren, vtkRefractionTargets* targets, const Frame& frame);
  // A coarse shading quad's program made ready (vtkRefractionQuad::Ready); nullptr, with an
  // error, when it does not build.
  vtkShaderProgram* ReadyCoarseQuad(vtkOpenGLRenderWindow* renWin,
    std::unique_ptr<vtkOpenGLQuadHelper>& quad, const std::string& fragmentSource,
    const std::string& vertexSource);
  // Mip levels for the renderer's cube map where it has none and is filtered linearly, so that
  // the filtered lookups (rfEnvironment) can average over a ray's spread: VTK 9.1's
  // vtkEquirectangularToCubeMapTexture fixes its minification filter to linear and makes no
  // levels, whatever its Mipmap flag says. Made again whenever VTK reloads the texture (its
  // filter is linear again then). Call with the cube map loaded and bound.
  static void AddEnvironmentMipmaps(vtkOpenGLTexture* cube);
  void Draw(vtkOpenGLRenderer* ren, vtkRefractionMethod* method, vtkRefractionPass* settings,
    vtkRefractionTargets* targets, const Frame& frame, const std::vector<float>& materialIOR,
    const std::vector<float>& materialSheet, int kind);

  // The glass colour target into the framebuffer bound now, with the glass's depth; with
  // anti-aliasing (corners) each pixel averages its four corners over the scene.
  void Composite(vtkOpenGLRenderer* ren, vtkRefractionTargets* targets, bool corners,
    const int rectangle[4]);
  // Frame::SmoothInternalReflections: into the colour attached now (the glass colour target,
  // the front capture's depth test set), the shading's output `shaded` with the pixels near a
  // marked one smoothed (shaders/rfSmoothReflectedFS.glsl).
  void SmoothReflectedPixels(vtkOpenGLRenderer* ren, vtkTextureObject* shaded);
  // Anti-aliasing: into the depth buffer attached now, the nearest front depth of the four
  // pixels that meet at each corner (shaders/rfCornerDepthFS.glsl).
  void DrawCornerDepth(vtkOpenGLRenderer* ren, vtkTextureObject* frontDepth);
  std::unique_ptr<Program> Shade;
  std::unique_ptr<Program> Debug;
  std::unique_ptr<Program> CoarseSamples;
  std::unique_ptr<vtkOpenGLQuadHelper> CompositeQuad;
  std::unique_ptr<vtkOpenGLQuadHelper> CornerCompositeQuad;
  std::unique_ptr<vtkOpenGLQuadHelper> SmoothQuad;
  std::unique_ptr<vtkOpenGLQuadHelper> CornerDepthQuad;
  std::unique_ptr<vtkOpenGLQuadHelper> CoarseDepthQuad;
  std::unique_ptr<vtkOpenGLQuadHelper> CoarseResolveQuad;
  std::string CoarseResolveDefines;
};

#endif
