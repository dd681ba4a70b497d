/**
 * @class   vtkRefractionTargets
 * @brief   The off-screen render targets of vtkRefractionPass, allocated per method.
 *
 * One holder owns every texture the pass renders into and the framebuffer object it binds
 * them to. The pass asks each frame for the set of targets its method needs; the others are
 * released, so what a method costs in memory is what it uses. Bytes are counted from the
 * sizes the driver reports for each allocated texture (glGetTexLevelParameteriv), not from
 * the formats asked for.
 */
#ifndef vtkRefractionTargets_h
#define vtkRefractionTargets_h

#include "vtkObject.h"
#include "vtkSmartPointer.h" // For members

#include <string> // For MatchSceneDepth
#include <vector> // For members

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class vtkRefractionTargets : public vtkObject
{
public:
  static vtkRefractionTargets* New();
  vtkTypeMacro(vtkRefractionTargets, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum TargetType
  {
    FRONT_SURFACE = 0, ///< RGBA32F: octahedral view-space normal (2), -z_view, material + 1
    FRONT_DEPTH,       ///< DEPTH32F: the glass's nearest surface, written to the screen's depth
    FRONT_AUX,         ///< R32F: ISR's d_N at the front surface (view-space units; < 0: none)
    FRONT_COLOR,       ///< RGBA8: the data's colour at the front surface (actor or scalars)
    BACK_SURFACE,      ///< RGBA32F, filtered: outward view-space normal of the back surface
                       ///< and its -z_view in alpha, 0 where there is none
    BACK_Z,            ///< DEPTH32F: the depth test of the back capture
    SCENE_COLOR,       ///< RGBA8: the opaque scene (and SSP's refraction mask in alpha)
    SCENE_DEPTH,       ///< the opaque scene's depth (window coordinates), in the scene's format
    GLASS_COLOR,       ///< RGBA16F: the shaded glass, which the composite puts into the scene:
                       ///< at each pixel, or with anti-aliasing at each pixel's lower-left
                       ///< corner (alpha 1 where the corner lies on the glass)
    GLASS_COLOR_SHADED, ///< RGBA16F: GLASS_COLOR as the shading wrote it, which smoothing the
                        ///< pixels reflected inside reads (SetSmoothInternalReflections)
    CORNER_Z,          ///< DEPTH32F: anti-aliasing, the nearest front depth of the four pixels
                       ///< that meet at each pixel's lower-left corner (1: no glass there)
    PEEL_1,            ///< RGBA32F: PEEL's depth-peeled layers 1 .. 7 (layer 0 is
    PEEL_2,            ///< FRONT_SURFACE): octahedral normal toward the viewer, -z_view,
    PEEL_3,            ///< +-(material + 1), positive where the outward side faces the viewer
    PEEL_4,
    PEEL_5,
    PEEL_6,
    PEEL_7,
    PEEL_Z,            ///< DEPTH32F: the depth test of the peeling
    PEEL_DEPTHS_A,     ///< RGBA32F: the depths of layers 0-3 (vtkRefractionLayerPack)
    PEEL_DEPTHS_B,     ///< RGBA32F: the depths of layers 4-7
    PEEL_SLOTS,        ///< R32UI, SetPeelSlots times the height: PEEL's k-buffer, the depths
                       ///< of layers 1 .. K - 1 sorted (vtkRefractionGeometryStage)
    PEEL_STACK,        ///< RGBA32F: the K layers' texels side by side, as many to a row of
                       ///< layers as fit the driver's largest texture (layer k at column
                       ///< k % columns, row k / columns, each the window's size; columns:
                       ///< the stack's width over the window's), so that the shading reads
                       ///< any layer in one fetch (vtkRefractionLayerPack)
    FRONT_SH,          ///< RGBA32F: the SH method's exit direction (view space) and length
    DEBUG_0,           ///< RGBA32F: P2 and |P2 - P1|
    DEBUG_1,           ///< RGBA32F: T2 and the flags
    COARSE_COLOR,      ///< RGBA16F, filtered, half the width and height (rounded up): the
                       ///< colour traced at the lower-left pixel of each 2x2 block and the
                       ///< glass's -z_view there (CoarseShading)
    COARSE_RAY,        ///< RGBA32F, filtered, as COARSE_COLOR: that ray's exit direction and
                       ///< material + 1; 0 where no glass, or where it was reflected inside
    COARSE_Z,          ///< DEPTH32F, as COARSE_COLOR: the front depth at each block's traced
                       ///< pixel, which culls the blocks without glass
    TRACE_Z,           ///< DEPTH32F: 0 at the glass pixels the blocks' rays do not stand
                       ///< for, 1 elsewhere: culls the pixels that need no ray of their own
    TARGET_COUNT
  };
  static const char* GetTargetName(int target);

  /**
   * Allocate exactly the targets flagged in `wanted` (indexed by TargetType) at width x
   * height, and the min/max reduction chain when `reduction` is set; release all others.
   * Targets that exist at the right size are kept.
   */
  void Update(vtkOpenGLRenderWindow* renWin, int width, int height,
    const std::vector<bool>& wanted, bool reduction);

  /// The target, or nullptr when it is not allocated.
  vtkTextureObject* Get(int target) const;
  /// How many texels each side of a reduction pass's block holds: every level of the chain is
  /// this many times smaller than the one before (rounded up).
  static constexpr int ReductionBlock = 4;
  /// The reduction chain, down to 1x1 (RG32F: min, max); empty when not allocated.
  const std::vector<vtkSmartPointer<vtkTextureObject>>& GetReductionLevels() const
  {
    return this->ReductionLevels;
  }
  vtkOpenGLFramebufferObject* GetFramebuffer() const;

  /**
   * Give SCENE_DEPTH the depth format of the framebuffer bound for reading (the one VTK
   * draws the scene into). The scene is copied with one glBlitFramebuffer of colour and depth,
   * which resolves a multisampled window (VTK's default) and, for depth, requires identical
   * formats on both sides: DEPTH_COMPONENT16/24/32, 32F or DEPTH24_STENCIL8 here. Call before
   * Update. Returns false, with the reason in `error`, for a framebuffer without depth or
   * with a depth format no texture here can match.
   */
  bool MatchSceneDepth(std::string& error);

  /// How many slots (rows of the height each) PEEL_SLOTS holds: K - 1; PEEL_STACK holds
  /// K layers. Call before Update; a change allocates them again.
  void SetPeelSlots(int slots);

  /// Bytes of all allocated targets, as the driver reports their formats.
  unsigned long long GetBytes() const;

  /// Counts the mipmap levels a target has been given since it was allocated (the glass
  /// colour gets two for the composite at the window's samples, vtkRefractionSampleComposite):
  /// measures it again the first time after each allocation, so not every frame.
  void CountMipmaps(int target);

  /// A target's mip levels for the draws inside this scope: made from level 0 when it begins,
  /// with these filters and levels up to maxLevel, the texture active on its unit throughout;
  /// its filters and maximum level set back and its levels counted (CountMipmaps) when it
  /// ends: every other reader fetches level 0, and a mipmapped filter with levels left from
  /// another size would make the texture incomplete. Nothing where the target is not there.
  class ScopedMipmaps
  {
  public:
    ScopedMipmaps(vtkRefractionTargets* targets, int target, int minification,
      int magnification, int maxLevel);
    ~ScopedMipmaps();
    ScopedMipmaps(const ScopedMipmaps&) = delete;
    ScopedMipmaps& operator=(const ScopedMipmaps&) = delete;

  private:
    vtkRefractionTargets* Targets;
    int Target;
    vtkTextureObject* Texture;
    int Minification = 0;
    int Magnification = 0;
    int MaxLevel = 0;
  };

  void ReleaseGraphicsResources(vtkWindow* w);

protected:
  vtkRefractionTargets();
  ~vtkRefractionTargets() override;

private:
  vtkRefractionTargets(const vtkRefractionTargets&) = delete;
  void operator=(const vtkRefractionTargets&) = delete;

  void Allocate(vtkOpenGLRenderWindow* renWin, int target);
  vtkSmartPointer<vtkTextureObject> Targets[TARGET_COUNT];
  unsigned long long TargetBytes[TARGET_COUNT] = {};
  bool MipmapsCounted[TARGET_COUNT] = {};
  std::vector<vtkSmartPointer<vtkTextureObject>> ReductionLevels;
  unsigned long long ReductionBytes = 0;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  int Width = 0;
  int Height = 0;
  int SceneDepthFormat = -1; // vtkTextureObject's depth enum; -1: DEPTH24_STENCIL8
  int PeelSlots = 1;
};

#endif
