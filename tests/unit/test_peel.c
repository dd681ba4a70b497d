/* Unit tests of rf_peel_trace (the PEEL method's trace, kernel/rf_kernel_peel.h) on layers
 * peeled analytically from spheres: every pixel's line of sight is intersected with the
 * spheres and the hits, sorted by depth, are the layers, as the GPU peels them. The trace is
 * compared with an exact ray tracer of the same spheres (Snell's law at every surface, the
 * medium from the innermost sphere the ray is inside): a single sphere (the two-interface
 * case), deep peeling on it (K = 8, fewer layers than K), a ball inside a ball of another index,
 * and two balls one behind the other. */
#include "rf_peel.h"

#include "rf_kernel_peel.h"

#include "rf_test.h"

#include <math.h>
#include <stdlib.h>

#define SIZE 96
#define MAX_SPHERES 3

typedef struct sphere
{
  rf_vec3 centre;
  double radius;
  int material;
} sphere;

typedef struct scene
{
  sphere spheres[MAX_SPHERES];
  int count;
  double ior[MAX_SPHERES];
  double projection[16];
  double inverse_focal; /* tan(fovy / 2) */
  int layers; /* K of the capture: its last layer the furthest surface where
                 rf_peel_last_is_furthest says so, as the pass peels it; otherwise the nearest */
} scene;

/* The scene's camera: a 30 degree perspective at the origin looking down -z. */
static void make_camera(scene* s)
{
  const double near_plane = 0.1;
  const double far_plane = 100.0;
  const double f = 1.0 / tan(0.5 * 30.0 * 3.14159265358979 / 180.0);
  int i;
  for (i = 0; i < 16; ++i)
  {
    s->projection[i] = 0.0;
  }
  s->projection[0] = f;
  s->projection[5] = f;
  s->projection[10] = (far_plane + near_plane) / (near_plane - far_plane);
  s->projection[11] = 2.0 * far_plane * near_plane / (near_plane - far_plane);
  s->projection[14] = -1.0;
  s->inverse_focal = 1.0 / f;
}

/* A scene of `count` spheres (MAX_SPHERES at most) seen by make_camera's camera, the index of
 * material m in ior[m]. */
static void make_scene(scene* s, const sphere* spheres, int count, const double ior[MAX_SPHERES])
{
  int i;
  make_camera(s);
  s->count = count;
  s->layers = 0;
  for (i = 0; i < count; ++i)
  {
    s->spheres[i] = spheres[i];
  }
  for (i = 0; i < MAX_SPHERES; ++i)
  {
    s->ior[i] = ior[i];
  }
}

/* The line of sight through texture coordinates tc (the nearest texel's centre). */
static rf_vec3 sight(const scene* s, const double tc[2])
{
  int texel[2];
  double ndc[2];
  int k;
  for (k = 0; k < 2; ++k)
  {
    texel[k] = (int)fmin(tc[k] * SIZE, SIZE - 1.0);
    ndc[k] = 2.0 * (texel[k] + 0.5) / SIZE - 1.0;
  }
  return rf_vec3_normalize(
    rf_vec3_make(ndc[0] * s->inverse_focal, ndc[1] * s->inverse_focal, -1.0));
}

/* Both hits (t > tmin) of the ray O + t D with a sphere; false when it misses. */
static int sphere_hits(const sphere* sp, rf_vec3 O, rf_vec3 D, double t[2])
{
  const rf_vec3 oc = rf_vec3_sub(O, sp->centre);
  const double b = rf_vec3_dot(oc, D);
  const double c = rf_vec3_dot(oc, oc) - sp->radius * sp->radius;
  const double disc = b * b - c;
  if (disc <= 0.0)
  {
    return 0;
  }
  t[0] = -b - sqrt(disc);
  t[1] = -b + sqrt(disc);
  return 1;
}

