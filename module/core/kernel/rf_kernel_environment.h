/* rf_kernel_environment.h (kernel dialect, C and GLSL): the built-in environment, a
 * sky/ground pattern made in code so that the demo, the tests and the reference tracer need no
 * image file. One source for rf_environment.c and the shaders. */
#ifndef RF_KERNEL_ENVIRONMENT_H
#define RF_KERNEL_ENVIRONMENT_H

#ifndef RF_GLSL
#include "rf_kernel_prelude.h"
#endif

/* The box-filtered square wave of period 2 (+1 where floor(x) is even, -1 where odd) over
 * [x - width / 2, x + width / 2], width > 0: the difference of its integral at both ends
 * (the integral of the wave is a triangle wave). */
RF_KERNEL rf_float rfk_filtered_square_wave(rf_float x, rf_float width)
{
  rf_float a = rf_abs(rf_fract((x - 0.5 * width) * 0.5) - 0.5);
  rf_float b = rf_abs(rf_fract((x + 0.5 * width) * 0.5) - 0.5);
  return 2.0 * (a - b) / width;
}

/* The built-in environment averaged over a cone of directions `width` radians across (the
 * spread of a pixel's rays; 0: the one direction, exactly rfk_builtin_environment), so that
 * glass that magnifies or minifies it does not alias: each pattern is box-filtered at the
 * width it has in its own coordinates (the meridians in azimuth, the ring in height, the
 * tiles on the ground plane, where a cone of width w covers w / down^2 toward the horizon and
 * w / down across), the sun's lobe
 * widened as a Gaussian of the box's variance (w^2 / 12) with its energy kept. World space,
 * +y up; the direction need not be unit. A zero or non-finite direction gives the horizon
 * colour. Linear RGB, at most about 3 (the sun). */
RF_KERNEL rf_float3 rfk_builtin_environment_filtered(rf_float3 directionWorld, rf_float width)
{
  const rf_float3 horizon = rf_make3(0.85, 0.88, 0.92);
  const rf_float3 zenith = rf_make3(0.15, 0.35, 0.75);
  const rf_float3 tileDark = rf_make3(0.70, 0.22, 0.15);
  const rf_float3 tileLight = rf_make3(0.95, 0.93, 0.85);
  const rf_float3 sunColour = rf_make3(3.0, 2.6, 1.8);
  const rf_float3 sunDirection = rf_make3(0.48, 0.6, -0.64);
  const rf_float meridianWidth = 0.04; /* in sectors of 30 degrees of azimuth */
  const rf_float ringWidth = 0.02;     /* in height, d.y */
  const rf_float sunSharpness = 400.0;
  rf_float len = rf_length3(directionWorld);
  rf_float w = width > 0.0 ? width : 0.0;
  if (!(len > 0.0) || rf_isinf(len))
  {
    return horizon;
  }
  rf_float3 d = rf_div3(directionWorld, len);
  if (d.y >= 0.0)
  {
    /* Sky: a gradient, twelve meridians and a ring at 30 degrees of elevation (so that the
     * bending of straight lines shows through glass), and a sun. A line of profile
     * 1 - smoothstep(0, a, distance) filtered by a box of width f spreads by f / 2 on each
     * side, to a + f / 2, and dims by a / (a + f / 2): the same light over a wider band. */
    rf_float elevation = rf_sqrt(d.y);
    rf_float cosElevation = rf_sqrt(rf_max(1.0 - d.y * d.y, 0.0));
    rf_float azimuth = rf_atan2(d.z, d.x);
    rf_float sector = rf_fract(azimuth * (6.0 / 3.14159265358979));
    rf_float sectorSpread = 0.5 * w * (6.0 / 3.14159265358979) / rf_max(cosElevation, 1e-3);
    rf_float meridian = (1.0 -
                          rf_smoothstep(0.0, meridianWidth + sectorSpread,
                            rf_min(sector, 1.0 - sector))) *
      (meridianWidth / (meridianWidth + sectorSpread));
    rf_float ringSpread = 0.5 * w * cosElevation;
    rf_float ring = (1.0 - rf_smoothstep(0.0, ringWidth + ringSpread, rf_abs(d.y - 0.5))) *
      (ringWidth / (ringWidth + ringSpread));
    rf_float sharpness =
      w > 0.0 ? 1.0 / (1.0 / sunSharpness + w * w / 12.0) : sunSharpness;
    rf_float sun = rf_pow(rf_max(rf_dot3(d, sunDirection), 0.0), sharpness) *
      (w > 0.0 ? sharpness / sunSharpness : 1.0);
    rf_float line = rf_max(meridian, ring) * 0.6;
    return rf_add3(rf_scale3(rf_mix3(horizon, zenith, elevation), 1.0 - line),
      rf_scale3(sunColour, sun));
  }
  /* Ground: unit tiles on the plane y = -1, fading into the horizon where they would alias. */
  rf_float down = -d.y;
  rf_float u = d.x / rf_max(down, 1e-4);
  rf_float v = d.z / rf_max(down, 1e-4);
  rf_float checker = rf_fract((rf_floor(u) + rf_floor(v)) * 0.5) * 2.0;
  if (w > 0.0)
  {
    /* The footprint's extent along u and along v: its radial and tangential extents
     * projected (the hit point at distance rho = tan(angle from straight down) moves by
     * w / down^2 radially and w / down across). Tiles of different parity: the product of the
     * two filtered waves is -1 there. A footprint wider than a few tiles gives their mean; the
     * cap keeps the division finite. */
    rf_float radial = w / rf_max(down * down, 1e-8);
    rf_float across = w / rf_max(down, 1e-8);
    rf_float rho = rf_sqrt(u * u + v * v);
    rf_float cu = rho > 0.0 ? rf_abs(u) / rho : 1.0;
    rf_float cv = rho > 0.0 ? rf_abs(v) / rho : 0.0;
    rf_float fu = rf_min(cu * radial + cv * across, 1e4);
    rf_float fv = rf_min(cv * radial + cu * across, 1e4);
    checker = 0.5 - 0.5 * rfk_filtered_square_wave(u, fu) * rfk_filtered_square_wave(v, fv);
  }
  rf_float fade = rf_smoothstep(0.0, 0.35, down);
  return rf_mix3(horizon, rf_mix3(tileLight, tileDark, checker), fade);
}

/* The built-in environment along one direction (see rfk_builtin_environment_filtered). */
RF_KERNEL rf_float3 rfk_builtin_environment(rf_float3 directionWorld)
{
  return rfk_builtin_environment_filtered(directionWorld, 0.0);
}

#endif /* RF_KERNEL_ENVIRONMENT_H */
