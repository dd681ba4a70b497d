/* rf_dir_search.c: DIR ray / perspective-depth-map intersection
 * (Oliveira and Brauwers 2007, sections 3.2-3.3): validation around kernel/rf_kernel_dir.h. */
#include "rf_dir_search.h"

#include "kernel/rf_kernel_dir.h"

#include <math.h>
#include <stddef.h>

/* Below this |T1.z| (of the unit direction) the ray is parallel to the image
 * plane: S and E of eq. 3-4 are at infinity. */
#define RF_DIR_MIN_DIRECTION_Z 1e-12

/* Relative size of S.z - E.z below which k2 (eq. 9) is meaningless. */
#define RF_DIR_MIN_RELATIVE_RANGE 1e-12

#if RF_KERNEL_MAX_SEARCH_STEPS != RF_CBS_MAX_STEPS
#error "the kernel's step cap and the validated step range disagree"
#endif

static rf_mat4 matrix_of(const double projection[16])
{
  rf_mat4 m;
  int i;
  for (i = 0; i < 16; ++i)
  {
    m.m[i] = projection[i];
  }
  return m;
}

/* The camera of a public call: the projection; a C sampler needs no viewport size. */
static rfk_camera camera_of(const double projection[16])
{
  return rfk_make_camera(matrix_of(projection), rf_make2(1.0, 1.0), RF_FALSE);
}

/* The public segment as the kernel's (k2 as computed, so never affine). */
static rfk_dir_segment kernel_segment(const rf_dir_segment* seg)
{
  rfk_dir_segment k;
  k.S = seg->S;
  k.dv = rf_sub3(seg->E, seg->S);
  k.ts = rf_make2(seg->ts[0], seg->ts[1]);
  k.dt = rf_make2(seg->te[0] - seg->ts[0], seg->te[1] - seg->ts[1]);
  k.k1 = seg->k1;
  k.k2 = seg->k2;
  k.affine = RF_FALSE;
  return k;
}

static rf_depth_map depth_map_of(rf_depth_sampler sample, void* context)
{
  rf_depth_map map;
  map.sample = sample;
  map.context = context;
  return map;
}

static int all_finite(const double* values, int count)
{
  int i;
  for (i = 0; i < count; ++i)
  {
    if (!isfinite(values[i]))
    {
      return 0;
    }
  }
  return 1;
}

/* Projects a view-space point to [0,1]^2 texture coordinates (rfk_texture_of_clip), refusing
 * points on or behind the camera plane, where the perspective division (and eq. 8's w = -z)
 * no longer describes the image. */
static rf_status project_to_texture(const double projection[16], rf_vec3 p, double tc[2])
{
  const rf_float4 clip = rfk_clip_of(camera_of(projection), p);
  rf_float2 t;
  if (!(clip.w > 0.0))
  {
    return isfinite(clip.w) ? RF_ERR_DEGENERATE_DIRECTION : RF_ERR_NOT_FINITE;
  }
  t = rfk_texture_of_clip(clip);
  tc[0] = t.x;
  tc[1] = t.y;
  return all_finite(tc, 2) ? RF_OK : RF_ERR_NOT_FINITE;
}

/* The point of the ray P1 + t T1 on the plane z = plane_z (eq. 3-4). */
static rf_vec3 ray_at_plane(rf_vec3 P1, rf_vec3 T1, double plane_z)
{
  rf_vec3 point = rf_add3(P1, rf_scale3(T1, rfk_ray_plane_parameter(P1, T1, plane_z)));
  /* Exactly on the plane by construction; remove the rounding so that
   * alpha (eq. 9) is exactly 0 at S and 1 at E. */
  point.z = plane_z;
  return point;
}

rf_status rf_dir_segment_init(rf_vec3 P1, rf_vec3 T1, double depth_min, double depth_max,
  const double projection[16], rf_dir_segment* seg)
{
  rf_dir_segment result;
  rf_vec3 unit_direction;
  rf_status status;
  double z_min;
  double z_max;
  if (projection == NULL || seg == NULL)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  if (!rf_vec3_is_finite(P1) || !rf_vec3_is_finite(T1) || !all_finite(projection, 16))
  {
    return RF_ERR_NOT_FINITE;
  }
  status = rf_validate_depth_range(depth_min, depth_max);
  if (status != RF_OK)
  {
    return status;
  }
  /* Equal depths make S == E and k2 (eq. 9) divide by zero. */
  if (depth_max - depth_min <= RF_DIR_MIN_RELATIVE_RANGE * depth_max)
  {
    return RF_ERR_EMPTY_RANGE;
  }
  unit_direction = rf_vec3_normalize(T1);
  if (fabs(unit_direction.z) < RF_DIR_MIN_DIRECTION_Z)
  {
    return RF_ERR_DEGENERATE_DIRECTION;
  }
  /* T1.z > 0 moves toward the camera: the search from S (near) to E (far)
   * would run against the ray, i.e. behind P1. */
  if (unit_direction.z > 0.0)
  {
    return RF_ERR_DEGENERATE_DIRECTION;
  }

  /* Camera-space planes: depths are positive distances, z = -depth. */
  z_min = -depth_min;
  z_max = -depth_max;
  result.S = ray_at_plane(P1, unit_direction, z_min); /* eq. 3 */
  result.E = ray_at_plane(P1, unit_direction, z_max); /* eq. 4 */
  if (!rf_vec3_is_finite(result.S) || !rf_vec3_is_finite(result.E))
  {
    return RF_ERR_NOT_FINITE;
  }
  /* eq. 9 constants; S.z - E.z = depth_max - depth_min > 0 here. */
  result.k1 = 1.0 / result.S.z;
  result.k2 = rfk_dir_k2(result.S.z, result.E.z);
  /* A subnormal depth makes 1 / S.z overflow, huge depths S.z E.z: eq. 9 would then give
   * infinite or NaN parameters (found by fuzzing, tests/fuzz). */
  if (!isfinite(result.k1) || !isfinite(result.k2))
  {
    return RF_ERR_NOT_FINITE;
  }

  status = project_to_texture(projection, result.S, result.ts);
  if (status != RF_OK)
  {
    return status;
  }
  status = project_to_texture(projection, result.E, result.te);
  if (status != RF_OK)
  {
    return status;
  }
  *seg = result;
  return RF_OK;
}

