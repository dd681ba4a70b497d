/* Bad input to the C core's public functions: each answers NULL pointers, NaN and infinite
 * values, zero vectors, IOR <= 0 and negative absorption with its documented status (or NaN /
 * -1 where the function returns a number) and leaves its outputs alone on error.
 * Per-actor absorption does not exist in the render pass yet: rf_validate_absorption is the
 * check it will use, tested here on its own. */
#include "rf_dir_search.h"
#include "rf_environment.h"
#include "rf_optics.h"
#include "rf_validate.h"

#include "rf_test.h"

#include <math.h>
#include <string.h>

static int same_vec(rf_vec3 a, rf_vec3 b)
{
  return memcmp(&a, &b, sizeof(a)) == 0;
}

static void test_absorption(void)
{
  const double negative[3] = { 0.5, -1e-12, 0.0 };
  const double negative_zero[3] = { -0.0, 0.0, 0.0 };
  const double minus_inf[3] = { 0.0, -INFINITY, 0.0 };
  const double nan_channel[3] = { NAN, 0.0, 0.0 };
  const char* message = rf_status_message(RF_ERR_ABSORPTION_NEGATIVE);
  CHECK(rf_validate_absorption(negative) == RF_ERR_ABSORPTION_NEGATIVE);
  /* -0.0 is zero: no amplification. */
  CHECK(rf_validate_absorption(negative_zero) == RF_OK);
  CHECK(rf_validate_absorption(minus_inf) == RF_ERR_NOT_FINITE);
  CHECK(rf_validate_absorption(nan_channel) == RF_ERR_NOT_FINITE);
  CHECK(rf_validate_absorption(NULL) == RF_ERR_NULL_ARGUMENT);
  CHECK(message != NULL && strstr(message, "negative") != NULL);
}

static void test_ior(void)
{
  const double bad[] = { 0.0, -0.0, -1.0, -INFINITY, INFINITY, NAN, -1e-300 };
  const rf_vec3 d = rf_vec3_make(0.0, 0.0, -1.0);
  const rf_vec3 n = rf_vec3_make(0.0, 0.0, 1.0);
  size_t i;
  for (i = 0; i < sizeof(bad) / sizeof(bad[0]); ++i)
  {
    const rf_vec3 sentinel = rf_vec3_make(7.0, 7.0, 7.0);
    rf_vec3 t = sentinel;
    CHECK(rf_validate_ior(bad[i]) != RF_OK);
    CHECK(rf_refract(d, n, bad[i], &t) == rf_validate_ior(bad[i]));
    CHECK(same_vec(t, sentinel));
    CHECK(rf_refract_clamped(d, n, bad[i], &t) == rf_validate_ior(bad[i]));
    CHECK(same_vec(t, sentinel));
    CHECK(isnan(rf_fresnel_dielectric(0.5, bad[i])));
    CHECK(isnan(rf_fresnel_schlick(0.5, bad[i])));
    CHECK(rf_critical_angle(bad[i]) == -1.0);
    CHECK(rf_brewster_angle(bad[i], 1.5) == -1.0);
    CHECK(rf_brewster_angle(1.0, bad[i]) == -1.0);
  }
  /* Denormal and huge but finite indices are legal and give finite answers. */
  {
    rf_vec3 t;
    const rf_status s = rf_refract(rf_vec3_make(0.3, 0.0, -1.0), n, 1e-300, &t);
    CHECK(s == RF_OK && rf_vec3_is_finite(t) && fabs(rf_vec3_length(t) - 1.0) < 1e-12);
    CHECK(rf_refract_clamped(rf_vec3_make(0.3, 0.0, -1.0), n, 1e300, &t) == RF_TIR);
    CHECK(rf_vec3_is_finite(t) && fabs(rf_vec3_length(t) - 1.0) < 1e-12);
    CHECK(rf_fresnel_dielectric(0.5, 1e300) == 1.0);
  }
}