/* The layers at tc: every sphere surface on the line of sight, sorted by depth. */
static void sample_layers(void* context, const double tc[2], int layer, double rgba[4])
{
  const scene* s = (const scene*)context;
  const rf_vec3 D = sight(s, tc);
  double t[2 * MAX_SPHERES];
  int owner[2 * MAX_SPHERES];
  int n = 0;
  int i;
  int j;
  rgba[0] = rgba[1] = rgba[2] = rgba[3] = 0.0;
  for (i = 0; i < s->count; ++i)
  {
    double h[2];
    if (sphere_hits(&s->spheres[i], rf_vec3_make(0.0, 0.0, 0.0), D, h))
    {
      t[n] = h[0];
      owner[n++] = i;
      t[n] = h[1];
      owner[n++] = i;
    }
  }
  for (i = 1; i < n; ++i)
  {
    for (j = i; j > 0 && t[j - 1] > t[j]; --j)
    {
      const double tt = t[j];
      const int oo = owner[j];
      t[j] = t[j - 1];
      owner[j] = owner[j - 1];
      t[j - 1] = tt;
      owner[j - 1] = oo;
    }
  }
  if (rf_peel_last_is_furthest(s->layers) && layer == s->layers - 1 && n > s->layers)
  {
    layer = n - 1;
  }
  if (layer < n)
  {
    const sphere* sp = &s->spheres[owner[layer]];
    const rf_vec3 P = rf_vec3_scale(D, t[layer]);
    const rf_vec3 outward = rf_vec3_normalize(rf_vec3_sub(P, sp->centre));
    const int facing = rf_vec3_dot(outward, D) < 0.0;
    const rf_vec3 toward = facing ? outward : rf_vec3_scale(outward, -1.0);
    /* The octahedral encoding of the kernel (rf_oct_encode), written out. */
    const double l1 = fabs(toward.x) + fabs(toward.y) + fabs(toward.z);
    double ex = toward.x / l1;
    double ey = toward.y / l1;
    if (toward.z < 0.0)
    {
      const double fx = (1.0 - fabs(ey)) * (ex < 0.0 ? -1.0 : 1.0);
      const double fy = (1.0 - fabs(ex)) * (ey < 0.0 ? -1.0 : 1.0);
      ex = fx;
      ey = fy;
    }
    rgba[0] = ex;
    rgba[1] = ey;
    rgba[2] = -P.z;
    rgba[3] = (facing ? 1.0 : -1.0) * (sp->material + 1);
  }
}

/* The exact path from the entry point: the medium is the innermost sphere the ray is inside.
 * Returns the direction the ray leaves with (after at most `bounces` reflections) and the
 * last surface point; *entry the first hit, *entered its material, *N1 its outward normal. */
static int exact_trace(const scene* s, rf_vec3 D, int bounces, rf_vec3* P1, rf_vec3* N1,
  int* entered, rf_vec3* last, rf_vec3* out)
{
  rf_vec3 O = rf_vec3_make(0.0, 0.0, 0.0);
  int inside[MAX_SPHERES] = { 0 };
  int reflections = 0;
  int hits = 0;
  int k;
  for (k = 0; k < 16; ++k)
  {
    double best = 1e30;
    int which = -1;
    int i;
    rf_vec3 P;
    rf_vec3 outward;
    double n_here = 1.0;
    double n_there = 1.0;
    int innermost = -1;
    for (i = 0; i < s->count; ++i)
    {
      double h[2];
      if (sphere_hits(&s->spheres[i], O, D, h))
      {
        const double t = h[0] > 1e-9 ? h[0] : h[1];
        if (t > 1e-9 && t < best)
        {
          best = t;
          which = i;
        }
      }
    }
    if (which < 0)
    {
      break;
    }
    P = rf_vec3_add(O, rf_vec3_scale(D, best));
    outward = rf_vec3_normalize(rf_vec3_sub(P, s->spheres[which].centre));
    if (hits == 0)
    {
      *P1 = P;
      *N1 = outward;
      *entered = s->spheres[which].material;
    }
    ++hits;
    /* The index the ray is in: the smallest sphere containing it (nested balls). */
    for (i = 0; i < s->count; ++i)
    {
      if (inside[i] && (innermost < 0 || s->spheres[i].radius < s->spheres[innermost].radius))
      {
        innermost = i;
      }
    }
    n_here = innermost < 0 ? 1.0 : s->ior[s->spheres[innermost].material];
    inside[which] = !inside[which];
    innermost = -1;
    for (i = 0; i < s->count; ++i)
    {
      if (inside[i] && (innermost < 0 || s->spheres[i].radius < s->spheres[innermost].radius))
      {
        innermost = i;
      }
    }
    n_there = innermost < 0 ? 1.0 : s->ior[s->spheres[innermost].material];
    {
      const rf_vec3 facing = rf_vec3_dot(D, outward) < 0.0 ? outward : rf_vec3_scale(outward, -1.0);
      rf_vec3 next;
      if (!rf_test_snell(D, facing, n_here / n_there, &next))
      {
        inside[which] = !inside[which];
        if (reflections >= bounces)
        {
          *last = P;
          *out = next;
          return hits;
        }
        ++reflections;
      }
      D = next;
    }
    O = P;
    *last = P;
  }
  *out = D;
  return hits;
}

