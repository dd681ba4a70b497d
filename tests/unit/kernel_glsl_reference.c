/* kernel_glsl_reference.c: the C side of test_kernel_glsl. */
#include "kernel_glsl_reference.h"

#include "rf_kernel_cases.h"

#include <math.h>
#include <stddef.h>

/* A float depth map read as texelFetch reads the texture, optionally disturbed (to find
 * decisions that rounding can flip). */
typedef struct rft_float_map
{
  const rft_scene* scene;
  double depth_scale;
  double tc_offset;
} rft_float_map;

static double rft_sample(void* context, const double tc[2])
{
  const rft_float_map* map = (const rft_float_map*)context;
  const double size[2] = { (double)map->scene->width, (double)map->scene->height };
  double at[2];
  int texel[2];
  at[0] = fmin(fmax(tc[0] + map->tc_offset, 0.0), 1.0);
  at[1] = fmin(fmax(tc[1] + map->tc_offset, 0.0), 1.0);
  rf_texel_index(at, size, texel);
  return map->depth_scale * (double)map->scene->depth[texel[1] * map->scene->width + texel[0]];
}

int rft_make_scene(int width, int height, float* depth, rft_scene* scene)
{
  const double near_plane = 1.0;
  const double far_plane = 20.0;
  const double f = 1.0 / tan(25.0 * 3.14159265358979 / 180.0);
  const double values[16] = { f, 0.0, 0.0, 0.0, 0.0, f, 0.0, 0.0, 0.0, 0.0,
    (far_plane + near_plane) / (near_plane - far_plane),
    2.0 * far_plane * near_plane / (near_plane - far_plane), 0.0, 0.0, -1.0, 0.0 };
  int i;
  int j;
  int count = 0;
  scene->width = width;
  scene->height = height;
  scene->depth = depth;
  for (i = 0; i < 16; ++i)
  {
    scene->projection[i] = (double)(float)values[i];
  }
  scene->focal[0] = scene->projection[0];
  scene->focal[1] = scene->projection[5];
  scene->depth_range[0] = 1e30;
  scene->depth_range[1] = 0.0;
  for (j = 0; j < height; ++j)
  {
    for (i = 0; i < width; ++i)
    {
      const float d = (float)rft_back_depth(rf_make2(i + 0.5, j + 0.5),
        rf_make2((double)width, (double)height), rf_make2(scene->focal[0], scene->focal[1]));
      depth[j * width + i] = d;
      if (d > 0.0f)
      {
        ++count;
        scene->depth_range[0] = fmin(scene->depth_range[0], d);
        scene->depth_range[1] = fmax(scene->depth_range[1], d);
      }
    }
  }
  return count;
}

#if RFT_TEST_REFRACT_REFLECT != RFT_CASE_REFRACT_REFLECT ||                                      \
  RFT_TEST_REFRACT_CLAMP != RFT_CASE_REFRACT_CLAMP ||                                              \
  RFT_TEST_SEARCH_FIRST != RFT_CASE_SEARCH_PAPER ||                                                \
  RFT_TEST_SEARCH_LAST != RFT_CASE_SEARCH_TOWARD_CAMERA ||                                         \
  RFT_CASE_CHORD_NORMAL != RFT_CASE_COUNT - 1
#error "kernel_glsl_reference.h and rf_kernel_cases.h number the cases differently"
#endif

int rft_case_count(void)
{
  return RFT_CASE_COUNT;
}

const char* rft_case_name(int test_case)
{
  static const char* const names[RFT_CASE_COUNT] = { "refract (reflect policy)",
    "refract (clamp policy)", "Fresnel (exact, Schlick, exact leaving)", "DIR alpha (eq. 9)",
    "octahedral encode", "octahedral round trip", "built-in environment", "ISR distance",
    "frustum exit and projection", "SSP (Fresnel, perturbed position)",
    "DIR search, paper (5 steps)",
    "DIR search, defaults (8 adaptive + secant)",
    "DIR search, IOR 3 (5 steps + secant)", "DIR search, toward the camera",
    "spherical harmonics (orders 8, 5, 2)", "chord-symmetric normal" };
  return test_case >= 0 && test_case < RFT_CASE_COUNT ? names[test_case] : "unknown";
}

