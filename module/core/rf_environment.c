#include "rf_environment.h"

#include <math.h>

static double rf_fract(double x) { return x - floor(x); }
static double rf_clamp01(double x) { return x < 0.0 ? 0.0 : (x > 1.0 ? 1.0 : x); }
static double rf_smoothstep(double e0, double e1, double x)
{
  const double t = rf_clamp01((x - e0) / (e1 - e0));
  return t * t * (3.0 - 2.0 * t);
}
static void rf_mix3(const double a[3], const double b[3], double t, double out[3])
{
  int i;
  for (i = 0; i < 3; ++i)
  {
    out[i] = a[i] + (b[i] - a[i]) * t;
  }
}

void rf_builtin_environment(const double direction_world[3], double rgb[3])
{
  static const double horizon[3] = { 0.85, 0.88, 0.92 };
  static const double zenith[3] = { 0.15, 0.35, 0.75 };
  static const double tile_dark[3] = { 0.70, 0.22, 0.15 };
  static const double tile_light[3] = { 0.95, 0.93, 0.85 };
  static const double sun_colour[3] = { 3.0, 2.6, 1.8 };
  const double len = sqrt(direction_world[0] * direction_world[0] +
    direction_world[1] * direction_world[1] + direction_world[2] * direction_world[2]);
  double d[3];
  int i;
  if (!(len > 0.0) || !isfinite(len))
  {
    for (i = 0; i < 3; ++i)
    {
      rgb[i] = horizon[i];
    }
    return;
  }
  for (i = 0; i < 3; ++i)
  {
    d[i] = direction_world[i] / len;
  }

  if (d[1] >= 0.0)
  {
    /* Sky: a gradient, twelve meridians and a ring at 30 degrees of elevation (so that the
     * bending of straight lines shows through glass), and a sun. */
    const double elevation = sqrt(d[1]);
    const double azimuth = atan2(d[2], d[0]);
    const double sector = rf_fract(azimuth * (6.0 / 3.14159265358979));
    const double meridian = 1.0 - rf_smoothstep(0.0, 0.04, fmin(sector, 1.0 - sector));
    const double ring = 1.0 - rf_smoothstep(0.0, 0.02, fabs(d[1] - 0.5));
    const double sun_cos = d[0] * 0.48 + d[1] * 0.6 + d[2] * (-0.64);
    const double sun = pow(fmax(sun_cos, 0.0), 400.0);
    const double line = fmax(meridian, ring) * 0.6;
    rf_mix3(horizon, zenith, elevation, rgb);
    for (i = 0; i < 3; ++i)
    {
      rgb[i] = rgb[i] * (1.0 - line) + sun_colour[i] * sun;
    }
  }
  else
  {
    /* Ground: unit tiles on the plane y = -1, fading into the horizon where they would alias. */
    const double down = -d[1];
    const double u = d[0] / fmax(down, 1e-4);
    const double v = d[2] / fmax(down, 1e-4);
    const double checker = rf_fract((floor(u) + floor(v)) * 0.5) * 2.0;
    const double fade = rf_smoothstep(0.0, 0.35, down);
    double tile[3];
    rf_mix3(tile_light, tile_dark, checker, tile);
    rf_mix3(horizon, tile, fade, rgb);
  }
}
