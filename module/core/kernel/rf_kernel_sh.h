/* rf_kernel_sh.h (kernel dialect, C and GLSL): real spherical harmonics up to order
 * RF_SH_MAX_ORDER, for the SH method (Genevaux et al., seed 003): per vertex, the direction in
 * which light leaves the glass and the length it travelled inside, as functions of the
 * incoming direction, are projected on this basis when the mesh is prepared and evaluated at
 * render time.
 *
 * Y_l^m for l = 0..L, m = -l..l at index l (l + 1) + m; (L + 1)^2 coefficients. Real form
 * without the Condon-Shortley phase (Y_1^1 = 0.488603 x, as in graphics):
 *   m > 0: sqrt(2) K_l^m Q_l^m(z) Re((x + i y)^m),  m < 0: sqrt(2) K_l^|m| Q_l^|m|(z)
 *   Im((x + i y)^|m|),  m = 0: K_l^0 Q_l^0(z),
 * K_l^m = sqrt((2l + 1) / (4 pi) (l - m)! / (l + m)!), and Q_l^m the associated Legendre
 * function divided by sin^m(theta) (the sin^m goes into (x + i y)^m, so nothing divides by
 * it at the poles): Q_m^m = (2m - 1)!!, Q_{m+1}^m = (2m + 1) z Q_m^m,
 * Q_l^m = ((2l - 1) z Q_{l-1}^m - (l + m - 1) Q_{l-2}^m) / (l - m). The direction is unit.
 *
 * The coefficients of a sum are read through rf_sh_coefficient(table, i), which the
 * including side provides (C: an array; GLSL: a texture the stage reads). */
#ifndef RF_KERNEL_SH_H
#define RF_KERNEL_SH_H

#ifndef RF_GLSL
#include "rf_kernel_prelude.h"
#endif

#define RF_SH_MAX_ORDER 8
#define RF_SH_PI 3.14159265358979323846

/* The number of coefficients of order L: (L + 1)^2. */
RF_KERNEL int rfk_sh_count(int order)
{
  return (order + 1) * (order + 1);
}

/* K_l^m (m >= 0), the factorial ratio by a product: (l - m)! / (l + m)! =
 * 1 / ((l - m + 1) (l - m + 2) ... (l + m)). */
RF_KERNEL rf_float rfk_sh_normalization(int l, int m)
{
  rf_float ratio = 1.0;
  for (int k = l - m + 1; k <= l + m; ++k)
  {
    ratio = ratio / rf_float_of(k);
  }
  return rf_sqrt(rf_float_of(2 * l + 1) / (4.0 * RF_SH_PI) * ratio);
}

/* One basis function Y_l^m at the unit direction d (|m| <= l <= RF_SH_MAX_ORDER). */
RF_KERNEL rf_float rfk_sh_basis(int l, int m, rf_float3 d)
{
  int a = m < 0 ? -m : m;
  /* (x + i y)^a and Q_a^a = (2a - 1)!! */
  rf_float re = 1.0;
  rf_float im = 0.0;
  rf_float q = 1.0;
  for (int k = 1; k <= a; ++k)
  {
    rf_float nextRe = re * d.x - im * d.y;
    im = re * d.y + im * d.x;
    re = nextRe;
    q = q * rf_float_of(2 * k - 1);
  }
  /* Q_l^a upward from Q_a^a. */
  rf_float before = 0.0;
  for (int n = a + 1; n <= l; ++n)
  {
    rf_float next = (rf_float_of(2 * n - 1) * d.z * q - rf_float_of(n + a - 1) * before) /
      rf_float_of(n - a);
    before = q;
    q = next;
  }
  rf_float k = rfk_sh_normalization(l, a);
  if (m == 0)
  {
    return k * q;
  }
  return 1.41421356237309504880 * k * q * (m > 0 ? re : im);
}

#if !defined(RF_GLSL) || defined(RF_SH_TABLE)
/* The sum of coefficients table[base + i] times Y_i over the order-L basis at the unit
 * direction d: every (l, m) in one sweep over m, each Q_l^m by the recurrence in l. */
RF_KERNEL rf_float rfk_sh_evaluate(rf_sh_table table, int base, int order, rf_float3 d)
{
  rf_float sum = 0.0;
  rf_float re = 1.0;  /* Re((x + i y)^m) */
  rf_float im = 0.0;  /* Im((x + i y)^m) */
  rf_float qmm = 1.0; /* Q_m^m = (2m - 1)!! */
  for (int m = 0; m <= order; ++m)
  {
    if (m > 0)
    {
      rf_float nextRe = re * d.x - im * d.y;
      im = re * d.y + im * d.x;
      re = nextRe;
      qmm = qmm * rf_float_of(2 * m - 1);
    }
    rf_float before = 0.0;
    rf_float q = qmm;
    for (int l = m; l <= order; ++l)
    {
      if (l > m)
      {
        rf_float next =
          (rf_float_of(2 * l - 1) * d.z * q - rf_float_of(l + m - 1) * before) / rf_float_of(l - m);
        before = q;
        q = next;
      }
      rf_float kq = rfk_sh_normalization(l, m) * q;
      int centre = base + l * (l + 1);
      if (m == 0)
      {
        sum = sum + kq * rf_sh_coefficient(table, centre);
      }
      else
      {
        sum = sum + 1.41421356237309504880 * kq *
            (re * rf_sh_coefficient(table, centre + m) + im * rf_sh_coefficient(table, centre - m));
      }
    }
  }
  return sum;
}
#endif /* !RF_GLSL || RF_SH_TABLE */

#endif /* RF_KERNEL_SH_H */
