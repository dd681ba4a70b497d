/* rf_tracer.h: the reference ray tracer (ground truth for the GPU refraction methods).
 *
 * It renders glass meshes over the environment with Embree 3 on the CPU, with the camera
 * VTK gives the GPU (view and projection matrices), so that every pixel can be compared
 * with what vtkRefractionPass draws (DESIGN.md, sections 4 and 5). Two modes:
 *
 *  - RF_TRACE_TWO_INTERFACE: the exact counterpart of the GPU's per-pixel formula
 *    (shaders/rfRefractionFS.glsl), with the TRUE exit point instead of DIR's depth-map
 *    search (Oliveira & Brauwers 2007, section 3):
 *      P1, N1 = nearest hit and its interpolated normal (facing the viewer),
 *      F  = rf_fresnel_dielectric(-dot(V, N1), 1/ior)      (0 with fresnel off),
 *      R  = reflect(V, N1),  T1 = refract(V, N1, 1/ior)    (TIR policy as below),
 *      P2 = first intersection of P1 + t T1 (t > epsilon) with the glass, N2 its normal,
 *      T2 = refract(T1, -N2, ior) with the TIR policy: tir_clamp = 1 clamps the
 *           transmission angle to the critical angle (the paper's section 5,
 *           rf_refract_clamped), tir_clamp = 0 reflects once (rf_refract),
 *      colour = F env(R) + (1 - F) exp(-absorption |P2 - P1|) env(T2).
 *    The absorption factor is 1 for clear glass (absorption 0), which is what the GPU draws.
 *    A refracted ray that finds no exit (an open mesh) leaves with T2 = T1 and P2 = P1.
 *  - RF_TRACE_FULL: Whitted recursion. Every interface splits the ray into reflection and
 *    transmission by the exact Fresnel term, TIR reflects (no clamp), light inside glass
 *    is attenuated by exp(-absorption * distance) per channel (Beer-Lambert), rays that
 *    leave take env(direction). A path ends after max_depth interfaces, or when its weight
 *    falls below RF_TRACE_MIN_WEIGHT; it then continues straight into the environment
 *    (the dropped energy is below that weight times the environment's brightest value).
 *
 * Coordinates: meshes are in WORLD space; the per-pixel outputs p1, p2 and t2 are in VIEW
 * space, as the GPU's debug output. The environment is looked up with WORLD directions.
 * Images: pixel (i, j), row j = 0 at the BOTTOM (as VTK images and glReadPixels), is
 * element j * width + i. Pixel centres are where OpenGL rasterizes them: NDC
 * ((i + 0.5) / W * 2 - 1, (j + 0.5) / H * 2 - 1). The primary ray runs from the near plane
 * to the far plane through that pixel (perspective: on the line through the eye), so glass
 * outside the clipping range is not seen, as on the GPU. */
#ifndef RF_TRACER_H
#define RF_TRACER_H

#include "rf_reference_status.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Paths of the full mode whose weight (largest channel) drops below this are not split any
 * further. 1e-4 is 40 times below one step of the 8-bit images the GPU writes. */
#define RF_TRACE_MIN_WEIGHT 1e-4
/* Largest accepted max_depth (the recursion uses the C stack). */
#define RF_TRACE_MAX_DEPTH_LIMIT 64
/* Largest accepted samples_per_side (1024 rays per pixel: the benchmark's --convergence traces
 * its truth at twice the sides of --supersample 16, to see whether 16 x 16 has converged). */
#define RF_TRACE_MAX_SAMPLES_PER_SIDE 32

/* One glass object. Triangles index positions (and normals, when given). */
typedef struct rf_mesh
{
  const float* positions;   /* xyz per vertex, WORLD space */
  const float* normals;     /* xyz per vertex (WORLD space), or NULL: geometric normals */
  size_t vertex_count;
  const unsigned* triangles; /* 3 vertex indices per triangle */
  size_t triangle_count;
  double ior;               /* index of refraction, finite and > 0 */
  double absorption[3];     /* Beer-Lambert coefficients per unit length, >= 0; 0 = clear */
} rf_mesh;

