/* rf_kernel_octahedral.h (kernel dialect, C and GLSL): unit normals in two numbers, for a
 * G-buffer. The octahedral mapping (Meyer et al. 2010, "On floating-point normal vectors";
 * survey: Cigolle et al. 2014, JCGT 3(2)): project onto the octahedron |x| + |y| + |z| = 1,
 * fold the lower half (z < 0) over the upper one, keep (x, y) in [-1, 1]^2. */
#ifndef RF_KERNEL_OCTAHEDRAL_H
#define RF_KERNEL_OCTAHEDRAL_H

#ifndef RF_GLSL
#include "rf_kernel_prelude.h"
#endif

/* The lower half's fold: (1 - |p.yx|) sign(p), sign never 0 so the seam maps consistently. */
RF_KERNEL rf_float2 rfk_oct_fold(rf_float2 p)
{
  return rf_make2((1.0 - rf_abs(p.y)) * rf_sign_not_zero(p.x),
    (1.0 - rf_abs(p.x)) * rf_sign_not_zero(p.y));
}

/* A non-zero normal (need not be unit) to [-1, 1]^2; a zero or non-finite one to (0, 0), which
 * decodes to +z (the G-buffer marks empty texels by their depth, not by the normal). */
RF_KERNEL rf_float2 rf_oct_encode(rf_float3 n)
{
  rf_float l1 = rf_abs(n.x) + rf_abs(n.y) + rf_abs(n.z);
  if (!(l1 > 0.0) || rf_isinf(l1))
  {
    return rf_make2(0.0, 0.0);
  }
  rf_float2 p = rf_make2(n.x / l1, n.y / l1);
  return n.z < 0.0 ? rfk_oct_fold(p) : p;
}

/* [-1, 1]^2 back to the unit normal. */
RF_KERNEL rf_float3 rf_oct_decode(rf_float2 e)
{
  rf_float z = 1.0 - rf_abs(e.x) - rf_abs(e.y);
  rf_float2 p = z < 0.0 ? rfk_oct_fold(e) : e;
  return rf_normalize3(rf_make3(p.x, p.y, z));
}

#endif /* RF_KERNEL_OCTAHEDRAL_H */
