/* rf_environment_map.c: image environments sampled as OpenGL samples them (see the header). */
#include "rf_environment_map.h"

#include <math.h>
#include <stddef.h>

/* vtkEquirectangularToCubeMapTexture's toSpherical constants (about 1/(2 pi) and 1/pi), kept
 * as VTK writes them so that the reference reads the same texel as the pass. */
#define RF_LATLONG_U_SCALE 0.1591
#define RF_LATLONG_V_SCALE 0.3183
/* Largest accepted side of an environment image. */
#define RF_ENVIRONMENT_MAX_SIDE 65536

static int rf_wrap_index(int k, int size, int repeat)
{
  if (repeat)
  {
    k %= size;
    return k < 0 ? k + size : k;
  }
  return k < 0 ? 0 : (k >= size ? size - 1 : k);
}

/* GL texture filtering of one 2D image at (s, t) in [0, 1] (outside with repeat). */
static void rf_sample_image(const float* texels, int width, int height, double s, double t,
  int linear, int repeat, double rgb[3])
{
  int c;
  if (!linear)
  {
    const int i = rf_wrap_index((int)floor(s * width), width, repeat);
    const int j = rf_wrap_index((int)floor(t * height), height, repeat);
    const float* texel = texels + 3 * ((size_t)j * (size_t)width + (size_t)i);
    for (c = 0; c < 3; ++c)
    {
      rgb[c] = texel[c];
    }
    return;
  }
  {
    const double x = s * width - 0.5;
    const double y = t * height - 0.5;
    const double x0 = floor(x);
    const double y0 = floor(y);
    const double fx = x - x0;
    const double fy = y - y0;
    const int i0 = rf_wrap_index((int)x0, width, repeat);
    const int i1 = rf_wrap_index((int)x0 + 1, width, repeat);
    const int j0 = rf_wrap_index((int)y0, height, repeat);
    const int j1 = rf_wrap_index((int)y0 + 1, height, repeat);
    const float* t00 = texels + 3 * ((size_t)j0 * (size_t)width + (size_t)i0);
    const float* t10 = texels + 3 * ((size_t)j0 * (size_t)width + (size_t)i1);
    const float* t01 = texels + 3 * ((size_t)j1 * (size_t)width + (size_t)i0);
    const float* t11 = texels + 3 * ((size_t)j1 * (size_t)width + (size_t)i1);
    for (c = 0; c < 3; ++c)
    {
      const double bottom = (1.0 - fx) * t00[c] + fx * t10[c];
      const double top = (1.0 - fx) * t01[c] + fx * t11[c];
      rgb[c] = (1.0 - fy) * bottom + fy * top;
    }
  }
}

static void rf_sample_latlong(const rf_environment_map* map, const double d[3], double rgb[3])
{
  const double length = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  double sine = d[1] / length;
  sine = sine > 1.0 ? 1.0 : (sine < -1.0 ? -1.0 : sine);
  rf_sample_image(map->texels[0], map->width, map->height,
    atan2(d[2], d[0]) * RF_LATLONG_U_SCALE + 0.5, asin(sine) * RF_LATLONG_V_SCALE + 0.5,
    map->linear, map->repeat, rgb);
}

/* OpenGL's cube face selection (major axis; ties go to x, then y, as Mesa resolves them). */
static void rf_sample_cube(const rf_environment_map* map, const double d[3], double rgb[3])
{
  const double ax = fabs(d[0]);
  const double ay = fabs(d[1]);
  const double az = fabs(d[2]);
  int face;
  double sc;
  double tc;
  double ma;
  if (ax >= ay && ax >= az)
  {
    face = d[0] >= 0.0 ? 0 : 1;
    ma = ax;
    sc = d[0] >= 0.0 ? -d[2] : d[2];
    tc = -d[1];
  }
  else if (ay >= az)
  {
    face = d[1] >= 0.0 ? 2 : 3;
    ma = ay;
    sc = d[0];
    tc = d[1] >= 0.0 ? d[2] : -d[2];
  }
  else
  {
    face = d[2] >= 0.0 ? 4 : 5;
    ma = az;
    sc = d[2] >= 0.0 ? d[0] : -d[0];
    tc = -d[1];
  }
  rf_sample_image(map->texels[face], map->width, map->height, 0.5 * (sc / ma + 1.0),
    0.5 * (tc / ma + 1.0), map->linear, 0, rgb);
}

rf_status rf_environment_map_frame(const double up[3], const double right[3], double frame[9])
{
  double front[3];
  double length = 0.0;
  int i;
  if (up == NULL || right == NULL || frame == NULL)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  for (i = 0; i < 3; ++i)
  {
    if (!isfinite(up[i]) || !isfinite(right[i]))
    {
      return RF_ERR_NOT_FINITE;
    }
  }
  front[0] = right[1] * up[2] - right[2] * up[1];
  front[1] = right[2] * up[0] - right[0] * up[2];
  front[2] = right[0] * up[1] - right[1] * up[0];
  for (i = 0; i < 3; ++i)
  {
    length += front[i] * front[i];
  }
  if (!(length > 0.0))
  {
    return RF_REF_ERR_BAD_OPTION;
  }
  for (i = 0; i < 3; ++i)
  {
    frame[0 + i] = right[i];
    frame[3 + i] = up[i];
    frame[6 + i] = front[i];
  }
  return RF_OK;
}