typedef struct comparison
{
  int rays;
  int close;     /* exit direction within 2 degrees of the exact one */
  double median; /* median angle error, degrees */
  int failures;  /* calls that did not return RF_OK */
} comparison;

static int compare_doubles(const void* a, const void* b)
{
  const double x = *(const double*)a;
  const double y = *(const double*)b;
  return x < y ? -1 : x > y;
}

/* The trace of every pixel whose sight meets the scene, against the exact path. `minimum_hits`
 * keeps only the pixels whose exact path crosses at least that many surfaces. */
static comparison compare(const scene* s, int layers, int bounces, int minimum_hits)
{
  static double errors[SIZE * SIZE];
  comparison result = { 0, 0, 0.0, 0 };
  scene captured = *s;
  int x;
  int y;
  captured.layers = layers;
  for (y = 0; y < SIZE; ++y)
  {
    for (x = 0; x < SIZE; ++x)
    {
      const double tc[2] = { (x + 0.5) / SIZE, (y + 0.5) / SIZE };
      const rf_vec3 D = sight(s, tc);
      rf_vec3 P1;
      rf_vec3 N1;
      rf_vec3 last;
      rf_vec3 exact;
      rf_vec3 T1;
      int material = 0;
      rf_peel_input input;
      rf_peel_result traced;
      int k;
      const int hits = exact_trace(s, D, bounces, &P1, &N1, &material, &last, &exact);
      if (hits < minimum_hits || hits == 0)
      {
        continue;
      }
      rf_test_snell(D, N1, 1.0 / s->ior[material], &T1);
      input.P1 = P1;
      input.T1 = T1;
      input.material = material;
      input.layers = layers;
      input.interfaces = rf_peel_interfaces(layers, bounces);
      input.bounces = bounces;
      input.tir_clamp = 0;
      input.extent = 8.0;
      input.depth_range[0] = 4.0; /* the spheres lie within depths 4.8 .. 8.8 */
      input.depth_range[1] = 9.5;
      for (k = 0; k < 16; ++k)
      {
        input.projection[k] = s->projection[k];
      }
      input.viewport[0] = SIZE;
      input.viewport[1] = SIZE;
      input.parallel = 0;
      input.ior = s->ior;
      input.sheet = NULL;
      input.materials = MAX_SPHERES;
      if (rf_peel_trace(&input, sample_layers, &captured, &traced) != RF_OK)
      {
        ++result.failures;
        continue;
      }
      errors[result.rays] =
        acos(fmin(1.0, fmax(-1.0, rf_vec3_dot(traced.T2, exact)))) * 180.0 / 3.14159265358979;
      result.close += errors[result.rays] <= 2.0;
      ++result.rays;
    }
  }
  if (result.rays > 0)
  {
    qsort(errors, (size_t)result.rays, sizeof(double), compare_doubles);
    result.median = errors[result.rays / 2];
  }
  printf("  K=%d B=%d: %d rays, %d within 2 deg, median %.3f deg, %d failed calls\n", layers,
    bounces, result.rays, result.close, result.median, result.failures);
  return result;
}

