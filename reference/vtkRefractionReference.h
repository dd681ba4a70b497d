/**
 * @class   vtkRefractionReference
 * @brief   Ground truth for vtkRefractionPass: ray traces a renderer's glass on the CPU.
 *
 * Collects the renderer's visible actors marked as glass (vtkRefractionPass::IsGlass), takes
 * each mapper's input polydata, triangulates it, moves points and point normals (when there
 * are any; else geometric normals are used) to world space with the actor's matrix, and
 * traces them, with the renderer's other visible actors as opaque surfaces around them
 * (OpaqueActors), with the reference tracer (rf_tracer.h, Embree 3) through the renderer's
 * active camera: VTK's view matrix and projection matrix at the image's aspect ratio, the
 * matrices the GPU uses. Call it after the scene has been rendered (or after setting the
 * clipping range yourself): the camera's clipping range is used as it is.
 *
 * Two modes: TWO_INTERFACE is the exact counterpart of the pass's per-pixel formula with
 * the true exit point instead of DIR's depth-map search; FULL is a Whitted ray tracer
 * (Fresnel splits at every interface, true TIR, Beer-Lambert absorption, MaxDepth
 * interfaces). The output image has, per pixel (row 0 at the bottom, as the pass's debug
 * image), the float point arrays "Colour" (3, linear RGB), "P1", "P2", "T2" (3, view space),
 * "Thickness", "Bounces", "TIR", "Hit", "Flags" (0 no glass, 1 glass, 2 glass with
 * TIR), named as in vtkRefractionPass::GetDebugImage() where they overlap, and "Opaque" (1
 * where an opaque actor is seen in front of any glass: Flags 0, Colour its colour).
 *
 * Opaque actors (OpaqueActors, on by default): every visible non-glass vtkActor of the
 * renderer with a vtkPolyData surface and opacity 1 stops the rays that meet it: a primary
 * ray (the pixel is then not glass), the rays leaving the glass and the Fresnel reflections
 * (in both modes), with the colour VTK draws it with the renderer's default headlight
 * (rf_opaque_material: ambient + diffuse |N.z| + specular |N.z|^power along the view axis,
 * two-sided; the plain ambient + diffuse colour with lighting off; the mapper's scalar
 * colours, per point interpolated or per cell flat, in place of the ambient and diffuse
 * colours). Colours are the 8-bit framebuffer's values as fractions (no gamma), what the
 * pass captures and shows through the glass. Not reproduced: textures, other lights than
 * the default headlight (a light kit, positional lights), cell normals, scalar colours
 * interpolated before mapping (InterpolateScalarsBeforeMapping), field-data colours, edges,
 * PBR interpolation, and the rasterizer's per-fragment normal interpolation beyond
 * barycentric interpolation of the point normals (Flat interpolation uses the triangle's
 * normal, as VTK does). Actors that are translucent, drawn as points or wireframe, part of an
 * assembly (vtkAxesActor) or without polydata are left out with one warning per Trace.
 *
 * The environment is the one the pass samples: the renderer's environment texture when it
 * is a cube map (a vtkEquirectangularToCubeMapTexture is resampled from its lat-long input
 * into a cube of its CubeMapSize, as VTK renders it; a vtkTexture with CubeMapOn is read
 * from its six inputs), looked up through the renderer's EnvironmentUp and
 * EnvironmentRight exactly as the shader does (rf_environment_map.h); otherwise what
 * EnvironmentMode says the pass used: the built-in one (rf_builtin_environment) or the
 * renderer's background, solid or gradient, in the ray's direction exactly as the pass's
 * shader computes it (rf_background_environment_lookup). SetEnvironmentImage gives a
 * lat-long image instead, sampled directly (the environment itself, without the cube map's
 * resampling). Texel values are used as they are (floats raw, 8 and 16 bit normalized,
 * 8 bit sRGB decoded when the texture says so), as a texture with direct scalars is.
 *
 * SamplesPerSide N > 1 shades N x N sub-pixel positions and averages them (sub-samples
 * that miss the glass take the renderer's background colour): the anti-aliased truth a
 * camera sees. "Coverage" holds the share of sub-samples on glass; everything else is the
 * pixel centre's. Trace reports its progress through vtkCommand::ProgressEvent (call data:
 * a double in [0, 1]).
 * Glass far from the origin is traced relative to its centre (subtracted in double), so
 * offsets such as 1e7 keep full float precision, as VTK's mappers do on the GPU.
 *
 * @code
 * vtkNew<vtkRefractionReference> reference;
 * reference->SetMode(vtkRefractionReference::TWO_INTERFACE);
 * if (reference->Trace(renderer, 512, 512)) { vtkImageData* truth = reference->GetOutput(); }
 * @endcode
 */
#ifndef vtkRefractionReference_h
#define vtkRefractionReference_h

#include "rf_reference_export.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For members

#include <string> // For members

class vtkImageData;
class vtkRenderer;
class vtkTexture;

