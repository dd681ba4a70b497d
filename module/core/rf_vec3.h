/* rf_vec3.h: a 3-vector of doubles and the handful of operations the
 * refraction core needs. Header-only so that the C core and the C++ render
 * pass share one definition without a link dependency. Written without
 * compound literals so the header also compiles as C++. */
#ifndef RF_VEC3_H
#define RF_VEC3_H

#include <math.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rf_vec3
{
  double x, y, z;
} rf_vec3;

static inline rf_vec3 rf_vec3_make(double x, double y, double z)
{
  rf_vec3 v;
  v.x = x;
  v.y = y;
  v.z = z;
  return v;
}

static inline rf_vec3 rf_vec3_add(rf_vec3 a, rf_vec3 b)
{
  return rf_vec3_make(a.x + b.x, a.y + b.y, a.z + b.z);
}

static inline rf_vec3 rf_vec3_sub(rf_vec3 a, rf_vec3 b)
{
  return rf_vec3_make(a.x - b.x, a.y - b.y, a.z - b.z);
}

static inline rf_vec3 rf_vec3_scale(rf_vec3 v, double s)
{
  return rf_vec3_make(v.x * s, v.y * s, v.z * s);
}

static inline double rf_vec3_dot(rf_vec3 a, rf_vec3 b)
{
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

static inline rf_vec3 rf_vec3_cross(rf_vec3 a, rf_vec3 b)
{
  return rf_vec3_make(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

static inline double rf_vec3_length(rf_vec3 v)
{
  return sqrt(rf_vec3_dot(v, v));
}

static inline int rf_vec3_is_finite(rf_vec3 v)
{
  return isfinite(v.x) && isfinite(v.y) && isfinite(v.z);
}

/* Unit vector along v, or the zero vector when v is zero or not finite, so
 * callers test rf_vec3_length(result) > 0 instead of receiving NaNs.
 * Dividing by the largest component first (not multiplying by its
 * reciprocal, which overflows for subnormals) keeps the squared length from
 * overflowing (or underflowing to zero) for very large (small) inputs. */
static inline rf_vec3 rf_vec3_normalize(rf_vec3 v)
{
  const rf_vec3 zero = rf_vec3_make(0.0, 0.0, 0.0);
  double largest;
  double length;
  rf_vec3 scaled;
  if (!rf_vec3_is_finite(v))
  {
    return zero;
  }
  largest = fmax(fabs(v.x), fmax(fabs(v.y), fabs(v.z)));
  if (!(largest > 0.0))
  {
    return zero;
  }
  scaled = rf_vec3_make(v.x / largest, v.y / largest, v.z / largest);
  length = rf_vec3_length(scaled);
  return rf_vec3_scale(scaled, 1.0 / length);
}

#ifdef __cplusplus
}
#endif

#endif /* RF_VEC3_H */