double rf_dir_alpha(const rf_dir_segment* seg, double Pz)
{
  if (seg == NULL)
  {
    return NAN;
  }
  return rfk_dir_alpha(seg->k1, seg->k2, Pz);
}

void rf_dir_texcoord(const rf_dir_segment* seg, double alpha, double tc[2])
{
  rf_float2 t;
  if (tc == NULL)
  {
    return;
  }
  if (seg == NULL)
  {
    tc[0] = NAN;
    tc[1] = NAN;
    return;
  }
  t = rfk_dir_texcoord(kernel_segment(seg), alpha);
  tc[0] = t.x;
  tc[1] = t.y;
}

/* The arguments rf_dir_cbs and rf_dir_secant_refine share. */
static rf_status rf_check_search_arguments(const rf_dir_segment* seg, int steps,
  rf_depth_sampler sample, const rf_vec3* P2, const double* tc, const double* beta)
{
  if (seg == NULL || sample == NULL || P2 == NULL || tc == NULL || beta == NULL)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  return rf_validate_cbs_steps(steps);
}

rf_status rf_dir_cbs(const rf_dir_segment* seg, int steps, rf_depth_sampler sample, void* context,
  rf_vec3* P2, double tc[2], double* beta)
{
  rfk_dir_segment k;
  double bracket;
  rf_status status;
  status = rf_check_search_arguments(seg, steps, sample, P2, tc, beta);
  if (status != RF_OK)
  {
    return status;
  }
  k = kernel_segment(seg);
  *P2 = rfk_dir_cbs(k, steps, depth_map_of(sample, context), rf_make2(1.0, 1.0), beta, &bracket);
  /* eq. 10 at the accepted point: the texel the search accepted it on. */
  rf_dir_texcoord(seg, rfk_dir_alpha(k.k1, k.k2, P2->z), tc);
  return RF_OK;
}

double rf_cbs_error_bound(int steps)
{
  if (steps < 0)
  {
    return 1.0;
  }
  /* section 3.3: beta_error <= 0.5^c. */
  return ldexp(1.0, -steps);
}

rf_status rf_dir_secant_refine(const rf_dir_segment* seg, int steps, rf_depth_sampler sample,
  void* context, rf_vec3* P2, double tc[2], double* beta)
{
  rf_float2 t;
  rf_status status;
  status = rf_check_search_arguments(seg, steps, sample, P2, tc, beta);
  if (status != RF_OK)
  {
    return status;
  }
  t = rf_make2(tc[0], tc[1]);
  rfk_dir_secant(kernel_segment(seg), steps, rf_cbs_error_bound(steps),
    depth_map_of(sample, context), rf_make2(1.0, 1.0), P2, &t, beta);
  tc[0] = t.x;
  tc[1] = t.y;
  return RF_OK;
}

rf_status rf_dir_search(const rf_dir_search_input* input, rf_depth_sampler sample, void* context,
  rf_dir_search_result* result)
{
  rf_vec3 unit_direction;
  rf_vec3 P2;
  rf_float2 tc;
  rfk_camera camera;
  int found;
  rf_status status;
  if (input == NULL || sample == NULL || result == NULL)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  if (!rf_vec3_is_finite(input->P1) || !rf_vec3_is_finite(input->T1) ||
    !all_finite(input->projection, 16) || !isfinite(input->depth_min) ||
    !isfinite(input->depth_max))
  {
    return RF_ERR_NOT_FINITE;
  }
  status = rf_validate_cbs_steps(input->steps);
  if (status != RF_OK)
  {
    return status;
  }
  if (input->viewport[0] < 1 || input->viewport[1] < 1)
  {
    return RF_ERR_EMPTY_RANGE;
  }
  unit_direction = rf_vec3_normalize(input->T1);
  if (!(rf_vec3_length(unit_direction) > 0.0))
  {
    return RF_ERR_DEGENERATE_DIRECTION;
  }
  camera = rfk_make_camera(matrix_of(input->projection),
    rf_make2((double)input->viewport[0], (double)input->viewport[1]), input->parallel != 0);
  found = rfk_dir_search(input->P1, unit_direction, rf_make2(input->depth_min, input->depth_max),
    camera,
    rfk_make_search_settings(input->steps, input->adaptive != 0, input->secant != 0),
    depth_map_of(sample, context), &P2, &tc);
  if (!rf_vec3_is_finite(P2) || !isfinite(tc.x) || !isfinite(tc.y))
  {
    return RF_ERR_NOT_FINITE;
  }
  result->P2 = P2;
  result->tc[0] = tc.x;
  result->tc[1] = tc.y;
  result->found = found;
  return RF_OK;
}
