/* rf_dir_search.h: the ray / perspective-depth-map intersection of
 * Oliveira and Brauwers 2007 ("DIR"), sections 3.2-3.3, on the CPU: the checks of the public
 * API around the formulas of kernel/rf_kernel_dir.h, which the shaders run too.
 *
 * Everything is in view (camera) space with the OpenGL convention: the
 * camera sits at the origin looking down -z, so visible points have z < 0.
 * Depths are POSITIVE distances d = -z_view, as stored in the depth map. */
#ifndef RF_DIR_SEARCH_H
#define RF_DIR_SEARCH_H

#include "rf_validate.h"
#include "rf_vec3.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The search segment of one refracted ray T1 and its per-ray constants. */
typedef struct rf_dir_segment
{
  rf_vec3 S;    /* ray point on the plane z = -depth_min (eq. 3) */
  rf_vec3 E;    /* ray point on the plane z = -depth_max (eq. 4) */
  double k1;    /* 1 / S.z (eq. 9) */
  double k2;    /* S.z E.z / (S.z - E.z) (eq. 9) */
  double ts[2]; /* texture coordinates of S, t'_s (eq. 10) */
  double te[2]; /* texture coordinates of E, t'_e (eq. 10) */
} rf_dir_segment;

/* Builds the segment of the ray P1 + t T1 (T1 need not be unit) between the
 * depth planes (eq. 3-4), its constants k1, k2 (eq. 9) and the texture
 * coordinates of S and E (eq. 10). `projection` is the OpenGL perspective
 * projection as a 4x4 ROW-MAJOR matrix (element [row * 4 + col]) applied to
 * column vectors; eq. 8 assumes its w row is (0, 0, -1, 0).
 * Errors: RF_ERR_NULL_ARGUMENT; RF_ERR_NOT_FINITE (non-finite input or
 * projection, or depths so small or large that the eq. 9 constants overflow);
 * RF_ERR_EMPTY_RANGE (see rf_validate_depth_range, and
 * depth_min == depth_max); RF_ERR_DEGENERATE_DIRECTION (|T1.z| < 1e-12, or
 * T1.z > 0: the ray moves toward the camera and never reaches the range, or
 * S or E projects onto or behind the camera plane). On error *seg is left
 * unchanged. */
rf_status rf_dir_segment_init(rf_vec3 P1, rf_vec3 T1, double depth_min, double depth_max,
  const double projection[16], rf_dir_segment* seg);

/* Image-space interpolation parameter of the ray point with view-space z
 * coordinate Pz (negative), eq. 9: alpha = (1/Pz - k1) k2. 0 at S, 1 at E.
 * NaN when seg is NULL. */
double rf_dir_alpha(const rf_dir_segment* seg, double Pz);

/* Texture coordinates at alpha, eq. 10: (1 - alpha) t'_s + alpha t'_e.
 * Writes NaNs when seg is NULL; does nothing when tc is NULL. */
void rf_dir_texcoord(const rf_dir_segment* seg, double alpha, double tc[2]);

/* Returns the stored POSITIVE depth at texture coordinate tc, or 0 for an
 * empty texel (outside the object's silhouette). Called with tc in [0, 1]^2 only. */
typedef double (*rf_depth_sampler)(void* context, const double tc[2]);

/* Conservative binary search (Algorithm 2) along the segment alone, as rfk_dir_cbs of
 * kernel/rf_kernel_dir.h: starts at S and, halving the step each time, advances toward E only
 * while the candidate point lies in front of the stored depth; an empty texel (depth 0, and
 * any tc outside [0, 1]^2, which is not sampled) never lets the ray advance, so the result maps
 * to a valid texel whenever the search moved at all.
 * On RF_OK: *P2 is the estimate of the intersection, tc its texture coordinates (eq. 10) and
 * *beta its parameter along S-E (eq. 5). When the segment crosses the stored surface once,
 * inside the silhouette, beta lies below the crossing by at most rf_cbs_error_bound(steps).
 * `context` is passed through to `sample` (may be NULL); a NaN sample counts as empty.
 * The shader runs the whole of rf_dir_search below (which uses this loop).
 * Errors: RF_ERR_NULL_ARGUMENT, RF_ERR_STEPS_OUT_OF_RANGE. */
