/* rf_kernel_environment.h (kernel dialect, C and GLSL): the built-in environment, a
 * sky/ground pattern made in code so that the demo, the tests and the reference tracer need no
 * image file. One source for rf_environment.c and the shaders. */
#ifndef RF_KERNEL_ENVIRONMENT_H
#define RF_KERNEL_ENVIRONMENT_H

#ifndef RF_GLSL
#include "rf_kernel_prelude.h"
#endif

/* Strips of the footprint the ground's tiles are averaged over
 * (rfk_builtin_environment_footprint). */
#define RF_GROUND_STRIPS 4

/* The box-filtered square wave of period 2 (+1 where floor(x) is even, -1 where odd) over
 * [x - width / 2, x + width / 2], width > 0: the difference of its integral at both ends
 * (the integral of the wave is a triangle wave). */
RF_KERNEL rf_float rfk_filtered_square_wave(rf_float x, rf_float width)
{
  rf_float a = rf_abs(rf_fract((x - 0.5 * width) * 0.5) - 0.5);
  rf_float b = rf_abs(rf_fract((x + 0.5 * width) * 0.5) - 0.5);
  return 2.0 * (a - b) / width;
}

/* A square wave of period 2 (+1 where floor(x) is even, -1 where odd) box-filtered over
 * `width` (rfk_filtered_square_wave); a box narrower than a hundred-thousandth of a period
 * (relative to x) is the point value, where the difference of the two ends would round away. */
RF_KERNEL rf_float rfk_square_wave_over(rf_float x, rf_float width)
{
  rf_float point = 1.0 - 4.0 * rf_fract(rf_floor(x) * 0.5);
  return width > 1e-5 * (1.0 + rf_abs(x)) ? rfk_filtered_square_wave(x, width) : point;
}

/* How far a pattern's coordinate moves over a footprint: the sum of its changes along the two
 * spans (the extent of the parallelogram they span, in that coordinate), at most `cap`; NaN
 * (a span that is not finite) gives 0, the point value. */
RF_KERNEL rf_float rfk_footprint_extent(rf_float alongA, rf_float alongB, rf_float cap)
{
  rf_float extent = rf_abs(alongA) + rf_abs(alongB);
  return extent >= 0.0 ? rf_min(extent, cap) : 0.0;
}

/* The built-in environment averaged over the footprint of a pixel's rays: the parallelogram of
 * directions spanned by spanA and spanB about directionWorld (how far the unit direction turns
 * across the pixel along each of the screen's axes; zero spans: the one direction, exactly
 * rfk_builtin_environment), so that glass that magnifies or minifies the environment does not
 * alias, and a footprint long one way is not blurred the other (across the torus's rims, where
 * the rays spread along the rim and not across it). Each pattern is box-filtered in its own
 * coordinate over the footprint's extent there (the meridians in azimuth, the ring in height,
 * the tiles in the ground plane's u and v, strip by strip along the footprint), the sun's lobe
 * widened as a Gaussian of the box's variance (the spans' mean square / 12) with its energy
 * kept. World space, +y up; the direction need not be unit, the spans are taken as turns of
 * the unit direction. A zero or non-finite direction gives the horizon colour. Linear RGB, at
 * most about 3 (the sun). */
