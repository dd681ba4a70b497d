/* rf_tracer_camera.c: the camera's matrices and the primary rays (see rf_tracer_camera.h). */
#include "rf_tracer_camera.h"

#include "rf_tracer_full.h"
#include "rf_tracer_two_interface.h"

#include <string.h>

/* Gauss-Jordan with partial pivoting; returns 0 for a singular matrix. */
int rf_mat4_invert(const double m[16], double inverse[16])
{
  double a[4][8];
  int r;
  int c;
  int k;
  for (r = 0; r < 4; ++r)
  {
    for (c = 0; c < 4; ++c)
    {
      a[r][c] = m[r * 4 + c];
      a[r][c + 4] = (r == c) ? 1.0 : 0.0;
    }
  }
  for (k = 0; k < 4; ++k)
  {
    int pivot = k;
    double scale;
    for (r = k + 1; r < 4; ++r)
    {
      if (fabs(a[r][k]) > fabs(a[pivot][k]))
      {
        pivot = r;
      }
    }
    if (!(fabs(a[pivot][k]) > 0.0))
    {
      return 0;
    }
    if (pivot != k)
    {
      for (c = 0; c < 8; ++c)
      {
        const double t = a[k][c];
        a[k][c] = a[pivot][c];
        a[pivot][c] = t;
      }
    }
    scale = 1.0 / a[k][k];
    for (c = 0; c < 8; ++c)
    {
      a[k][c] *= scale;
    }
    for (r = 0; r < 4; ++r)
    {
      if (r != k && a[r][k] != 0.0)
      {
        const double f = a[r][k];
        for (c = 0; c < 8; ++c)
        {
          a[r][c] -= f * a[k][c];
        }
      }
    }
  }
  for (r = 0; r < 4; ++r)
  {
    for (c = 0; c < 4; ++c)
    {
      inverse[r * 4 + c] = a[r][c + 4];
      if (!isfinite(inverse[r * 4 + c]))
      {
        return 0;
      }
    }
  }
  return 1;
}

/* m * (x, y, z, w) followed by the homogeneous divide. */
static rf_vec3 rf_mat4_project(const double m[16], double x, double y, double z, double w)
{
  const double h[4] = { x, y, z, w };
  double o[4];
  int r;
  for (r = 0; r < 4; ++r)
  {
    o[r] = m[r * 4 + 0] * h[0] + m[r * 4 + 1] * h[1] + m[r * 4 + 2] * h[2] + m[r * 4 + 3] * h[3];
  }
  return rf_vec3_make(o[0] / o[3], o[1] / o[3], o[2] / o[3]);
}

rf_vec3 rf_mat4_point(const double m[16], rf_vec3 p)
{
  return rf_mat4_project(m, p.x, p.y, p.z, 1.0);
}

/* The linear part applied to a direction, renormalized (a view transform is rigid; the
 * renormalization only removes rounding). */
rf_vec3 rf_mat4_direction(const double m[16], rf_vec3 d)
{
  return rf_vec3_normalize(rf_vec3_make(m[0] * d.x + m[1] * d.y + m[2] * d.z,
    m[4] * d.x + m[5] * d.y + m[6] * d.z, m[8] * d.x + m[9] * d.y + m[10] * d.z));
}

/* Shades the primary ray through NDC (x, y): from the near plane to the far plane. */
void rf_trace_primary(const rf_tracer* tr, double x, double y, rf_pixel* px)
{
  const rf_vec3 near_view = rf_mat4_project(tr->clip_to_view, x, y, -1.0, 1.0);
  const rf_vec3 far_view = rf_mat4_project(tr->clip_to_view, x, y, 1.0, 1.0);
  const rf_vec3 near_world = rf_mat4_point(tr->view_to_world, near_view);
  const rf_vec3 far_world = rf_mat4_point(tr->view_to_world, far_view);
  const rf_vec3 span = rf_vec3_sub(far_world, near_world);
  const rf_vec3 dir = rf_vec3_normalize(span);
  memset(px, 0, sizeof(*px));
  if (rf_vec3_length(dir) > 0.0)
  {
    if (tr->options->mode == RF_TRACE_FULL)
    {
      rf_shade_full(tr, near_world, dir, rf_vec3_length(span), px);
    }
    else
    {
      rf_shade_two_interface(tr, near_world, dir, rf_vec3_length(span), px);
    }
  }
}
