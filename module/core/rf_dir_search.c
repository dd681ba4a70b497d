/* rf_dir_search.c: DIR ray / perspective-depth-map intersection
 * (Oliveira and Brauwers 2007, sections 3.2-3.3). */
#include "rf_dir_search.h"

#include <math.h>
#include <stddef.h>

/* Below this |T1.z| (of the unit direction) the ray is parallel to the image
 * plane: S and E of eq. 3-4 are at infinity. */
#define RF_DIR_MIN_DIRECTION_Z 1e-12

/* Relative size of S.z - E.z below which k2 (eq. 9) is meaningless. */
#define RF_DIR_MIN_RELATIVE_RANGE 1e-12

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

/* Projects a view-space point to [0,1]^2 texture coordinates as Algorithm 1:
 * clip = projection (p, 1), ndc = clip.xy / clip.w, t' = 0.5 ndc + 0.5. */
static rf_status project_to_texture(const double projection[16], rf_vec3 p, double tc[2])
{
  int row;
  double clip[4];
  for (row = 0; row < 4; ++row)
  {
    const double* m = projection + 4 * row;
    clip[row] = m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3];
  }
  /* w <= 0 puts the point on or behind the camera plane, where the
   * perspective division (and eq. 8's w = -z) no longer describes the image. */
  if (!(clip[3] > 0.0))
  {
    return isfinite(clip[3]) ? RF_ERR_DEGENERATE_DIRECTION : RF_ERR_NOT_FINITE;
  }
  tc[0] = 0.5 * (clip[0] / clip[3]) + 0.5;
  tc[1] = 0.5 * (clip[1] / clip[3]) + 0.5;
  return all_finite(tc, 2) ? RF_OK : RF_ERR_NOT_FINITE;
}

/* The point of the ray P1 + t T1 on the plane z = plane_z (eq. 3-4). */
static rf_vec3 ray_at_plane(rf_vec3 P1, rf_vec3 T1, double plane_z)
{
  rf_vec3 point = rf_vec3_add(P1, rf_vec3_scale(T1, (plane_z - P1.z) / T1.z));
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
  result.k2 = result.S.z * result.E.z / (result.S.z - result.E.z);
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
  /* eq. 9: eq. 8 solved for alpha; perspective makes alpha != beta (eq. 5). */
  return (1.0 / Pz - seg->k1) * seg->k2;
}

void rf_dir_texcoord(const rf_dir_segment* seg, double alpha, double tc[2])
{
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
  /* eq. 10, written as Algorithm 1's t'_s + alpha dt. */
  tc[0] = seg->ts[0] + alpha * (seg->te[0] - seg->ts[0]);
  tc[1] = seg->ts[1] + alpha * (seg->te[1] - seg->ts[1]);
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
  rf_vec3 position;
  rf_vec3 step;
  double step_beta = 1.0;
  double position_beta = 0.0;
  int i;
  rf_status status;
  status = rf_check_search_arguments(seg, steps, sample, P2, tc, beta);
  if (status != RF_OK)
  {
    return status;
  }

  /* Algorithm 2: P2 = S, dv = E - S. */
  position = seg->S;
  step = rf_vec3_sub(seg->E, seg->S);
  for (i = 0; i < steps; ++i)
  {
    double candidate_z;
    double candidate_tc[2];
    double stored_depth;
    step = rf_vec3_scale(step, 0.5);
    step_beta *= 0.5; /* beta of eq. 5 moves with dv: exact powers of two */
    candidate_z = position.z + step.z;
    rf_dir_texcoord(seg, rf_dir_alpha(seg, candidate_z), candidate_tc); /* eq. 9-10 */
    stored_depth = sample(context, candidate_tc);
    /* Advance only while the candidate is in front of the stored back
     * surface. Empty texels store 0, which no point in front of the camera
     * is nearer than, so the ray never advances across the silhouette: this
     * is what makes the search conservative (section 3.3). */
    if (-candidate_z < stored_depth)
    {
      position = rf_vec3_add(position, step);
      position_beta += step_beta;
    }
  }

  /* The loop's last texture coordinate may belong to a rejected candidate:
   * recompute it for the accepted point (bit-identical to the accepted
   * candidate's, since position.z is computed the same way). */
  *P2 = position;
  rf_dir_texcoord(seg, rf_dir_alpha(seg, position.z), tc);
  *beta = position_beta;
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
  rf_vec3 far_end;
  double far_tc[2];
  double refined_tc[2];
  double near_gap;
  double far_gap;
  double far_stored;
  double t;
  rf_vec3 refined;
  double bracket;
  rf_status status;
  status = rf_check_search_arguments(seg, steps, sample, P2, tc, beta);
  if (status != RF_OK)
  {
    return status;
  }
  bracket = ldexp(1.0, -steps);
  if (*beta + bracket > 1.0)
  {
    return RF_OK; /* the bracket would reach past E */
  }
  far_end = rf_vec3_add(*P2, rf_vec3_scale(rf_vec3_sub(seg->E, seg->S), bracket));
  rf_dir_texcoord(seg, rf_dir_alpha(seg, far_end.z), far_tc);
  far_stored = sample(context, far_tc);
  near_gap = sample(context, tc) - (-P2->z);
  far_gap = far_stored - (-far_end.z);
  /* A bracket across the surface has the gap change sign; an empty far texel (a silhouette,
   * not a crossing) gives no usable slope. */
  if (!(far_stored > 0.0) || !(near_gap > 0.0) || !(far_gap < 0.0))
  {
    return RF_OK;
  }
  t = near_gap / (near_gap - far_gap);
  refined = rf_vec3_add(*P2, rf_vec3_scale(rf_vec3_sub(far_end, *P2), t));
  rf_dir_texcoord(seg, rf_dir_alpha(seg, refined.z), refined_tc);
  if (!(sample(context, refined_tc) > 0.0))
  {
    return RF_OK;
  }
  *P2 = refined;
  tc[0] = refined_tc[0];
  tc[1] = refined_tc[1];
  *beta += t * bracket;
  return RF_OK;
}
