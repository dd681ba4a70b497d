/* rf_environment.c: the public entry to the built-in environment of
 * kernel/rf_kernel_environment.h, which the shaders run too. */
#include "rf_environment.h"

#include "kernel/rf_kernel_environment.h"

void rf_builtin_environment(const double direction_world[3], double rgb[3])
{
  rf_builtin_environment_filtered(direction_world, 0.0, rgb);
}

void rf_builtin_environment_filtered(
  const double direction_world[3], double width, double rgb[3])
{
  const rf_float3 colour = rfk_builtin_environment_filtered(
    rf_make3(direction_world[0], direction_world[1], direction_world[2]), width);
  rgb[0] = colour.x;
  rgb[1] = colour.y;
  rgb[2] = colour.z;
}

void rf_builtin_environment_footprint(const double direction_world[3],
  const double span_a[3], const double span_b[3], double rgb[3])
{
  const rf_float3 colour = rfk_builtin_environment_footprint(
    rf_make3(direction_world[0], direction_world[1], direction_world[2]),
    rf_make3(span_a[0], span_a[1], span_a[2]), rf_make3(span_b[0], span_b[1], span_b[2]));
  rgb[0] = colour.x;
  rgb[1] = colour.y;
  rgb[2] = colour.z;
}