/* How an opaque surface is coloured: what VTK 9.1's polydata mapper draws with the renderer's
 * default light, a headlight of intensity 1 with two-sided lighting (light complexity 1 in
 * vtkOpenGLPolyDataMapper). With N the surface normal (flipped on faces whose winding turns
 * away from the camera, as VTK flips it on back faces) and n_z its component along the view
 * axis (toward the viewer; VTK's headlight shines along the view axis at every point, not
 * from the camera position):
 *   lit:   ambient Ca + diffuse Cd max(n_z, 0) + specular Cs max(n_z, 0)^specular_power
 *   unlit: ambient Ca + diffuse Cd                        (VTK with lighting off)
 * Ca and Cd are replaced by a mesh's scalar colour where it has one (VTK's default scalar
 * material mode). Every channel is clamped to [0, 1], as the 8-bit framebuffer holds it. */
typedef struct rf_opaque_material
{
  int lighting;          /* 1: lit by the headlight; 0: the plain colour */
  double ambient;        /* vtkProperty's Ambient, Diffuse, Specular, SpecularPower */
  double diffuse;
  double specular;
  double specular_power;
  double ambient_colour[3]; /* linear RGB in [0, 1], as VTK hands them to GL */
  double diffuse_colour[3];
  double specular_colour[3];
} rf_opaque_material;

typedef enum rf_colour_binding
{
  RF_COLOUR_MATERIAL = 0,     /* no scalar colours: the material's colours */
  RF_COLOUR_PER_VERTEX = 1,   /* interpolated barycentrically (point scalars) */
  RF_COLOUR_PER_TRIANGLE = 2  /* flat (cell scalars) */
} rf_colour_binding;

/* One opaque object: the scene around the glass. It stops every ray that meets it (primary,
 * reflected or leaving the glass) with its colour, as the pass's capture of the opaque scene
 * shows it. Triangles index positions (and normals, when given). */
typedef struct rf_opaque_mesh
{
  const float* positions;    /* xyz per vertex, WORLD space (the glass meshes' frame) */
  const float* normals;      /* xyz per vertex (WORLD space), or NULL: geometric normals */
  size_t vertex_count;
  const unsigned* triangles; /* 3 vertex indices per triangle */
  size_t triangle_count;
  rf_colour_binding colour_binding;
  const float* colours;      /* rgb in [0, 1] per vertex or per triangle (colour_binding),
                                NULL with RF_COLOUR_MATERIAL */
  rf_opaque_material material;
} rf_opaque_mesh;

typedef struct rf_camera
{
  double view[16];       /* world -> view, row-major (vtkCamera::GetViewTransformMatrix) */
  double projection[16]; /* view -> clip, row-major
                            (vtkCamera::GetProjectionTransformMatrix(width/height, -1, 1)) */
  int width, height;     /* pixels, > 0 */
} rf_camera;

typedef enum rf_trace_mode
{
  RF_TRACE_TWO_INTERFACE = 0,
  RF_TRACE_FULL = 1
} rf_trace_mode;

/* Environment radiance for a WORLD direction (not necessarily unit); rgb out. Called from
 * every worker thread at once: it must be safe for that (a pure function of its inputs). */
typedef void (*rf_environment_fn)(const double direction_world[3], double rgb[3], void* user);

/* Progress of a trace, fraction in [0, 1]; called on the thread that called rf_trace only. */
typedef void (*rf_progress_fn)(double fraction, void* user);

typedef struct rf_trace_options
{
  rf_trace_mode mode;
  int tir_clamp; /* two-interface mode: 1 clamps to the critical angle (paper), 0 reflects */
  int max_depth; /* full mode: interfaces per path, 1..RF_TRACE_MAX_DEPTH_LIMIT */
  int fresnel;   /* 1: blend by the exact Fresnel term; 0: transmission only (TIR still
                    reflects) */
  int threads;   /* worker threads (rows are interleaved over them), >= 1 */
  rf_environment_fn environment; /* NULL: rf_builtin_environment */
  void* environment_user;        /* passed to environment */
  /* Anti-aliased truth: 1 shades the pixel centre (what the pass shades); N > 1 shades an
   * N x N grid of sub-pixel positions ((i + (a + 0.5) / N, j + (b + 0.5) / N)) and averages
   * their colours, as a camera integrates over the pixel. 1..RF_TRACE_MAX_SAMPLES_PER_SIDE. */
  int samples_per_side;
  /* The colour of sub-samples that see no glass (the renderer's background); only used when
   * samples_per_side > 1 (with one sample a pixel without glass is 0, as before). */
  double background[3];
  rf_progress_fn progress; /* NULL: none; called after each row of the calling thread */
  void* progress_user;     /* passed to progress */
} rf_trace_options;

