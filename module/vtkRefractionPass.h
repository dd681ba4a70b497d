/**
 * @class   vtkRefractionPass
 * @brief   Renders the actors marked as glass as refractive glass in an ordinary VTK scene.
 *
 * The core method is DIR (Oliveira & Brauwers, "Real-Time Refraction Through Deformable
 * Objects", I3D 2007): the back surface of the glass is captured into a normal and a depth
 * texture, the min/max back depth is reduced on the GPU, and the front surface refracts the
 * view ray, finds the exit point with the perspective-correct conservative binary search and
 * refracts again into the environment. Nothing is precomputed, so any vtkPolyData works,
 * including one that deforms or is re-contoured every time step.
 *
 * Usage:
 * @code
 * vtkNew<vtkRefractionPass> glass;         // wraps the usual VTK passes
 * renderer->SetPass(glass);
 * vtkRefractionPass::MakeGlass(actor, 1.5); // index of refraction on the actor's keys
 * @endcode
 *
 * The pass wraps a delegate (by default a vtkRenderStepsPass). When the delegate is a
 * vtkRenderStepsPass the glass is drawn right after the opaque geometry, so translucent
 * geometry and overlays (scalar bars, text) come after it as usual. Unmarked actors render
 * exactly as without the pass and are depth-correct against the glass. A renderer without
 * glass actors costs one loop over its props.
 *
 * The environment is the renderer's environment texture when it is a cube map (for example
 * a vtkEquirectangularToCubeMapTexture), else a built-in sky/ground pattern made in code.
 */
#ifndef vtkRefractionPass_h
#define vtkRefractionPass_h

#include "vtkOpenGLRenderPass.h"
#include "vtkRenderingRefractionModule.h" // For export macro
#include "vtkMatrix4x4.h"                 // For members
#include "vtkNew.h"                       // For members
#include "vtkSmartPointer.h"              // For members

#include <memory> // For std::unique_ptr
#include <set>    // For ReportedGLErrors
#include <string> // For members
#include <vector> // For members

class vtkImageData;
class vtkInformationDoubleKey;
class vtkInformationDoubleVectorKey;
class vtkInformationIntegerKey;
class vtkOpenGLRenderWindow;
class vtkOpenGLRenderer;
class vtkProp;
class vtkRefractionDepthRange;
class vtkRefractionFrameBuilder;
class vtkRefractionGeometryStage;
class vtkRefractionGBufferComposite;
class vtkRefractionGlassChecker;
class vtkRefractionLayerPack;
class vtkRefractionLights;
class vtkRefractionMaterials;
class vtkRefractionMethod;
class vtkRefractionOpaqueStep;
class vtkRefractionRankExchange;
class vtkRefractionSampleComposite;
class vtkRefractionSelectionPass;
class vtkRefractionShadeStage;
class vtkRefractionStageTimers;
class vtkRefractionTargets;