/* What a comparison of a scene the trace handles must show: no failed call, more than
 * `min_rays` rays, at least `close_share` of them within 2 degrees of the exact exit, and a
 * median error under `max_median` degrees. */
static void check_close(const comparison* c, int min_rays, double close_share, double max_median)
{
  CHECK(c->failures == 0);
  CHECK(c->rays > min_rays);
  CHECK(c->close >= close_share * c->rays);
  CHECK(c->median < max_median);
}

static void test_single_sphere(void)
{
  const sphere ball = { { 0.0, 0.0, -6.0 }, 1.0, 0 };
  const double ior[MAX_SPHERES] = { 1.5, 1.5, 1.5 };
  scene s;
  comparison c;
  make_scene(&s, &ball, 1, ior);
  printf("one ball, IOR 1.5:\n");
  c = compare(&s, 2, 0, 2);
  /* What is left is the layers' texels (the ball turns by 1.9 degrees per texel here): with
   * the normal read at the nearest texel the median was 0.67 degrees; filtered over the four
   * texels around the exit (rfk_peel_normal) 0.03, 8 rays beyond 2 degrees; with the crossing
   * placed on the filtered depth too (rfk_peel_depth_filtered) 0.006, none. */
  check_close(&c, 500, 1.0, 0.02);
  /* K beyond the layers the scene has changes nothing (deep peeling on a convex shape). */
  {
    const comparison deep = compare(&s, 8, 4, 2);
    CHECK(deep.failures == 0);
    CHECK(deep.rays == c.rays && deep.close == c.close && deep.median == c.median);
  }
}

static void test_nested(void)
{
  const sphere balls[2] = { { { 0.0, 0.0, -6.0 }, 1.2, 0 }, { { 0.1, 0.0, -6.0 }, 0.6, 1 } };
  const double ior[MAX_SPHERES] = { 1.33, 1.8, 1.0 };
  scene s;
  comparison two;
  comparison four;
  make_scene(&s, balls, 2, ior);
  printf("a ball (1.8) inside a ball (1.33), rays through both:\n");
  two = compare(&s, 2, 0, 4);
  four = compare(&s, 4, 0, 4);
  /* Two layers cannot see the inner ball; four follow the ray through it. With the crossings
   * placed on the layers' depths a texel at a time, 86 % within 2 degrees and a median of 0.122;
   * on the filtered depths (rfk_peel_depth_filtered) 89 % and 0.035. */
  check_close(&four, 100, 0.88, 0.08);
  CHECK(two.close < 0.05 * two.rays);
}

static void test_overlapping(void)
{
  const sphere balls[2] = { { { -0.5, 0.0, -6.0 }, 0.6, 0 }, { { 0.3, 0.2, -8.0 }, 0.8, 1 } };
  const double ior[MAX_SPHERES] = { 1.5, 1.2, 1.0 };
  scene s;
  comparison c;
  make_scene(&s, balls, 2, ior);
  printf("two balls one behind the other, rays through both:\n");
  c = compare(&s, 4, 0, 4);
  /* A texel's depth at a time: 84 % within 2 degrees, median 0.226; filtered: 87 %, 0.071. */
  check_close(&c, 100, 0.86, 0.15);
}