static void test_vectors(void)
{
  const rf_vec3 ok = rf_vec3_make(0.0, 0.0, -1.0);
  const rf_vec3 up = rf_vec3_make(0.0, 0.0, 1.0);
  const rf_vec3 zero = rf_vec3_make(0.0, 0.0, 0.0);
  const rf_vec3 tiny = rf_vec3_make(0.0, 4.9e-324, 0.0);
  const rf_vec3 with_nan = rf_vec3_make(NAN, 0.0, 1.0);
  const rf_vec3 with_inf = rf_vec3_make(0.0, INFINITY, 1.0);
  rf_vec3 t = rf_vec3_make(7.0, 7.0, 7.0);
  CHECK(rf_refract(zero, up, 1.5, &t) == RF_ERR_DEGENERATE_DIRECTION);
  CHECK(rf_refract(ok, zero, 1.5, &t) == RF_ERR_DEGENERATE_DIRECTION);
  CHECK(rf_refract(with_nan, up, 1.5, &t) == RF_ERR_NOT_FINITE);
  CHECK(rf_refract(ok, with_inf, 1.5, &t) == RF_ERR_NOT_FINITE);
  CHECK(rf_refract_clamped(ok, with_nan, 1.5, &t) == RF_ERR_NOT_FINITE);
  CHECK(rf_refract(ok, up, 1.5, NULL) == RF_ERR_NULL_ARGUMENT);
  CHECK(rf_refract_clamped(ok, up, 1.5, NULL) == RF_ERR_NULL_ARGUMENT);
  CHECK(t.x == 7.0 && t.y == 7.0 && t.z == 7.0);
  /* A subnormal normal still has a direction: normalizing divides by the largest part first
   * (here perpendicular to the ray: grazing entry). */
  CHECK(rf_refract(ok, tiny, 1.0 / 1.5, &t) == RF_OK && rf_vec3_is_finite(t));
  CHECK(isnan(rf_fresnel_dielectric(NAN, 1.5)));
  CHECK(isnan(rf_fresnel_schlick(NAN, 1.5)));
  /* Cosines outside [0, 1] (a raw dot product) are clamped, infinities too. */
  CHECK(rf_fresnel_dielectric(INFINITY, 1.5) >= 0.0 && rf_fresnel_dielectric(INFINITY, 1.5) <= 1.0);
  CHECK(rf_fresnel_dielectric(-2.0, 1.5) == rf_fresnel_dielectric(1.0, 1.5));
  /* Equal indices are no interface: nothing reflected, straight through, at any angle. */
  CHECK(rf_fresnel_dielectric(0.0, 1.0) == 0.0);
  CHECK(rf_fresnel_dielectric(1e-9, 1.0) == 0.0);
  CHECK(rf_fresnel_schlick(0.0, 1.0) == 0.0);
  CHECK(rf_refract(rf_vec3_make(1.0, 0.0, -1e-9), up, 1.0, &t) == RF_OK);
  CHECK(fabs(t.x - 1.0) < 1e-15 && fabs(t.z + 1e-9) < 1e-20); /* the incident ray itself */
}

static double sample_constant(void* context, const double tc[2])
{
  (void)tc;
  return *(const double*)context;
}