class VTKRENDERINGREFRACTION_EXPORT vtkRefractionPass : public vtkOpenGLRenderPass
{
public:
  static vtkRefractionPass* New();
  vtkTypeMacro(vtkRefractionPass, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Methods. SIR refracts once into the environment. DIR (default) refracts at two
   * interfaces, the exit found by searching the captured back surface. ISR (Wyman 2005)
   * estimates the exit distance from d_V and a per-vertex d_N (point array
   * "ISRNormalDistance", e.g. from vtkISRDistanceFilter; without it d_N = d_V). SSP (Sousa,
   * GPU Gems 2 ch. 19) perturbs the screen position of the opaque scene behind the glass by
   * the normal, with the chapter's refraction mask so that objects in front do not leak in.
   * PEEL (Chi, Wang & Hu) peels PeelLayers layers of all the glass and follows the ray through
   * every interface they hold: glass inside glass and glass behind glass refract each other,
   * each with its own index, and total internal reflection is followed (TIRBounces). SH
   * (Genevaux et al.) reads exit directions precomputed per vertex through every interface as
   * spherical harmonics, for static meshes that went through vtkSHTransferFilter (module
   * Refraction::Reference); a glass mesh without a fitting transfer (none, stale after its
   * points changed, or for another index) is reported and the frame is drawn with DIR.
   */
  enum MethodType
  {
    SIR = 0,
    DIR = 1,
    ISR = 2,
    SSP = 3,
    PEEL = 4,
    SH = 5
  };
  /// The point array ISR reads d_N from.
  static const char* GetISRDistanceArrayName();
  /// Where DIR's search range [Zmin, Zmax] comes from.
  enum DepthRangeType
  {
    DEPTH_RANGE_REDUCTION = 0, ///< min/max of the captured back depths, on the GPU
    DEPTH_RANGE_BOUNDS = 1     ///< the glass actors' bounding boxes (paper, section 5)
  };
  /// What happens when the ray cannot leave the glass (total internal reflection).
  enum TIRPolicyType
  {
    TIR_CLAMP = 0,  ///< the paper's policy: clamp to the critical angle (tangent exit)
    TIR_REFLECT = 1 ///< reflect once, then leave into the environment
  };

  ///@{
  /// Per-actor glass settings, stored on the prop's property keys.
  static vtkInformationIntegerKey* GLASS();
  static vtkInformationDoubleKey* INDEX_OF_REFRACTION();
  /**
   * How a glass prop's surface is modelled: SURFACE_AUTO (the key absent: decided per
   * connected piece of the mesh, a thin sheet where the piece is open as a whole, its boundary
   * edges at least as long as the square root of its area, a solid otherwise, small holes
   * included; composite data per block), SURFACE_SOLID (refract in, search the
   * exit, refract out) or SURFACE_THIN_SHEET (a slab of ThinSheetThickness: the ray is offset
   * and tinted, and leaves in its own direction; no exit search).
   */
  static vtkInformationIntegerKey* SURFACE_MODEL();
  /// Dispersion: the red, green and blue indices of refraction (see SetDispersion).
  static vtkInformationDoubleVectorKey* DISPERSION();
  ///@}
  enum SurfaceModelType
  {
    SURFACE_AUTO = -1,
    SURFACE_SOLID = 0,
    SURFACE_THIN_SHEET = 1
  };
  /// Set a prop's surface model (on its property keys).
  static void SetSurfaceModel(vtkProp* prop, int model);

  /**
   * Mark a prop as glass with an index of refraction (1.5 by default). An invalid index
   * (not finite, or <= 0) is reported and the prop is left unmarked. Returns success.
   * Glass shows the renderer's lights (headlight, light kit, scene lights) as highlights,
   * in the actor's Specular times SpecularColor with its SpecularPower, weighted by the glass's
   * Fresnel reflectance as glass mirrors a small bright source (none at index 1). An actor
   * whose property still has VTK's defaults (Specular 0, SpecularPower 1) gets
   * DefaultGlassSpecular and DefaultGlassSpecularPower here; set Specular 0 for none.
   */
  static bool MakeGlass(vtkProp* prop, double indexOfRefraction = 1.5);
  static constexpr double DefaultGlassSpecular = 1.0;
  static constexpr double DefaultGlassSpecularPower = 100.0;
  /// Unmark a prop; it renders as an ordinary actor again.
  static void ClearGlass(vtkProp* prop);
  /// True when the prop is marked as glass.
  static bool IsGlass(vtkProp* prop);
  /// The prop's index of refraction (1.5 when the prop has none set).
  static double GetIndexOfRefraction(vtkProp* prop);

  /**
   * Dispersion (off unless set): a glass prop refracts red, green and blue light with their
   * own indices, each colour channel following its own rays (three times the shading stage's
   * work where any glass prop disperses). The index of refraction of MakeGlass becomes the
   * green one. Each index is validated as MakeGlass validates it; on a bad one the prop's
   * dispersion is left as it was and false returned. The prop must be glass already.
   */
  static bool SetDispersion(vtkProp* prop, double red, double green, double blue);
  /// Remove a prop's dispersion: one index for all colours again.
  static void ClearDispersion(vtkProp* prop);
  /// The prop's red, green and blue indices; false (and the plain index thrice) without
  /// dispersion.
  static bool GetDispersion(vtkProp* prop, double rgb[3]);

  ///@{
  /// The passes that render everything else. Default: a vtkRenderStepsPass.
  void SetDelegatePass(vtkRenderPass* delegatePass);
  vtkGetObjectMacro(DelegatePass, vtkRenderPass);
  ///@}

  ///@{
  /// Refraction method (DIR by default).
  vtkSetClampMacro(Method, int, SIR, SH);
  vtkGetMacro(Method, int);
  ///@}

  ///@{
  /// Steps of the conservative binary search (0..16, default 5 as in the paper).
  /// The exit point is within 0.5^steps of the search segment's length. Without
  /// AdaptiveSearch the count is built into the shading program (a change builds it again):
  /// a loop of constant bound shaded a full-window sphere 15-25 % faster on llvmpipe.
  void SetSearchSteps(int steps);
  vtkGetMacro(SearchSteps, int);
  ///@}

  ///@{
  /**
   * Adaptive search (off by default): per pixel, the number of search steps is the number
   * needed to tell apart the texels the search segment covers on screen,
   * ceil(log2(projected length in texels)), capped by SearchSteps.
   */
  vtkSetMacro(AdaptiveSearch, bool);
  vtkGetMacro(AdaptiveSearch, bool);
  vtkBooleanMacro(AdaptiveSearch, bool);
  ///@}

  ///@{
  /**
   * Beyond the paper (on by default): after the search, one secant step inside its final
   * bracket (the linear refinement of relief mapping), taken only between valid texels so
   * the search stays conservative. Off gives the paper's search exactly.
   */
  vtkSetMacro(SecantRefinement, bool);
  vtkGetMacro(SecantRefinement, bool);
  vtkBooleanMacro(SecantRefinement, bool);
  ///@}

  ///@{
  /**
   * Which back surface the capture keeps where several project to a pixel: the furthest
   * (the paper's and Wyman's choice) or the nearest back-facing one (beyond the paper: on
   * shapes of several parts, such as a contour of separate blobs, the furthest surface
   * belongs to another part). Back faces are told by winding, corrected per mesh by the sign
   * of its volume, so inward-wound closed meshes work too.
   */
  enum BackSurfaceType
  {
    BACK_SURFACE_FURTHEST = 0,
    BACK_SURFACE_NEAREST = 1
  };
  vtkSetClampMacro(BackSurface, int, BACK_SURFACE_FURTHEST, BACK_SURFACE_NEAREST);
  vtkGetMacro(BackSurface, int);
  ///@}

  ///@{
  /// SSP: perturbation of the screen position by the view-space normal (default 0.05, the
  /// chapter's value), Fresnel bias and power (0.4 and 5, the chapter's glass), and chromatic
  /// aberration (relative spread of the red and blue offsets; 0 = none).
  vtkSetClampMacro(SSPStrength, double, 0.0, 1.0);
  vtkGetMacro(SSPStrength, double);
  vtkSetClampMacro(SSPFresnelBias, double, 0.0, 1.0);
  vtkGetMacro(SSPFresnelBias, double);
  vtkSetClampMacro(SSPFresnelPower, double, 0.0, 64.0);
  vtkGetMacro(SSPFresnelPower, double);
  vtkSetClampMacro(ChromaticAberration, double, 0.0, 1.0);
  vtkGetMacro(ChromaticAberration, double);
  /// The chapter's refraction mask (on by default); off shows the leaking it prevents.
  vtkSetMacro(SSPRefractionMask, bool);
  vtkGetMacro(SSPRefractionMask, bool);
  vtkBooleanMacro(SSPRefractionMask, bool);
  ///@}

  ///@{
  /// Source of DIR's depth range (reduction pass by default).
  vtkSetClampMacro(DepthRangeMode, int, DEPTH_RANGE_REDUCTION, DEPTH_RANGE_BOUNDS);
  vtkGetMacro(DepthRangeMode, int);
  ///@}

  ///@{
  /// Total internal reflection policy at the exit (TIR_CLAMP by default, as the paper).
  vtkSetClampMacro(TIRPolicy, int, TIR_CLAMP, TIR_REFLECT);
  vtkGetMacro(TIRPolicy, int);
  ///@}

  ///@{
  /**
   * DIR and PEEL: total internal reflections followed inside the glass (0 by default: the TIR
   * policy decides at the first exit). With B > 0 a ray totally reflected at its exit is
   * mirrored there and followed to its next exit, up to B times; the TIR policy applies after
   * the last. DIR follows it between the front and the back capture only (a ray that would
   * cross a third surface leaves where the two-layer picture says); PEEL through its layers.
   * More is not always closer: on blobby glass (the benchmark's metaballs) rays that hug the
   * silhouette read worse after a third and fourth bounce than with two (docs/benchmark.md).
   */
  vtkSetClampMacro(TIRBounces, int, 0, 8);
  vtkGetMacro(TIRBounces, int);
  ///@}

  ///@{
  /**
   * DIR: follow the light the exit reflects back inside (on by default). With Fresnel, the
   * exit surface reflects part of the ray back into the glass (about 4 % at normal incidence
   * for IOR 1.5, more toward grazing); the two-interface model drops it. With this on, that
   * part is mirrored at the exit, its next interface estimated from the captured surfaces
   * without a search (one chord further, inside a sphere exact: every chord of a reflected
   * ray there is as long as the one before), refracted out there, and mixed in by its Fresnel
   * share, as PEEL does at its first exit. On the benchmark's meshes at 512 px in VTK's
   * default window, against the supersampled full reference (glass pixels, without -> with):
   * sphere 31.1 -> 37.5 dB, torus 31.5 -> 32.8, isosurface 20.2 -> 20.4, bunny 15.8 -> 15.9,
   * nested 11.5 -> 11.8, for 0 to 14 % more frame time on llvmpipe (1.29 -> 1.43 times plain
   * VTK on the sphere; bench/results/cpu-llvmpipe-quick-msaa8-fill). Without Fresnel, or
   * with another method, nothing changes (PEEL follows it through its layers already).
   */
  vtkSetMacro(ExitReflection, bool);
  vtkGetMacro(ExitReflection, bool);
  vtkBooleanMacro(ExitReflection, bool);
  ///@}

  ///@{
  /**
   * Smooth the pixels where the refracted ray was totally reflected inside the glass (off by
   * default; every method that finds an exit: DIR, ISR, PEEL). Through such a pixel the rays
   * leave along paths of their own (another wall, another bounce), so the one ray the pixel
   * traces is a poor estimate of the light it averages; with this on, each glass pixel within
   * one pixel of such a pixel shows the tent-weighted mean (1-2-1) of the glass in its 3 x 3
   * neighbourhood instead. Beyond the papers; shaders/rfReflectedFilter.glsl. Not with
   * SetAntiAliasing, whose four corners average a pixel already. Measured on the benchmark's
   * meshes in docs/benchmark.md.
   */
  vtkSetMacro(SmoothInternalReflections, bool);
  vtkGetMacro(SmoothInternalReflections, bool);
  vtkBooleanMacro(SmoothInternalReflections, bool);
  ///@}

  ///@{
  /**
   * SH: the width (in bands) of the semi-Gaussian low-pass filter on the SH weights of
   * Genevaux et al. (section 4.3), exp(-l^2 / (2 width^2)) on band l, against the ringing of
   * the truncated series; 0 turns it off. Default 5: on a ball at order 8 the exit direction's
   * mean error fell from 2.34 to 1.09 degrees (width 4: 1.25, 8: 1.53).
   */
  vtkSetClampMacro(SHSmoothing, double, 0.0, 100.0);
  vtkGetMacro(SHSmoothing, double);
  ///@}

  ///@{
  /**
   * PEEL: the layers of the glass captured by depth peeling, K (4 by default, as the paper),
   * counting the front surface: with 2 the layer behind the front is the furthest surface, what
   * DIR's back capture holds (the two-interface model); from 3 on they are the K nearest
   * surfaces. Each further layer costs one more draw of the glass (or none, SetPeelCapture)
   * and 16 bytes per pixel. Rays follow at most K - 1 + TIRBounces interfaces after the front
   * one. Peeling stops at the first layer that comes out empty (an occlusion query per layer):
   * the layers behind it would be empty too, so a convex glass costs two draws whatever K.
   */
  vtkSetClampMacro(PeelLayers, int, 2, 8);
  vtkGetMacro(PeelLayers, int);
  ///@}

  enum PeelCaptureModes
  {
    PEEL_CAPTURE_AUTO = 0,
    PEEL_CAPTURE_DEPTH_PEELING = 1,
    PEEL_CAPTURE_K_BUFFER = 2
  };
  ///@{
  /**
   * How PEEL captures its layers behind the front. DEPTH_PEELING: one draw of the glass per
   * layer (Everitt's depth peeling), stopping at the first layer that comes out empty.
   * K_BUFFER (with 3 or more layers, where the context has GL 4.2's image load/store and 3.3's
   * float bits or their ARB extensions; peeling elsewhere): two draws whatever K. The first
   * sorts each pixel's nearest depths behind the front into K - 1 slots with image atomics
   * (4 more bytes per slot and pixel), the second writes each layer's normal and material.
   * The same layers, so the same pictures. AUTO (default): the k-buffer with 6 or more layers
   * where the last PEEL frame found more than 3 holding glass and its glass could not be
   * peeled one facing at a time (as GetPeelFacingCulled reports where it is peeled; in one
   * process: across MPI ranks only K_BUFFER asks for it), peeling otherwise. Peeling by
   * facing drew PEEL 8's layers in 64-74 ms on the isosurface against the k-buffer's 89-102,
   * and alike on the bunny
   * (llvmpipe, single-sampled 512x512; docs/benchmark.md, *The k-buffer left where the
   * layers can be peeled by facing*). Against peeling both facings (llvmpipe, 2 cores, VTK's
   * default window at 512x512): PEEL 8 on the bunny 6.9 -> 4.6 times plain VTK, on the nested
   * contours 7.6 -> 6.2, on the sphere (two layers, where peeling stops after one draw)
   * 4.8 -> 5.5; with 4 layers the two read alike. Not measured on a GPU, where the draws saved
   * weigh more and the atomics less.
   */
  vtkSetClampMacro(PeelCapture, int, PEEL_CAPTURE_AUTO, PEEL_CAPTURE_K_BUFFER);
  vtkGetMacro(PeelCapture, int);
  ///@}

  /**
   * PEEL: how many of the PeelLayers layers the last frame found holding glass somewhere
   * (the front surface counts; 0 before the first PEEL frame). Across MPI ranks every layer is
   * drawn and this is PeelLayers.
   */
  vtkGetMacro(PeelLayersFound, int);

  /**
   * PEEL: how many times the last frame drew the glass to capture the layers behind the front
   * (0 before the first PEEL frame): one draw per layer peeled, two with the k-buffer
   * (SetPeelCapture). Peeling stops at the first empty layer, and without drawing the next
   * where no pixel holds another surface behind the layer just drawn: on convex glass (a
   * ball) one draw whatever PeelLayers.
   */
  vtkGetMacro(PeelLayersDrawn, int);

  /**
   * PEEL: whether the last frame peeled each layer's one facing only (false before the first
   * PEEL frame, with the k-buffer, and on the first frame of each new version of the mesh, so
   * that a mesh new every frame is never examined): where one glass actor of one closed mesh
   * (a vtkPolyData, or composite data with one visible block) is drawn whose pieces neither
   * nest nor wind against each other, every sight line enters and leaves it by turns, so
   * each layer behind the front is drawn with the faces of the other facing culled. The same
   * layers, in about half the fragments.
   */
  vtkGetMacro(PeelFacingCulled, bool);

  /**
   * What the glass shows where its rays leave toward the surroundings. Always the renderer's
   * environment texture when it is a cube map (a lat-long image through
   * vtkEquirectangularToCubeMapTexture, vtkRefractionImageIO::ReadEnvironment), honouring
   * EnvironmentUp and EnvironmentRight. Without one: ENVIRONMENT_RENDERER (default) the
   * renderer's background, solid or gradient (the colour the screen shows in that direction),
   * so glass of IOR 1 is invisible (and white glass alone over a solid background shows only
   * that background: give it a colour, DataColour, or something behind it);
   * ENVIRONMENT_BUILTIN the built-in sky and checkered ground (rf_builtin_environment), a
   * named option for tests, benchmarks and demonstrations.
   */
  enum EnvironmentType
  {
    ENVIRONMENT_RENDERER = 0,
    ENVIRONMENT_BUILTIN = 1
  };
  vtkSetClampMacro(EnvironmentMode, int, ENVIRONMENT_RENDERER, ENVIRONMENT_BUILTIN);
  vtkGetMacro(EnvironmentMode, int);
  void SetEnvironmentModeToRenderer() { this->SetEnvironmentMode(ENVIRONMENT_RENDERER); }
  void SetEnvironmentModeToBuiltin() { this->SetEnvironmentMode(ENVIRONMENT_BUILTIN); }

  ///@{
  /**
   * Refract the opaque scene behind the glass (on by default; nearby geometry, Wyman 2005):
   * the colour and depth of everything drawn before the glass are captured and the ray
   * leaving the glass is followed through them; where it meets nothing it takes the
   * environment. Off, or with no opaque prop in the renderer, nothing is captured. SIR, DIR
   * and ISR; SSP perturbs the captured scene in its own way.
   */
  vtkSetMacro(SceneRefraction, bool);
  vtkGetMacro(SceneRefraction, bool);
  vtkBooleanMacro(SceneRefraction, bool);
  ///@}

  ///@{
  /**
   * Colour from the data (on by default): the glass actor's colour, or its mapper's scalar
   * colours through the lookup table, tints the glass by Beer-Lambert absorption: light that
   * travels AbsorptionDistance inside the glass keeps exactly that colour, light along the
   * measured path |P2 - P1| keeps colour^(|P2 - P1| / AbsorptionDistance), so thick parts are
   * deeper in colour. White glass (the default actor colour) stays clear, and when no glass
   * prop has a colour, scalar colours or edges the colour is not even captured.
   * AbsorptionDistance is a length in world units that belongs to the material. 0 (default):
   * half the largest bounding-box diagonal of the glass props in the first frame that shows
   * data colour, then kept (a deforming object keeps the colour of its parts that do not move);
   * after a change of the setting back to 0 the next frame derives it anew.
   */
  vtkSetMacro(DataColour, bool);
  vtkGetMacro(DataColour, bool);
  vtkBooleanMacro(DataColour, bool);
  vtkSetClampMacro(AbsorptionDistance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(AbsorptionDistance, double);
  ///@}

  ///@{
  /// Thickness of the thin sheets (see SURFACE_MODEL); 0 (default): 1% of the prop's
  /// bounding-box diagonal.
  vtkSetClampMacro(ThinSheetThickness, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(ThinSheetThickness, double);
  ///@}

  ///@{
  /// Blend reflection and refraction with the exact dielectric Fresnel term (on by default).
  vtkSetMacro(Fresnel, bool);
  vtkGetMacro(Fresnel, bool);
  vtkBooleanMacro(Fresnel, bool);
  ///@}

  ///@{
  /// Average each lookup of the environment, and of the opaque scene behind the glass, over
  /// the directions the pixel's rays spread across (on by default): glass that shrinks them
  /// shows their mean rather than moire, as a camera's pixel does. Off: one direction per ray
  /// (what closed forms sample) and one texel of the captured scene.
  vtkSetMacro(FilteredLookups, bool);
  vtkGetMacro(FilteredLookups, bool);
  vtkBooleanMacro(FilteredLookups, bool);
  ///@}

  ///@{
  /**
   * Anti-aliasing of the glass (off by default, as VTK's own FXAA and multisampling are):
   * the refraction is shaded at the pixels' corners instead of their centres (one ray per
   * pixel, as many as without it, each meeting the glass where the G-buffer interpolated at
   * the corner puts the surface) and each pixel averages its four corners: four rays per
   * pixel for the price of one, plus a pass that finds the corners next to the glass (those
   * are shaded) and a composite that averages each pixel's four. At the silhouette the share
   * of a pixel's corners on the glass blends it over the scene. Costs one DEPTH32F target.
   * With FilteredLookups (the default) it is worth it only for the silhouette of a
   * single-sampled window: inside the glass the filtered lookups come closer to the
   * supersampled truth than the four corners averaged a pixel apart (tests: 33.9 dB against
   * 27.5 inside, 19.4 against 14.9 on the silhouette, single-sampled).
   */
  vtkSetMacro(AntiAliasing, bool);
  vtkGetMacro(AntiAliasing, bool);
  vtkBooleanMacro(AntiAliasing, bool);
  ///@}

  ///@{
  /**
   * Fewer rays than pixels (off by default): the refraction is traced at one pixel of each
   * 2x2 block, and every pixel whose neighbouring traced pixels lie on the same smooth part of
   * the glass (its own material, a depth within 2 % of its own, exit directions within about
   * 2 degrees of each other, no ray reflected inside, colours within 0.1 of each other) takes
   * their colours interpolated. The other pixels (the silhouettes, edges between actors,
   * creases and jumps of the exit, rays reflected inside, edges of what the glass shows) are
   * traced as without it. On llvmpipe it gained while a ray cost more than the lookups
   * (a full-window sphere at 2048 px: 5.2 -> 4.4 times plain VTK); since the full shading got
   * cheaper (loops of constant bound) it reads even with it there (3.8 times both), so it is
   * for a renderer where a ray costs much more than a lookup (not measured on a GPU). At
   * 512 px it read 0.1-0.3 dB below the full shading against the ray-traced truth
   * (docs/benchmark.md, *Coarse shading*, *Loops of constant bound*). Costs an RGBA16F, an RGBA32F
   * and a DEPTH32F target of a quarter of the pixels and a DEPTH32F target of all of them.
   * Not with AntiAliasing (which wins).
   */
  vtkSetMacro(CoarseShading, bool);
  vtkGetMacro(CoarseShading, bool);
  vtkBooleanMacro(CoarseShading, bool);
  ///@}

  ///@{
  /**
   * The glass's silhouette at the window's samples (on by default). VTK's default window is
   * multisampled, and the opaque actors' edges are resolved from its samples; the glass is
   * shaded once per pixel, so put into the scene pixel by pixel its silhouette would be
   * stair-stepped beside them. With this on, in a multisampled framebuffer the glass's front
   * surface is drawn once more, through the mappers, with the colour its pixels were shaded
   * (vtkRefractionSampleComposite): the window's samples cover the glass exactly as they would
   * cover an opaque actor of the same mesh, so its silhouette, and its edges against opaque
   * actors, are as smooth as VTK's own. Costs one more draw of the glass's front faces (in a
   * single-sampled framebuffer nothing: the pass composites pixel by pixel there). Works with
   * AntiAliasing too.
   */
  vtkSetMacro(MultiSampleSilhouette, bool);
  vtkGetMacro(MultiSampleSilhouette, bool);
  vtkBooleanMacro(MultiSampleSilhouette, bool);
  ///@}

  enum CompositeProgramModes
  {
    COMPOSITE_PROGRAM_AUTO = 0,
    COMPOSITE_PROGRAM_SEPARATE = 1,
    COMPOSITE_PROGRAM_SHARED = 2
  };
  ///@{
  /**
   * How the silhouette's draw at the window's samples (MultiSampleSilhouette) shares the
   * glass mappers' program with the G-buffer draws of the same frame. SHARED: one program holds
   * both, a uniform picks the stage. SEPARATE: the composite's code is in the program only
   * for its own draw, and that draw's program holds nothing else (no G-buffer code); VTK's
   * mapper rebuilds its shader source at each of the two switches a frame (its shader cache
   * keeps both compiled programs). Same pictures. AUTO (default):
   * SEPARATE on software rasterizers (llvmpipe, softpipe, SWR), which run the code of both
   * sides of a branch in every fragment, SHARED elsewhere. Measured on llvmpipe, 2 cores, a
   * 4-sample window at 512x512 (docs/benchmark.md): SEPARATE took DIR's frame from 1.74 to
   * 1.62 times plain VTK on the sphere, 2.00 to 1.85 on the torus; the switches cost about
   * 2 ms of CPU per frame there, which a GPU that skips the branch not taken would pay for
   * nothing (not measured on a GPU).
   */
  vtkSetClampMacro(CompositeProgram, int, COMPOSITE_PROGRAM_AUTO, COMPOSITE_PROGRAM_SHARED);
  vtkGetMacro(CompositeProgram, int);
  ///@}

  ///@{
  /**
   * Debug output: when on, every render also writes, per pixel of the glass, the exit point
   * P2 (view space), the exit direction T2 (view space) and the thickness |P2 - P1| into
   * GetDebugImage(): point arrays "P2" (3), "T2" (3), "Thickness" (1) and "Flags" (1: 0 no
   * glass, 1 glass, 2 glass with total internal reflection at the exit, 3 total reflection at
   * the entry: IOR < 1 beyond the critical angle, T2 is then the mirror direction).
   * GetDebugImage() is null after a frame whose debug program could not be built.
   */
  vtkSetMacro(DebugOutput, bool);
  vtkGetMacro(DebugOutput, bool);
  vtkBooleanMacro(DebugOutput, bool);
  vtkImageData* GetDebugImage();
  ///@}

  ///@{
  /**
   * GPU time of the pass's stages with GL timer queries (GL_TIME_ELAPSED), off by default
   * since a query costs a little. GetStageMilliseconds returns the last completed
   * measurement of a stage (-1 when none): call it after the frame has finished (glFinish).
   */
  enum TimedStageType
  {
    TIMED_BACK_CAPTURE = 0, ///< DIR pass 1 (DIR, ISR); PEEL's peeled layers
    TIMED_DEPTH_RANGE = 1,  ///< DIR pass 2 (DIR)
    TIMED_FRONT = 2,        ///< the front G-buffer (and SSP's mask and scene copy)
    TIMED_SHADE = 3,        ///< the refraction, once per glass pixel
    TIMED_STAGE_COUNT = 4
  };
  /// "back capture", "depth range", "front", "shade" (nullptr for an unknown stage).
  static const char* GetStageName(int stage);
  vtkSetMacro(GPUTiming, bool);
  vtkGetMacro(GPUTiming, bool);
  vtkBooleanMacro(GPUTiming, bool);
  double GetStageMilliseconds(int stage);
  ///@}

  /// Bytes of the GPU render targets the pass holds for the method of its last render (as
  /// the driver reports their formats), for memory reports.
  unsigned long long GetTextureBytes() const;

  /// Number of glass props drawn by the last render.
  vtkGetMacro(NumberOfGlassProps, int);

  ///@{
  /**
   * Sort-last parallel rendering (ParaView on several MPI ranks): with an exchange of more
   * than one rank, every rank draws its piece of the glass into its G-buffers, the buffers
   * are composited across the ranks (vtkRefractionGBufferComposite: the nearest front, the
   * furthest back, PEEL's nearest layers, the nearest opaque scene) and rank 0 shades the
   * whole glass once; the other ranks draw only their opaque props, and the depth compositing
   * that follows puts everything in its place. Every rank must render each frame (the
   * exchange's calls are collective). The multisampled silhouette (which redraws the glass's
   * own geometry) is off while compositing; ISR's d_N is each rank's piece's. Null (the
   * default) or one rank: one process, as without.
   */
  void SetRankExchange(vtkRefractionRankExchange* exchange);
  vtkRefractionRankExchange* GetRankExchange();
  /// The last frame's milliseconds in the G-buffer compositing on this rank (0 without it).
  double GetCompositeMilliseconds() const;
  /// Of those, the milliseconds blocked receiving (waiting for slower ranks, and the messages).
  double GetCompositeWaitMilliseconds() const;
  /// Bytes of one rank's G-buffers in the last composited frame (each rank but rank 0 sends
  /// one buffer per frame; 0 without compositing).
  unsigned long long GetCompositeBufferBytes() const;
  /**
   * The renderer's real background (its bottom colour with a gradient) while compositing
   * across ranks, for compositors that draw each rank over black and add the background
   * afterwards (ParaView's IceT pass): the glass then refracts this colour, and SSP's captured
   * scene has it where no opaque prop is. Used only while compositing, and only when
   * UseCompositingBackground is on.
   */
  vtkSetVector3Macro(CompositingBackground, double);
  vtkGetVector3Macro(CompositingBackground, double);
  vtkSetMacro(UseCompositingBackground, bool);
  vtkGetMacro(UseCompositingBackground, bool);
  ///@}

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  vtkRefractionPass();
  ~vtkRefractionPass() override;

  friend class vtkRefractionOpaqueStep;
  int RenderOpaqueAndGlass(const vtkRenderState* s, vtkRenderPass* opaque);
  /// While the renderer has a hardware selector: every prop drawn into it, the glass as its
  /// surface (vtkRefractionSelectionPass).
  void RenderSelection(const vtkRenderState* s);
  void RenderGlass(const vtkRenderState* s, std::vector<vtkProp*>& glass, bool opaqueScene);
  void CaptureScene(vtkOpenGLRenderer* ren, bool depth);
  /**
   * Across ranks (vtkRefractionPassRanks.cxx): draws PEEL's layers, agrees the bounds' depth
   * range, composites the G-buffers onto rank 0 (vtkRefractionGBufferComposite) and returns
   * whether this rank goes on to shade (rank 0).
   */
  bool CompositeAcrossRanks(vtkOpenGLRenderer* ren, vtkOpenGLRenderWindow* renWin,
    const std::vector<vtkProp*>& glass, vtkRefractionMethod* method, const double background[3],
    const double background2[3], int peelLayers, bool reduction, bool dataColour,
    bool sceneCapture, bool compositingBackground, vtkRefractionRankExchange* exchange);
  /// The exchange when it has more than one rank, else nullptr.
  vtkRefractionRankExchange* CompositingExchange();
  /// Each glass prop's bounds across the ranks (6 values per prop; xmin > xmax: none): a
  /// rank's own are those of its piece (vtkRefractionPassRanks.cxx; a collective call).
  static std::vector<double> AgreeGlassBounds(
    const std::vector<vtkProp*>& glass, vtkRefractionRankExchange* exchange);
  /**
   * Any OpenGL error pending is reported as an error of `call` (once per call: the same fault
   * every frame would flood the log) and cleared. Debian's VTK is built without
   * VTK_REPORT_OPENGL_ERRORS, so vtkOpenGLCheckErrorMacro says nothing there.
   */
  void ReportGLError(const char* call);

  vtkRenderPass* DelegatePass = nullptr;
  vtkSmartPointer<vtkRefractionOpaqueStep> OpaqueStep;

  int Method = DIR;
  int SearchSteps = 5;
  int DepthRangeMode = DEPTH_RANGE_REDUCTION;
  int TIRPolicy = TIR_CLAMP;
  int TIRBounces = 0;
  bool ExitReflection = true;
  bool SmoothInternalReflections = false;
  int PeelLayers = 4;
  int PeelCapture = PEEL_CAPTURE_AUTO;
  int PeelLayersFound = 0;
  int PeelLayersDrawn = 0;
  bool PeelFacingCulled = false;
  double SHSmoothing = 5.0;
  bool Fresnel = true;
  bool FilteredLookups = true;
  bool AntiAliasing = false;
  bool CoarseShading = false;
  bool MultiSampleSilhouette = true;
  int CompositeProgram = COMPOSITE_PROGRAM_AUTO;
  bool DebugOutput = false;
  bool AdaptiveSearch = false;
  bool SecantRefinement = true;
  int BackSurface = BACK_SURFACE_FURTHEST;
  double SSPStrength = 0.05;
  double SSPFresnelBias = 0.4;
  double SSPFresnelPower = 5.0;
  double ChromaticAberration = 0.0;
  bool SSPRefractionMask = true;
  bool GPUTiming = false;
  int EnvironmentMode = ENVIRONMENT_RENDERER;
  bool SceneRefraction = true;
  bool DataColour = true;
  double AbsorptionDistance = 0.0;
  double ThinSheetThickness = 0.0;
  int NumberOfGlassProps = 0;

  vtkNew<vtkRefractionGlassChecker> GlassChecker;
  vtkNew<vtkRefractionSelectionPass> SelectionPass;
  vtkNew<vtkRefractionTargets> Targets;
  vtkNew<vtkRefractionGeometryStage> GeometryStage;
  vtkNew<vtkRefractionDepthRange> DepthRange;
  vtkNew<vtkRefractionLayerPack> LayerPack;
  vtkNew<vtkRefractionShadeStage> ShadeStage;
  vtkNew<vtkRefractionSampleComposite> SampleComposite;
  vtkNew<vtkRefractionMaterials> Materials;
  vtkNew<vtkRefractionLights> Lights;
  vtkSmartPointer<vtkRefractionMethod> MethodObject;
  int MethodObjectType = -1;
  vtkNew<vtkRefractionStageTimers> StageTimers;
  vtkNew<vtkRefractionFrameBuilder> FrameBuilder;
  vtkSmartPointer<vtkRefractionRankExchange> RankExchange;
  vtkNew<vtkRefractionGBufferComposite> GBufferComposite;
  bool Composited = false; ///< whether the last frame composited across ranks
  double CompositingBackground[3] = { 0.0, 0.0, 0.0 };
  bool UseCompositingBackground = false;

  bool WarnedEmptyViewport = false;
  std::string WarnedSHTransfer; ///< the last reason SH fell back to DIR, said once
  std::string WarnedSceneDepth; ///< the last reason the scene could not be captured
  std::set<std::string> ReportedGLErrors; ///< the calls whose GL error was reported
  int Width = 0;
  int Height = 0;
  int ViewportOrigin[2] = { 0, 0 };
  double BoundsDepthRange[2] = { 0.0, 0.0 };
  vtkSmartPointer<vtkImageData> DebugImage;

private:
  vtkRefractionPass(const vtkRefractionPass&) = delete;
  void operator=(const vtkRefractionPass&) = delete;
};

#endif