rf_status rf_environment_map_validate(const rf_environment_map* map)
{
  int faces;
  int k;
  if (map == NULL)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  if ((map->layout != RF_ENVIRONMENT_LATLONG && map->layout != RF_ENVIRONMENT_CUBE) ||
    map->width <= 0 || map->height <= 0 || map->width > RF_ENVIRONMENT_MAX_SIDE ||
    map->height > RF_ENVIRONMENT_MAX_SIDE ||
    (map->layout == RF_ENVIRONMENT_CUBE && map->width != map->height))
  {
    return RF_REF_ERR_BAD_OPTION;
  }
  faces = map->layout == RF_ENVIRONMENT_CUBE ? 6 : 1;
  for (k = 0; k < faces; ++k)
  {
    if (map->texels[k] == NULL)
    {
      return RF_ERR_NULL_ARGUMENT;
    }
  }
  for (k = 0; k < 9; ++k)
  {
    if (!isfinite(map->frame[k]))
    {
      return RF_ERR_NOT_FINITE;
    }
  }
  return RF_OK;
}

void rf_environment_map_lookup(const double direction_world[3], double rgb[3], void* user)
{
  const rf_environment_map* map = (const rf_environment_map*)user;
  double d[3];
  int r;
  for (r = 0; r < 3; ++r)
  {
    d[r] = map->frame[3 * r + 0] * direction_world[0] + map->frame[3 * r + 1] * direction_world[1] +
      map->frame[3 * r + 2] * direction_world[2];
  }
  if (!isfinite(d[0]) || !isfinite(d[1]) || !isfinite(d[2]) ||
    !(d[0] * d[0] + d[1] * d[1] + d[2] * d[2] > 0.0))
  {
    rgb[0] = rgb[1] = rgb[2] = 0.0;
    return;
  }
  if (map->layout == RF_ENVIRONMENT_CUBE)
  {
    rf_sample_cube(map, d, rgb);
  }
  else
  {
    rf_sample_latlong(map, d, rgb);
  }
}

rf_status rf_environment_cube_from_latlong(
  const rf_environment_map* latlong, int side, float* const faces[6])
{
  int face;
  int a;
  int b;
  int k;
  if (latlong == NULL || faces == NULL || latlong->texels[0] == NULL)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  for (k = 0; k < 6; ++k)
  {
    if (faces[k] == NULL)
    {
      return RF_ERR_NULL_ARGUMENT;
    }
  }
  if (latlong->layout != RF_ENVIRONMENT_LATLONG || latlong->width <= 0 || latlong->height <= 0 ||
    side <= 0 || side > RF_ENVIRONMENT_MAX_SIDE)
  {
    return RF_REF_ERR_BAD_OPTION;
  }
  for (face = 0; face < 6; ++face)
  {
    for (b = 0; b < side; ++b)
    {
      for (a = 0; a < side; ++a)
      {
        /* vtkEquirectangularToCubeMapTexture's fragment at texCoord (s, t). */
        const double x = 2.0 * ((a + 0.5) / side) - 1.0;
        const double y = 1.0 - 2.0 * ((b + 0.5) / side);
        double d[3];
        double rgb[3];
        float* texel = faces[face] + 3 * ((size_t)b * (size_t)side + (size_t)a);
        switch (face)
        {
          case 0: d[0] = 1.0; d[1] = y; d[2] = -x; break;
          case 1: d[0] = -1.0; d[1] = y; d[2] = x; break;
          case 2: d[0] = x; d[1] = 1.0; d[2] = -y; break;
          case 3: d[0] = x; d[1] = -1.0; d[2] = y; break;
          case 4: d[0] = x; d[1] = y; d[2] = 1.0; break;
          default: d[0] = -x; d[1] = y; d[2] = -1.0; break;
        }
        rf_sample_latlong(latlong, d, rgb);
        for (k = 0; k < 3; ++k)
        {
          texel[k] = (float)rgb[k];
        }
      }
    }
  }
  return RF_OK;
}

void rf_background_environment_lookup(
  const double direction_world[3], double rgb[3], void* background)
{
  const rf_background_environment* b = (const rf_background_environment*)background;
  double d[3];
  double clip_y = 0.0;
  double clip_w = 0.0;
  double up;
  int r;
  int c;
  for (r = 0; r < 3; ++r)
  {
    d[r] = b->world_to_view[3 * r + 0] * direction_world[0] +
      b->world_to_view[3 * r + 1] * direction_world[1] +
      b->world_to_view[3 * r + 2] * direction_world[2];
  }
  for (c = 0; c < 3; ++c)
  {
    clip_y += b->projection[4 + c] * d[c];
    clip_w += b->projection[12 + c] * d[c];
  }
  if (clip_w > 1e-6 * sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]))
  {
    up = 0.5 + 0.5 * clip_y / clip_w;
  }
  else
  {
    up = d[1] >= 0.0 ? 1.0 : 0.0;
  }
  if (!isfinite(up))
  {
    up = 0.0;
  }
  up = fmin(fmax(up, 0.0), 1.0);
  for (c = 0; c < 3; ++c)
  {
    rgb[c] = b->bottom[c] + (b->top[c] - b->bottom[c]) * up;
  }
}