/* Per-pixel results; every array is optional (NULL: not written) except as noted.
 *  colour     3 floats, linear RGB, 0 where nothing is seen; an opaque surface's colour
 *             where the primary ray meets one before any glass; with samples_per_side > 1
 *             the average over the sub-samples (the background where they miss everything);
 *  coverage   share of the sub-samples that see glass (with one sample: hit);
 *  p1, p2, t2 3 floats, VIEW space: entry point, exit point, exit direction (unit);
 *  thickness  |P2 - P1| (two-interface), length travelled inside glass (full);
 *  bounces    interfaces on the (dominant) path; 0 where no glass is seen;
 *  tir        1 where TIR occurred at the exit (two-interface) or on the dominant path (full);
 *  hit        1 where glass is seen;
 *  opaque     1 where an opaque surface is seen in front of any glass (hit is then 0).
 * Everything but colour and coverage is the pixel centre's, whatever samples_per_side.
 * In the full mode p2, t2, thickness, bounces and tir describe the dominant path, the one
 * that transmits at every interface where it can (reflects only under TIR): the path the
 * two-interface model approximates. p2 is where it last leaves the glass, t2 its
 * direction into the environment. Where no glass is seen all values are 0. */
typedef struct rf_trace_image
{
  int width, height;
  float* colour;
  float* coverage;
  float* p1;
  float* p2;
  float* t2;
  float* thickness;
  int* bounces;
  unsigned char* tir;
  unsigned char* hit;
  unsigned char* opaque;
} rf_trace_image;

/* Defaults: two-interface, tir_clamp 1 (the paper), max_depth 8, fresnel 1, threads 2,
 * the built-in environment, one sample per pixel, black background, no progress. */
RF_REFERENCE_EXPORT rf_status rf_trace_options_default(rf_trace_options* options);

/* Allocates every array of img for w x h pixels, zeroed. On failure img holds no memory.
 * Errors: RF_ERR_NULL_ARGUMENT, RF_REF_ERR_BAD_OPTION (w or h <= 0 or too large),
 * RF_REF_ERR_OUT_OF_MEMORY. */
RF_REFERENCE_EXPORT rf_status rf_trace_image_alloc(rf_trace_image* img, int w, int h);
/* Frees what rf_trace_image_alloc allocated and zeroes img; NULL is a no-op. */
RF_REFERENCE_EXPORT void rf_trace_image_free(rf_trace_image* img);

/* Renders the meshes (all glass; a mesh with no triangles is skipped) into out, whose size
 * must be the camera's. Errors: RF_ERR_NULL_ARGUMENT, RF_ERR_NOT_FINITE (a position,
 * normal, matrix entry or absorption), RF_ERR_IOR_NOT_POSITIVE, RF_ERR_ABSORPTION_NEGATIVE,
 * RF_REF_ERR_INDEX_OUT_OF_RANGE, RF_REF_ERR_BAD_OPTION, RF_REF_ERR_OUT_OF_MEMORY,
 * RF_REF_ERR_EMBREE. On error out's contents are unspecified. */
RF_REFERENCE_EXPORT rf_status rf_trace(const rf_mesh* meshes, size_t mesh_count,
  const rf_camera* camera, const rf_trace_options* options, rf_trace_image* out);

/* rf_trace with opaque objects around the glass (rf_opaque_mesh): rays that meet one end
 * there with its colour (rf_opaque_shade). In the two-interface mode the rays leaving the
 * glass (T2 from P2, and the reflection R from P1) look for opaque surfaces only, as the
 * pass looks for them in its capture of the opaque scene; in the full mode every ray meets
 * whichever comes first. Errors as rf_trace, and for an opaque mesh: RF_ERR_NOT_FINITE (a
 * position, normal, colour or material value), RF_REF_ERR_BAD_OPTION (a colour binding
 * without colours or an unknown one, a colour or material value outside its range). */
RF_REFERENCE_EXPORT rf_status rf_trace_scene(const rf_mesh* meshes, size_t mesh_count,
  const rf_opaque_mesh* opaque, size_t opaque_count, const rf_camera* camera,
  const rf_trace_options* options, rf_trace_image* out);

/* The colour of an opaque surface point (the formula of rf_opaque_material): base_colour is
 * the scalar colour there, or NULL for the material's own; normal_view_z is the unit
 * normal's component toward the viewer along the view axis, after the two-sided flip. */
RF_REFERENCE_EXPORT void rf_opaque_shade(const rf_opaque_material* material,
  const double* base_colour, double normal_view_z, double rgb[3]);

#ifdef __cplusplus
}
#endif

#endif /* RF_TRACER_H */