rf_status rf_dir_cbs(const rf_dir_segment* seg, int steps, rf_depth_sampler sample, void* context,
  rf_vec3* P2, double tc[2], double* beta);

/* The paper's bound on the CBS error in beta after `steps` steps: 0.5^steps
 * (section 3.3). 1.0 (the whole segment) for negative steps. */
double rf_cbs_error_bound(int steps);

/* Beyond the paper: one secant step inside the bracket the search ends with (the linear
 * refinement of relief mapping, Policarpo et al. 2005), as rfk_dir_secant. After rf_dir_cbs
 * with `steps` >= 1 steps the crossing lies between P2 (in front of the stored surface) and
 * P2 + (E - S) 0.5^steps; where both ends sample valid texels, the crossing of the linear
 * interpolation of (stored depth - ray depth) replaces P2, and only if its own texel is
 * valid (the search stays conservative). Exact for a back surface of constant depth. With 0
 * steps nothing changes (as in the shader). Updates P2, tc and beta in place. */
rf_status rf_dir_secant_refine(const rf_dir_segment* seg, int steps, rf_depth_sampler sample,
  void* context, rf_vec3* P2, double tc[2], double* beta);

/* The inputs of the whole exit search the shader runs (rf_dir_search). */
typedef struct rf_dir_search_input
{
  rf_vec3 P1;            /* the entry point, view space */
  rf_vec3 T1;            /* the refracted direction (need not be unit) */
  double depth_min;      /* Zmin, Zmax of the back surface as positive depths; */
  double depth_max;      /* depth_min > depth_max means nothing was captured */
  double projection[16]; /* view to clip, ROW-MAJOR as rf_dir_segment_init's */
  int viewport[2];       /* the depth map's size in texels (the viewport's) */
  int parallel;          /* non-zero: a parallel projection */
  int steps;             /* 0..RF_CBS_MAX_STEPS */
  int adaptive;          /* non-zero: no more steps than bring the bracket under half a texel */
  int secant;            /* non-zero: one secant step in the final bracket */
} rf_dir_search_input;

typedef struct rf_dir_search_result
{
  rf_vec3 P2;   /* the exit estimate (P1 when nothing was found) */
  double tc[2]; /* its texture coordinates */
  int found;    /* 0 when nothing was captured (depth_min > depth_max) */
} rf_dir_search_result;

/* DIR's exit search exactly as the shader runs it (rfk_dir_search of kernel/rf_kernel_dir.h):
 * eq. 3-4 clipped to the frustum, searched sideways from P1 when T1.z >= -1e-6 (parallel to the
 * image plane or toward the camera), started at P1 when S lies outside the silhouette or behind
 * P1, a point when Zmin = Zmax, then algorithm 2 with the adaptive bound and the secant step as
 * asked. `sample` receives tc in [0, 1]^2 and stands for a texelFetch of the nearest texel
 * (rf_texel_index of kernel/rf_kernel_prelude.h).
 * Errors: RF_ERR_NULL_ARGUMENT; RF_ERR_NOT_FINITE (a non-finite or NaN input, or inputs so
 * extreme that the result overflows); RF_ERR_DEGENERATE_DIRECTION (T1 zero);
 * RF_ERR_STEPS_OUT_OF_RANGE; RF_ERR_EMPTY_RANGE (a viewport below 1x1). On error *result is
 * left unchanged. */
rf_status rf_dir_search(const rf_dir_search_input* input, rf_depth_sampler sample, void* context,
  rf_dir_search_result* result);

#ifdef __cplusplus
}
#endif

#endif /* RF_DIR_SEARCH_H */
