/* libFuzzer target over the C core's public functions (module/core). The first byte picks a
 * function; the rest feeds its arguments, biased toward the values that break numerics (NaN,
 * infinities, zeros of both signs, subnormals, the largest doubles, 1 +/- 1 ulp). Each call is
 * checked against its documented contract, and a violation aborts (a crash is a finding):
 *  - statuses are the documented ones, and on error the outputs are left alone;
 *  - on success directions are finite and unit, reflectances in [0, 1], angles in range;
 *  - the search stays on its segment (beta in [0, 1]) and gives finite points; the shader's
 *    whole search (rf_dir_search) gives finite points, and P1 itself when nothing was captured;
 *  - ISR's estimate is finite on success.
 * Built with clang -fsanitize=fuzzer,address,undefined (tests/fuzz/CMakeLists.txt); the same
 * file without libFuzzer replays the corpus (fuzz_replay.c). */
#include "rf_dir_search.h"
#include "rf_environment.h"
#include "rf_isr.h"
#include "rf_optics.h"
#include "rf_validate.h"

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct fuzz_input
{
  const uint8_t* data;
  size_t size;
} fuzz_input;

static uint8_t take_byte(fuzz_input* in)
{
  uint8_t b = 0;
  if (in->size > 0)
  {
    b = in->data[0];
    ++in->data;
    --in->size;
  }
  return b;
}

/* A double: one selector byte, then (for raw values) eight bytes of bit pattern. */
static double take_double(fuzz_input* in)
{
  static const double special[] = { 0.0, -0.0, 1.0, -1.0, 0.5, 2.0, 1.5, 1.0 / 1.5, 1e-6, 1e-12,
    1e-300, 4.9e-324, DBL_MIN, DBL_MAX, -DBL_MAX, 1e300, 1e7, 1e3, INFINITY, -INFINITY, NAN,
    1.0 + DBL_EPSILON, 1.0 - DBL_EPSILON / 2.0, 1.000001, 0.999999, 1000.0, 0.75 };
  const size_t count = sizeof(special) / sizeof(special[0]);
  const uint8_t selector = take_byte(in);
  if (selector < 2 * count)
  {
    return special[selector % count];
  }
  if (selector < 200)
  {
    /* A moderate value: sign, mantissa from two bytes, exponent in [-8, 8]. */
    const double mantissa = (double)((take_byte(in) << 8) | take_byte(in)) / 65535.0;
    const int exponent = (int)(take_byte(in) % 17) - 8;
    return ldexp((selector & 1) ? -mantissa : mantissa, exponent);
  }
  {
    uint64_t bits = 0;
    double value;
    int i;
    for (i = 0; i < 8; ++i)
    {
      bits = (bits << 8) | take_byte(in);
    }
    memcpy(&value, &bits, sizeof(value));
    return value;
  }
}

static rf_vec3 take_vec3(fuzz_input* in)
{
  const double x = take_double(in);
  const double y = take_double(in);
  const double z = take_double(in);
  return rf_vec3_make(x, y, z);
}

