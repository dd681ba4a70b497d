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