RF_KERNEL rf_float3 rfk_builtin_environment_footprint(
  rf_float3 directionWorld, rf_float3 spanA, rf_float3 spanB)
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
  const rf_float cap = 1e4; /* any wider footprint is the patterns' mean already */
  rf_float len = rf_length3(directionWorld);
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
     * side, to a + f / 2, and dims by a / (a + f / 2): the same light over a wider band. The
     * azimuth turns by (d.x e.z - d.z e.x) / (d.x^2 + d.z^2) for a turn e of the direction. */
    rf_float elevation = rf_sqrt(d.y);
    rf_float horizontal = rf_max(d.x * d.x + d.z * d.z, 1e-6);
    rf_float azimuth = rf_atan2(d.z, d.x);
    rf_float sector = rf_fract(azimuth * (6.0 / 3.14159265358979));
    rf_float sectorSpread = 0.5 * (6.0 / 3.14159265358979) *
      rfk_footprint_extent((d.x * spanA.z - d.z * spanA.x) / horizontal,
        (d.x * spanB.z - d.z * spanB.x) / horizontal, cap);
    rf_float meridian = (1.0 -
                          rf_smoothstep(0.0, meridianWidth + sectorSpread,
                            rf_min(sector, 1.0 - sector))) *
      (meridianWidth / (meridianWidth + sectorSpread));
    rf_float ringSpread = 0.5 * rfk_footprint_extent(spanA.y, spanB.y, cap);
    rf_float ring = (1.0 - rf_smoothstep(0.0, ringWidth + ringSpread, rf_abs(d.y - 0.5))) *
      (ringWidth / (ringWidth + ringSpread));
    rf_float variance =
      rfk_footprint_extent(rf_dot3(spanA, spanA), rf_dot3(spanB, spanB), cap) / 24.0;
    rf_float sharpness = variance > 0.0 ? 1.0 / (1.0 / sunSharpness + variance) : sunSharpness;
    rf_float sun = rf_pow(rf_max(rf_dot3(d, sunDirection), 0.0), sharpness) *
      (variance > 0.0 ? sharpness / sunSharpness : 1.0);
    rf_float line = rf_max(meridian, ring) * 0.6;
    return rf_add3(rf_scale3(rf_mix3(horizon, zenith, elevation), 1.0 - line),
      rf_scale3(sunColour, sun));
  }
  /* Ground: unit tiles on the plane y = -1 (the point u = d.x / down, v = d.z / down), fading
   * into the horizon where they would alias. A turn e of the direction moves the point by
   * ((e.x + u e.y) / down, (e.z + v e.y) / down). Tiles of different parity: the product of the
   * two filtered waves is -1 there; a footprint wider than a few tiles gives their mean. The
   * product filters the box of the footprint's extents in u and in v, which blurs across the
   * whole box where the footprint lies along a diagonal of the tiles (the tile edges the
   * torus's rings compress): it is averaged over RF_GROUND_STRIPS strips of the footprint
   * along the span that moves the point most, each filtered over its own, smaller box. The
   * strips replace lookups of the whole environment spaced along the footprint's long axis
   * (up to four, each evaluating the sky too), docs/benchmark.md, *The ground's strips*. */
  rf_float down = -d.y;
  rf_float safeDown = rf_max(down, 1e-4);
  rf_float u = d.x / safeDown;
  rf_float v = d.z / safeDown;
  rf_float2 moveA =
    rf_make2((spanA.x + u * spanA.y) / safeDown, (spanA.z + v * spanA.y) / safeDown);
  rf_float2 moveB =
    rf_make2((spanB.x + u * spanB.y) / safeDown, (spanB.z + v * spanB.y) / safeDown);
  rf_bool alongA = rf_abs(moveA.x) + rf_abs(moveA.y) >= rf_abs(moveB.x) + rf_abs(moveB.y);
  rf_float2 along = alongA ? moveA : moveB;
  rf_float2 across = alongA ? moveB : moveA;
  /* Not finite or wider than the cap (the patterns' mean already): the strips do not move. */
  rf_float alongU = rf_abs(along.x) <= cap ? along.x : 0.0;
  rf_float alongV = rf_abs(along.y) <= cap ? along.y : 0.0;
  rf_float strips = rf_float_of(RF_GROUND_STRIPS);
  rf_float fu = rfk_footprint_extent(along.x / strips, across.x, cap);
  rf_float fv = rfk_footprint_extent(along.y / strips, across.y, cap);
  rf_float product = 0.0;
  for (int i = 0; i < RF_GROUND_STRIPS; ++i)
  {
    rf_float offset = (rf_float_of(i) + 0.5) / strips - 0.5;
    product = product + rfk_square_wave_over(u + offset * alongU, fu) *
        rfk_square_wave_over(v + offset * alongV, fv);
  }
  rf_float checker = 0.5 - 0.5 * product / strips;
  rf_float fade = rf_smoothstep(0.0, 0.35, down);
  return rf_mix3(horizon, rf_mix3(tileLight, tileDark, checker), fade);
}

/* The built-in environment averaged over a cone of directions `width` radians across (the
 * spread of a pixel's rays; 0, negative or NaN: the one direction, exactly
 * rfk_builtin_environment): the footprint of two spans `width` long, one up the meridian and
 * one along the horizon (rfk_builtin_environment_footprint). */
RF_KERNEL rf_float3 rfk_builtin_environment_filtered(rf_float3 directionWorld, rf_float width)
{
  rf_float w = width > 0.0 ? rf_min(width, 1e4) : 0.0;
  rf_float len = rf_length3(directionWorld);
  rf_float3 d =
    len > 0.0 && !rf_isinf(len) ? rf_div3(directionWorld, len) : rf_make3(0.0, 1.0, 0.0);
  rf_float horizontal = rf_sqrt(d.x * d.x + d.z * d.z);
  rf_float3 alongHorizon = horizontal > 1e-6
    ? rf_make3(-d.z / horizontal, 0.0, d.x / horizontal)
    : rf_make3(1.0, 0.0, 0.0);
  rf_float3 upMeridian = horizontal > 1e-6
    ? rf_make3(-d.x * d.y / horizontal, horizontal, -d.z * d.y / horizontal)
    : rf_make3(0.0, 0.0, 1.0);
  return rfk_builtin_environment_footprint(
    directionWorld, rf_scale3(upMeridian, w), rf_scale3(alongHorizon, w));
}

/* The built-in environment along one direction (see rfk_builtin_environment_filtered). */
RF_KERNEL rf_float3 rfk_builtin_environment(rf_float3 directionWorld)
{
  return rfk_builtin_environment_filtered(directionWorld, 0.0);
}

#endif /* RF_KERNEL_ENVIRONMENT_H */