static void fail(const char* what, int line)
{
  fprintf(stderr, "fuzz_core: contract violated at line %d: %s\n", line, what);
  abort();
}
#define REQUIRE(cond)                                                                             \
  do                                                                                               \
  {                                                                                                \
    if (!(cond))                                                                                   \
    {                                                                                              \
      fail(#cond, __LINE__);                                                                       \
    }                                                                                              \
  } while (0)

static int is_unit(rf_vec3 v)
{
  return rf_vec3_is_finite(v) && fabs(rf_vec3_length(v) - 1.0) < 1e-9;
}

static int is_status(rf_status s)
{
  return s >= RF_OK && s <= RF_ERR_EMPTY_RANGE;
}

static void check_refract(fuzz_input* in, int clamped)
{
  const rf_vec3 incident = take_vec3(in);
  const rf_vec3 normal = take_vec3(in);
  const double eta = take_double(in);
  const rf_vec3 sentinel = rf_vec3_make(7.0, -7.0, 7.0);
  rf_vec3 t = sentinel;
  const rf_status s =
    clamped ? rf_refract_clamped(incident, normal, eta, &t) : rf_refract(incident, normal, eta, &t);
  REQUIRE(is_status(s));
  if (s == RF_OK || s == RF_TIR)
  {
    /* Documented: a unit direction, also for extreme (valid) indices. */
    REQUIRE(is_unit(t));
    REQUIRE(rf_validate_ior(eta) == RF_OK);
    REQUIRE(rf_vec3_is_finite(incident) && rf_vec3_is_finite(normal));
    if (s == RF_OK)
    {
      /* The transmitted ray continues away from the side it came from. */
      const rf_vec3 n = rf_vec3_normalize(normal);
      const rf_vec3 i = rf_vec3_normalize(incident);
      REQUIRE(rf_vec3_dot(i, n) * rf_vec3_dot(t, n) >= -1e-9);
    }
  }
  else
  {
    REQUIRE(memcmp(&t, &sentinel, sizeof(t)) == 0);
    REQUIRE(s != RF_ERR_NULL_ARGUMENT);
  }
  if (clamped)
  {
    REQUIRE(rf_refract_clamped(incident, normal, eta, NULL) != RF_OK);
  }
}

static void check_fresnel(fuzz_input* in)
{
  const double c = take_double(in);
  const double eta = take_double(in);
  const double n2 = take_double(in);
  const double exact = rf_fresnel_dielectric(c, eta);
  const double schlick = rf_fresnel_schlick(c, eta);
  const double critical = rf_critical_angle(eta);
  const double brewster = rf_brewster_angle(eta, n2);
  const int valid = !isnan(c) && rf_validate_ior(eta) == RF_OK;
  REQUIRE(valid ? (exact >= 0.0 && exact <= 1.0) : isnan(exact));
  REQUIRE(valid ? (schlick >= 0.0 && schlick <= 1.0) : isnan(schlick));
  REQUIRE(critical == -1.0 || (critical > 0.0 && critical <= 2.0 * atan(1.0)));
  REQUIRE(brewster == -1.0 || (brewster >= 0.0 && brewster <= 2.0 * atan(1.0)));
}

static double sample_from_data(void* context, const double tc[2])
{
  /* A depth map made of the fuzz input: the texel picked by tc (when finite). */
  const fuzz_input* map = (const fuzz_input*)context;
  size_t index = 0;
  double depth;
  if (map->size < sizeof(double))
  {
    return 0.0;
  }
  if (isfinite(tc[0]) && isfinite(tc[1]) && isfinite(tc[0] * 7.0 + tc[1] * 13.0))
  {
    const double u = fmod(fabs(tc[0] * 7.0 + tc[1] * 13.0), 1.0);
    index = (size_t)(u * (double)(map->size / sizeof(double)));
    if (index >= map->size / sizeof(double))
    {
      index = 0;
    }
  }
  memcpy(&depth, map->data + index * sizeof(double), sizeof(depth));
  return depth;
}

/* The shader's search on the same inputs; its settings from bits of the step count, so that
 * no byte is taken (the depth map is the rest of the input). */
static void check_shader_search(fuzz_input* in, rf_vec3 P1, rf_vec3 T1, double depth_min,
  double depth_max, const double projection[16], int steps)
{
  rf_dir_search_input input = { .P1 = P1, .T1 = T1, .depth_min = depth_min,
    .depth_max = depth_max, .viewport = { 64, 48 }, .steps = steps, .adaptive = steps & 1,
    .secant = (steps >> 1) & 1, .parallel = (steps >> 2) & 1 };
  rf_dir_search_result result;
  rf_dir_search_result untouched;
  rf_status s;
  memcpy(input.projection, projection, sizeof(input.projection));
  memset(&untouched, 0x5a, sizeof(untouched));
  result = untouched;
  s = rf_dir_search(&input, sample_from_data, in, &result);
  REQUIRE(is_status(s) && s != RF_TIR && s != RF_ERR_NULL_ARGUMENT);
  if (s != RF_OK)
  {
    REQUIRE(memcmp(&result, &untouched, sizeof(result)) == 0);
    REQUIRE(rf_validate_cbs_steps(steps) == RF_OK || s == RF_ERR_STEPS_OUT_OF_RANGE ||
      s == RF_ERR_NOT_FINITE);
    return;
  }
  REQUIRE(rf_validate_cbs_steps(steps) == RF_OK);
  REQUIRE(rf_vec3_is_finite(result.P2) && isfinite(result.tc[0]) && isfinite(result.tc[1]));
  REQUIRE(result.found == 1 || (result.found == 0 && memcmp(&result.P2, &P1, sizeof(P1)) == 0));
  REQUIRE(result.found == 1 || !(depth_min <= depth_max));
}

static void check_search(fuzz_input* in)
{
  const rf_vec3 P1 = take_vec3(in);
  const rf_vec3 T1 = take_vec3(in);
  const double depth_min = take_double(in);
  const double depth_max = take_double(in);
  double projection[16] = { 1.2, 0, 0, 0, 0, 1.2, 0, 0, 0, 0, -1.02, -0.2, 0, 0, -1, 0 };
  const int steps = (int)(take_byte(in) % 20) - 2;
  const int fuzz_projection = take_byte(in) & 1;
  rf_dir_segment seg;
  rf_dir_segment untouched;
  rf_status s;
  int i;
  if (fuzz_projection)
  {
    for (i = 0; i < 16; ++i)
    {
      projection[i] = take_double(in);
    }
  }
  check_shader_search(in, P1, T1, depth_min, depth_max, projection, steps);
  memset(&untouched, 0x5a, sizeof(untouched));
  seg = untouched;
  s = rf_dir_segment_init(P1, T1, depth_min, depth_max, projection, &seg);
  REQUIRE(is_status(s) && s != RF_TIR && s != RF_ERR_NULL_ARGUMENT);
  if (s != RF_OK)
  {
    REQUIRE(memcmp(&seg, &untouched, sizeof(seg)) == 0);
    return;
  }
  REQUIRE(rf_vec3_is_finite(seg.S) && rf_vec3_is_finite(seg.E));
  REQUIRE(isfinite(seg.k1) && isfinite(seg.k2));
  REQUIRE(isfinite(seg.ts[0]) && isfinite(seg.ts[1]) && isfinite(seg.te[0]) &&
    isfinite(seg.te[1]));
  /* eq. 9 is 0 at S and 1 at E up to rounding. */
  REQUIRE(fabs(rf_dir_alpha(&seg, seg.S.z)) < 1e-6 || fabs(seg.S.z - seg.E.z) < 1e-9 * fabs(seg.S.z));
  {
    rf_vec3 P2 = rf_vec3_make(9.0, 9.0, 9.0);
    double tc[2] = { 9.0, 9.0 };
    double beta = 9.0;
    const rf_status c = rf_dir_cbs(&seg, steps, sample_from_data, in, &P2, tc, &beta);
    if (rf_validate_cbs_steps(steps) != RF_OK)
    {
      REQUIRE(c == RF_ERR_STEPS_OUT_OF_RANGE && beta == 9.0);
      return;
    }
    REQUIRE(c == RF_OK);
    REQUIRE(beta >= 0.0 && beta <= 1.0 - rf_cbs_error_bound(steps) + 1e-15);
    REQUIRE(rf_vec3_is_finite(P2));
  }
}

static void check_misc(fuzz_input* in)
{
  double direction[3];
  double rgb[3] = { NAN, NAN, NAN };
  const double absorption[3] = { take_double(in), take_double(in), take_double(in) };
  const double ior = take_double(in);
  const int steps = (int)(int8_t)take_byte(in);
  const rf_status a = rf_validate_absorption(absorption);
  const rf_vec3 v = take_vec3(in);
  const rf_vec3 u = rf_vec3_normalize(v);
  int k;
  direction[0] = take_double(in);
  direction[1] = take_double(in);
  direction[2] = take_double(in);
  rf_builtin_environment(direction, rgb);
  for (k = 0; k < 3; ++k)
  {
    REQUIRE(isfinite(rgb[k]) && rgb[k] >= 0.0 && rgb[k] <= 4.0);
  }
  REQUIRE(a == RF_OK || a == RF_ERR_NOT_FINITE || a == RF_ERR_ABSORPTION_NEGATIVE);
  for (k = 0; k < 3; ++k)
  {
    if (a == RF_OK)
    {
      REQUIRE(isfinite(absorption[k]) && absorption[k] >= 0.0);
    }
  }
  REQUIRE((rf_validate_ior(ior) == RF_OK) == (isfinite(ior) && ior > 0.0));
  REQUIRE((rf_validate_cbs_steps(steps) == RF_OK) == (steps >= 0 && steps <= RF_CBS_MAX_STEPS));
  REQUIRE(rf_status_message((rf_status)steps) != NULL);
  REQUIRE(rf_vec3_length(u) == 0.0 || is_unit(u));
  REQUIRE(rf_vec3_length(u) > 0.0 || !rf_vec3_is_finite(v) || (v.x == 0.0 && v.y == 0.0 && v.z == 0.0));
  {
    /* ISR's estimate on values already taken. */
    const rf_vec3 w = rf_vec3_make(direction[0], direction[1], direction[2]);
    double d = 9.0;
    rf_status s = rf_isr_distance(absorption[0], absorption[1], v, w, u, ior, &d);
    REQUIRE(is_status(s) && s != RF_TIR && s != RF_ERR_NULL_ARGUMENT);
    REQUIRE(s == RF_OK ? isfinite(d) : d == 9.0);
    s = rf_isr_view_distance(absorption[2], w, v, &d);
    REQUIRE(is_status(s) && s != RF_TIR && s != RF_ERR_NULL_ARGUMENT);
    REQUIRE(s == RF_OK ? isfinite(d) : 1);
  }
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  fuzz_input in;
  in.data = data;
  in.size = size;
  switch (take_byte(&in) % 5)
  {
    case 0:
      check_refract(&in, 0);
      break;
    case 1:
      check_refract(&in, 1);
      break;
    case 2:
      check_fresnel(&in);
      break;
    case 3:
      check_search(&in);
      break;
    default:
      check_misc(&in);
      break;
  }
  return 0;
}