static void rft_evaluate_with(
  const rft_scene* scene, int test_case, int i, int j, rft_float_map* map, double out[4])
{
  rf_mat4 projection;
  rf_depth_map depth_map;
  rf_float4 value;
  const rf_float2 size = rf_make2((double)scene->width, (double)scene->height);
  int k;
  for (k = 0; k < 16; ++k)
  {
    projection.m[k] = scene->projection[k];
  }
  depth_map.sample = rft_sample;
  depth_map.context = map;
  value = rft_evaluate(test_case, rf_make2(i + 0.5, j + 0.5), size,
    rf_make2(scene->focal[0], scene->focal[1]), rfk_make_camera(projection, size, RF_FALSE),
    rf_make2(scene->depth_range[0], scene->depth_range[1]), depth_map);
  out[0] = value.x;
  out[1] = value.y;
  out[2] = value.z;
  out[3] = value.w;
}

void rft_evaluate_pixel(const rft_scene* scene, int test_case, int i, int j, double out[4])
{
  rft_float_map map;
  map.scene = scene;
  map.depth_scale = 1.0;
  map.tc_offset = 0.0;
  rft_evaluate_with(scene, test_case, i, j, &map, out);
}

static int rft_near_integer(double x)
{
  return fabs(x - floor(x + 0.5)) < 1e-4 * (1.0 + fabs(x));
}

int rft_is_ambiguous(const rft_scene* scene, int test_case, int i, int j)
{
  const rf_float2 pixel = rf_make2(i + 0.5, j + 0.5);
  const rf_float2 size = rf_make2((double)scene->width, (double)scene->height);
  if (test_case == RFT_CASE_REFRACT_REFLECT || test_case == RFT_CASE_REFRACT_CLAMP)
  {
    const rf_float3 incident = rft_incident(pixel, size);
    const rf_float3 facing = rfk_facing_normal(incident, rft_normal(pixel, size));
    const rf_float3 tangent = rfk_tangential_part(incident, facing);
    return fabs(rfk_transmitted_cos_squared(rf_dot3(tangent, tangent), rft_eta(pixel, size))) <
      1e-4;
  }
  if (test_case == RFT_CASE_OCT_ENCODE)
  {
    const rf_float3 n = rft_sphere_direction(pixel, size);
    return n.z < 0.0 && fmin(fabs(n.x), fabs(n.y)) < 1e-5;
  }
  if (test_case == RFT_CASE_ENVIRONMENT)
  {
    const rf_float3 d = rft_sphere_direction(pixel, size);
    const double down = fmax(-d.y, 1e-4);
    return fabs(d.y) < 1e-5 ||
      (d.y < 0.0 && (rft_near_integer(d.x / down) || rft_near_integer(d.z / down)));
  }
  if (test_case >= RFT_CASE_SEARCH_PAPER && test_case <= RFT_CASE_SEARCH_TOWARD_CAMERA)
  {
    static const double scales[4] = { 1.0 + 1e-5, 1.0 - 1e-5, 1.0, 1.0 };
    static const double offsets[4] = { 0.0, 0.0, 1e-5, -1e-5 };
    double nominal[4];
    int v;
    int k;
    rft_evaluate_pixel(scene, test_case, i, j, nominal);
    for (v = 0; v < 4; ++v)
    {
      rft_float_map map;
      double disturbed[4];
      map.scene = scene;
      map.depth_scale = scales[v];
      map.tc_offset = offsets[v];
      rft_evaluate_with(scene, test_case, i, j, &map, disturbed);
      for (k = 0; k < 4; ++k)
      {
        const double allowed = rft_tolerance(test_case) * (1.0 + fabs(nominal[k]));
        if (!(fabs(disturbed[k] - nominal[k]) <= allowed))
        {
          return 1;
        }
      }
    }
  }
  return 0;
}

double rft_tolerance(int test_case)
{
  /* Float carries 24 bits (6e-8 relative); the formulas lose at most a few hundred ulps: the
   * sun's pow(x, 400) multiplies a relative error by 400, eq. 9's 1/z - k1 cancels, the
   * search adds depths and positions of size ~5. Measured on llvmpipe: at most 6.3e-5
   * (refraction near grazing), 3.5e-5 (the sun), 1.1e-5 (the searches). */
  (void)test_case;
  return 1e-4;
}
