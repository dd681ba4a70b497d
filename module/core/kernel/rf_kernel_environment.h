/* rf_kernel_environment.h (kernel dialect, C and GLSL): the built-in environment, a
 * sky/ground pattern made in code so that the demo, the tests and the reference tracer need no
 * image file. One source for rf_environment.c and the shaders. */
#ifndef RF_KERNEL_ENVIRONMENT_H
#define RF_KERNEL_ENVIRONMENT_H

#ifndef RF_GLSL
#include "rf_kernel_prelude.h"
#endif

/* World space, +y up; the direction need not be unit. A zero or non-finite direction gives the
 * horizon colour. Linear RGB, at most about 3 (the sun). */
RF_KERNEL rf_float3 rfk_builtin_environment(rf_float3 directionWorld)
{
  const rf_float3 horizon = rf_make3(0.85, 0.88, 0.92);
  const rf_float3 zenith = rf_make3(0.15, 0.35, 0.75);
  const rf_float3 tileDark = rf_make3(0.70, 0.22, 0.15);
  const rf_float3 tileLight = rf_make3(0.95, 0.93, 0.85);
  const rf_float3 sunColour = rf_make3(3.0, 2.6, 1.8);
  const rf_float3 sunDirection = rf_make3(0.48, 0.6, -0.64);
  rf_float len = rf_length3(directionWorld);
  if (!(len > 0.0) || rf_isinf(len))
  {
    return horizon;
  }
  rf_float3 d = rf_div3(directionWorld, len);
  if (d.y >= 0.0)
  {
    /* Sky: a gradient, twelve meridians and a ring at 30 degrees of elevation (so that the
     * bending of straight lines shows through glass), and a sun. */
    rf_float elevation = rf_sqrt(d.y);
    rf_float azimuth = rf_atan2(d.z, d.x);
    rf_float sector = rf_fract(azimuth * (6.0 / 3.14159265358979));
    rf_float meridian = 1.0 - rf_smoothstep(0.0, 0.04, rf_min(sector, 1.0 - sector));
    rf_float ring = 1.0 - rf_smoothstep(0.0, 0.02, rf_abs(d.y - 0.5));
    rf_float sun = rf_pow(rf_max(rf_dot3(d, sunDirection), 0.0), 400.0);
    rf_float line = rf_max(meridian, ring) * 0.6;
    return rf_add3(rf_scale3(rf_mix3(horizon, zenith, elevation), 1.0 - line),
      rf_scale3(sunColour, sun));
  }
  /* Ground: unit tiles on the plane y = -1, fading into the horizon where they would alias. */
  rf_float down = -d.y;
  rf_float u = d.x / rf_max(down, 1e-4);
  rf_float v = d.z / rf_max(down, 1e-4);
  rf_float checker = rf_fract((rf_floor(u) + rf_floor(v)) * 0.5) * 2.0;
  rf_float fade = rf_smoothstep(0.0, 0.35, down);
  return rf_mix3(horizon, rf_mix3(tileLight, tileDark, checker), fade);
}

#endif /* RF_KERNEL_ENVIRONMENT_H */