class RF_REFERENCE_EXPORT vtkRefractionReference : public vtkObject
{
public:
  static vtkRefractionReference* New();
  vtkTypeMacro(vtkRefractionReference, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ModeType
  {
    TWO_INTERFACE = 0, ///< the GPU's formula with the true exit point
    FULL = 1           ///< Whitted recursion: Fresnel splits, TIR, absorption
  };

  ///@{
  /// Tracing mode (TWO_INTERFACE by default).
  vtkSetClampMacro(Mode, int, TWO_INTERFACE, FULL);
  vtkGetMacro(Mode, int);
  ///@}

  ///@{
  /// TWO_INTERFACE only: TIR at the exit clamps to the critical angle (on, the paper's and
  /// the pass's default TIR_CLAMP) or reflects once (off, the pass's TIR_REFLECT).
  vtkSetMacro(TIRClamp, bool);
  vtkGetMacro(TIRClamp, bool);
  vtkBooleanMacro(TIRClamp, bool);
  ///@}

  ///@{
  /// FULL only: interfaces per path (1..64, default 8).
  vtkSetClampMacro(MaxDepth, int, 1, 64);
  vtkGetMacro(MaxDepth, int);
  ///@}

  ///@{
  /// Blend reflection and refraction with the exact dielectric Fresnel term (on by default).
  vtkSetMacro(Fresnel, bool);
  vtkGetMacro(Fresnel, bool);
  vtkBooleanMacro(Fresnel, bool);
  ///@}

  ///@{
  /// Worker threads (rows are interleaved over them; default 2).
  vtkSetClampMacro(Threads, int, 1, 256);
  vtkGetMacro(Threads, int);
  ///@}

  ///@{
  /// Rays per pixel along each side: 1 (the default) shades the pixel centre as the pass
  /// does; N shades an N x N grid and averages (1..32).
  vtkSetClampMacro(SamplesPerSide, int, 1, 32);
  vtkGetMacro(SamplesPerSide, int);
  ///@}

  ///@{
  /// An explicit lat-long environment (2D image, 1 to 4 components; rows from the bottom,
  /// as VTK reads images), sampled bilinearly with repeat, in the renderer's
  /// EnvironmentUp/EnvironmentRight frame. nullptr (the default): the renderer's.
  void SetEnvironmentImage(vtkImageData* image);
  vtkImageData* GetEnvironmentImage();
  ///@}

  ///@{
  /**
   * The environment without a cube map, as the pass's EnvironmentMode:
   * vtkRefractionPass::ENVIRONMENT_RENDERER (0) the renderer's background (solid or
   * gradient), vtkRefractionPass::ENVIRONMENT_BUILTIN (1, the default, what the reference
   * always used) the built-in sky and ground. Match a pass with
   * SetEnvironmentMode(pass->GetEnvironmentMode()) (the pass defaults to the renderer's).
   */
  vtkSetClampMacro(EnvironmentMode, int, 0, 1);
  vtkGetMacro(EnvironmentMode, int);
  void SetEnvironmentModeToRenderer() { this->SetEnvironmentMode(0); }
  void SetEnvironmentModeToBuiltin() { this->SetEnvironmentMode(1); }
  ///@}

  ///@{
  /// Trace the renderer's visible non-glass actors as opaque surfaces (on by default; see
  /// the class comment for what is reproduced). Off: glass alone, over the environment.
  vtkSetMacro(OpaqueActors, bool);
  vtkGetMacro(OpaqueActors, bool);
  vtkBooleanMacro(OpaqueActors, bool);
  ///@}

  /// What the last Trace looked the environment up in, in words.
  const char* GetEnvironmentDescription() { return this->EnvironmentDescription.c_str(); }

  ///@{
  /// Beer-Lambert absorption per unit length (world units) of every glass actor, per
  /// colour channel; 0 (clear glass, the default) is what the pass draws.
  vtkSetVector3Macro(Absorption, double);
  vtkGetVector3Macro(Absorption, double);
  ///@}

  /**
   * Trace the renderer's glass into a width x height image (0: the renderer's size).
   * Returns false, with an error message, when there is no visible glass actor, a glass
   * actor has no polydata input, empty polydata or non-finite points, or tracing fails.
   */
  bool Trace(vtkRenderer* renderer, int width = 0, int height = 0);

  /// The image of the last successful Trace (nullptr before).
  vtkImageData* GetOutput();

  /// World-space bounding-box diagonal of the glass last traced: the length P2 errors are
  /// measured against (rf_position_error).
  vtkGetMacro(GlassDiagonal, double);
  /// Glass actors and triangles last traced.
  vtkGetMacro(NumberOfGlassActors, int);
  /// Opaque actors last traced.
  vtkGetMacro(NumberOfOpaqueActors, int);
  vtkGetMacro(NumberOfTriangles, vtkIdType);
  /// Wall-clock seconds of the last trace (BVH build and rays; not the mesh collection).
  vtkGetMacro(TraceSeconds, double);

protected:
  vtkRefractionReference();
  ~vtkRefractionReference() override;

  int Mode = TWO_INTERFACE;
  bool TIRClamp = true;
  int MaxDepth = 8;
  bool Fresnel = true;
  int Threads = 2;
  double Absorption[3] = { 0.0, 0.0, 0.0 };
  int SamplesPerSide = 1;
  vtkSmartPointer<vtkImageData> EnvironmentImage;
  int EnvironmentMode = 1; // vtkRefractionPass::ENVIRONMENT_BUILTIN
  bool OpaqueActors = true;
  int NumberOfOpaqueActors = 0;
  std::string EnvironmentDescription = "none traced yet";

  double GlassDiagonal = 0.0;
  int NumberOfGlassActors = 0;
  vtkIdType NumberOfTriangles = 0;
  double TraceSeconds = 0.0;
  vtkSmartPointer<vtkImageData> Output;

private:
  vtkRefractionReference(const vtkRefractionReference&) = delete;
  void operator=(const vtkRefractionReference&) = delete;
};

#endif