static void test_bad_input(void)
{
  const double ior[1] = { 1.5 };
  const double bad_ior[1] = { -1.0 };
  scene s;
  rf_peel_input input;
  rf_peel_result result;
  int k;
  make_camera(&s);
  s.count = 0;
  input.P1 = rf_vec3_make(0.0, 0.0, -5.0);
  input.T1 = rf_vec3_make(0.0, 0.0, -1.0);
  input.material = 0;
  input.layers = 4;
  input.interfaces = 3;
  input.bounces = 0;
  input.tir_clamp = 1;
  input.extent = 2.0;
  input.depth_range[0] = 4.0;
  input.depth_range[1] = 6.0;
  for (k = 0; k < 16; ++k)
  {
    input.projection[k] = s.projection[k];
  }
  input.viewport[0] = SIZE;
  input.viewport[1] = SIZE;
  input.parallel = 0;
  input.ior = ior;
  input.sheet = NULL;
  input.materials = 1;
  /* No layers at all (not even the entry's): the trace still ends, finite. */
  CHECK(rf_peel_trace(&input, sample_layers, &s, &result) == RF_OK);
  CHECK(rf_vec3_is_finite(result.P2) && rf_vec3_is_finite(result.T2) && result.bounces == 0);
  CHECK(rf_peel_trace(NULL, sample_layers, &s, &result) == RF_ERR_NULL_ARGUMENT);
  CHECK(rf_peel_trace(&input, NULL, &s, &result) == RF_ERR_NULL_ARGUMENT);
  input.layers = 9;
  CHECK(rf_peel_trace(&input, sample_layers, &s, &result) == RF_ERR_STEPS_OUT_OF_RANGE);
  input.layers = 4;
  input.material = 1;
  CHECK(rf_peel_trace(&input, sample_layers, &s, &result) == RF_ERR_STEPS_OUT_OF_RANGE);
  input.material = 0;
  input.T1 = rf_vec3_make(0.0, 0.0, 0.0);
  CHECK(rf_peel_trace(&input, sample_layers, &s, &result) == RF_ERR_DEGENERATE_DIRECTION);
  input.T1 = rf_vec3_make(0.0, NAN, -1.0);
  CHECK(rf_peel_trace(&input, sample_layers, &s, &result) == RF_ERR_NOT_FINITE);
  input.T1 = rf_vec3_make(0.0, 0.0, -1.0);
  input.ior = bad_ior;
  CHECK(rf_peel_trace(&input, sample_layers, &s, &result) == RF_ERR_IOR_NOT_POSITIVE);
  input.ior = ior;
  input.extent = 0.0;
  CHECK(rf_peel_trace(&input, sample_layers, &s, &result) == RF_ERR_EMPTY_RANGE);
  input.extent = 2.0;
  input.depth_range[0] = 7.0;
  CHECK(rf_peel_trace(&input, sample_layers, &s, &result) == RF_ERR_EMPTY_RANGE);
  input.depth_range[0] = 4.0;
  input.depth_range[1] = INFINITY;
  CHECK(rf_peel_trace(&input, sample_layers, &s, &result) == RF_ERR_NOT_FINITE);
}

/* Where two layers hold the glass (one glass's front and back at every pixel), a ray that has
 * left it is not searched for more: only glass behind glass, which needs a third layer
 * somewhere, could be met on its way (rfk_peel_may_meet_more). Two layers captured by PEEL 2
 * (capped) may have more behind them. */
static void test_leaving_two_layers(void)
{
  rfk_peel_ray ray =
    rfk_peel_entered(rf_vec3_make(0.0, 0.0, -5.0), rf_vec3_make(0.0, 0.0, -1.0), 0);
  CHECK(rfk_peel_may_meet_more(2, RF_FALSE, ray)); /* inside: its way out is still to find */
  ray.stack = rfk_peel_stack_pop(ray.stack);
  CHECK(rfk_peel_stack_top(ray.stack) < 0);
  CHECK(!rfk_peel_may_meet_more(2, RF_FALSE, ray));
  CHECK(!rfk_peel_may_meet_more(1, RF_FALSE, ray));
  CHECK(rfk_peel_may_meet_more(2, RF_TRUE, ray)); /* K = 2 found 2: there may be more */
  CHECK(rfk_peel_may_meet_more(3, RF_FALSE, ray)); /* a third layer: glass behind glass */
  CHECK(rfk_peel_may_meet_more(8, RF_FALSE, ray));
}

int main(void)
{
  test_single_sphere();
  test_nested();
  test_overlapping();
  test_bad_input();
  test_leaving_two_layers();
  return RF_TEST_SUMMARY();
}