static void test_search(void)
{
  /* A 90 degree perspective projection, near 1, far 10 (row-major). */
  const double projection[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -11.0 / 9.0, -20.0 / 9.0, 0, 0,
    -1, 0 };
  double bad_projection[16];
  const rf_vec3 P1 = rf_vec3_make(0.0, 0.0, -2.0);
  const rf_vec3 T1 = rf_vec3_make(0.1, 0.0, -1.0);
  /* T1 parallel to the image plane, toward the eye, or zero. */
  const rf_vec3 degenerate_T1[] = { { 1, 0, 0 }, { 1, 0, 1e-13 }, { 0, 0, 1 }, { 0, 0, 0 } };
  size_t d;
  rf_dir_segment seg;
  rf_dir_segment untouched;
  double depth = 2.5;
  rf_vec3 P2;
  double tc[2];
  double beta;
  memset(&untouched, 0x5a, sizeof(untouched));
  seg = untouched;
  memcpy(bad_projection, projection, sizeof(projection));
  bad_projection[5] = NAN;
  CHECK(rf_dir_segment_init(P1, T1, 2.0, 3.0, NULL, &seg) == RF_ERR_NULL_ARGUMENT);
  CHECK(rf_dir_segment_init(P1, T1, 2.0, 3.0, projection, NULL) == RF_ERR_NULL_ARGUMENT);
  CHECK(rf_dir_segment_init(P1, T1, 2.0, 3.0, bad_projection, &seg) == RF_ERR_NOT_FINITE);
  CHECK(rf_dir_segment_init(rf_vec3_make(NAN, 0, -2), T1, 2.0, 3.0, projection, &seg) ==
    RF_ERR_NOT_FINITE);
  CHECK(rf_dir_segment_init(P1, rf_vec3_make(0, INFINITY, -1), 2.0, 3.0, projection, &seg) ==
    RF_ERR_NOT_FINITE);
  CHECK(rf_dir_segment_init(P1, T1, NAN, 3.0, projection, &seg) == RF_ERR_NOT_FINITE);
  CHECK(rf_dir_segment_init(P1, T1, 3.0, 2.0, projection, &seg) == RF_ERR_EMPTY_RANGE);
  CHECK(rf_dir_segment_init(P1, T1, 0.0, 2.0, projection, &seg) == RF_ERR_EMPTY_RANGE);
  /* Zmin = Zmax: S = E, k2 would divide by zero. */
  CHECK(rf_dir_segment_init(P1, T1, 2.5, 2.5, projection, &seg) == RF_ERR_EMPTY_RANGE);
  for (d = 0; d < sizeof(degenerate_T1) / sizeof(degenerate_T1[0]); ++d)
  {
    CHECK(rf_dir_segment_init(P1, degenerate_T1[d], 2.0, 3.0, projection, &seg) ==
      RF_ERR_DEGENERATE_DIRECTION);
  }
  CHECK(memcmp(&seg, &untouched, sizeof(seg)) == 0);
  /* Only now a valid segment, then bad search arguments. */
  CHECK(rf_dir_segment_init(P1, T1, 2.0, 3.0, projection, &seg) == RF_OK);
  CHECK(rf_dir_cbs(NULL, 5, sample_constant, &depth, &P2, tc, &beta) == RF_ERR_NULL_ARGUMENT);
  CHECK(rf_dir_cbs(&seg, 5, NULL, &depth, &P2, tc, &beta) == RF_ERR_NULL_ARGUMENT);
  CHECK(rf_dir_cbs(&seg, 5, sample_constant, &depth, NULL, tc, &beta) == RF_ERR_NULL_ARGUMENT);
  CHECK(rf_dir_cbs(&seg, -1, sample_constant, &depth, &P2, tc, &beta) ==
    RF_ERR_STEPS_OUT_OF_RANGE);
  CHECK(rf_dir_cbs(&seg, RF_CBS_MAX_STEPS + 1, sample_constant, &depth, &P2, tc, &beta) ==
    RF_ERR_STEPS_OUT_OF_RANGE);
  /* A NaN stored depth counts as empty: the search never advances. */
  depth = NAN;
  CHECK(rf_dir_cbs(&seg, 5, sample_constant, &depth, &P2, tc, &beta) == RF_OK);
  CHECK(beta == 0.0 && same_vec(P2, seg.S));
  depth = INFINITY; /* in front of everything: advances all the way */
  CHECK(rf_dir_cbs(&seg, 5, sample_constant, &depth, &P2, tc, &beta) == RF_OK);
  CHECK(fabs(beta - (1.0 - ldexp(1.0, -5))) < 1e-15 && rf_vec3_is_finite(P2));
  CHECK(isnan(rf_dir_alpha(NULL, -2.0)));
  rf_dir_texcoord(NULL, 0.5, tc);
  CHECK(isnan(tc[0]) && isnan(tc[1]));
  rf_dir_texcoord(&seg, 0.5, NULL); /* must not crash */
  CHECK(rf_cbs_error_bound(-3) == 1.0);
}

static void test_environment(void)
{
  const double zero[3] = { 0.0, 0.0, 0.0 };
  const double nan_dir[3] = { NAN, 1.0, 0.0 };
  const double inf_dir[3] = { INFINITY, 0.0, 0.0 };
  const double huge[3] = { 1e300, -1e300, 1e300 };
  const double* dirs[] = { zero, nan_dir, inf_dir, huge };
  size_t i;
  for (i = 0; i < sizeof(dirs) / sizeof(dirs[0]); ++i)
  {
    double rgb[3] = { NAN, NAN, NAN };
    rf_builtin_environment(dirs[i], rgb);
    CHECK(isfinite(rgb[0]) && isfinite(rgb[1]) && isfinite(rgb[2]));
  }
}

int main(void)
{
  test_absorption();
  test_ior();
  test_vectors();
  test_search();
  test_environment();
  return RF_TEST_SUMMARY();
}
