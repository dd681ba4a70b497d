/* Unit tests of rf_metrics against values computed by hand (in the comments). */
#include "rf_metrics.h"

#include "rf_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define W 24
#define H 20
#define N (W * H)
#define C1 (0.01 * 0.01)
#define C2 (0.03 * 0.03)

/* A deterministic texture in [0.2, 0.7]: a few sines (no rand(), so results repeat). */
static void texture(float* image, int channels)
{
  int k;
  int c;
  for (k = 0; k < N; ++k)
  {
    const int x = k % W;
    const int y = k / W;
    for (c = 0; c < channels; ++c)
    {
      image[k * channels + c] =
        (float)(0.45 + 0.25 * sin(0.7 * x + 1.3 * c) * cos(0.45 * y - 0.2 * c));
    }
  }
}

static void test_identical(void)
{
  static float a[3 * N];
  double v = -1.0;
  texture(a, 3);
  CHECK(rf_rmse(a, a, N, 3, NULL, &v) == RF_OK);
  CHECK_NEAR(v, 0.0, 0.0);
  CHECK(rf_psnr(a, a, N, 3, NULL, &v) == RF_OK);
  CHECK_NEAR(v, RF_PSNR_CAP_DB, 0.0);
  CHECK(rf_ssim(a, a, W, H, 3, NULL, &v) == RF_OK);
  CHECK_NEAR(v, 1.0, 1e-12);
}

static void test_constant_offset(void)
{
  static float a[3 * N];
  static float b[3 * N];
  double v = -1.0;
  int k;
  texture(a, 3);
  for (k = 0; k < 3 * N; ++k)
  {
    b[k] = a[k] + 0.1f; /* stays inside [0, 1]: no clamping */
  }
  /* Every difference is 0.1 (to float rounding): RMSE 0.1, PSNR 20 log10(1 / 0.1) = 20 dB. */
  CHECK(rf_rmse(a, b, N, 3, NULL, &v) == RF_OK);
  CHECK_NEAR(v, 0.1, 1e-6);
  CHECK(rf_psnr(a, b, N, 3, NULL, &v) == RF_OK);
  CHECK_NEAR(v, 20.0, 1e-4);
}

static void test_rmse_by_hand(void)
{
  /* Two 1-channel pixels differing by 0.3 and 0.4: sqrt((0.09 + 0.16) / 2) = 0.35355339. */
  const float a[3] = { 0.0f, 0.0f, 0.9f };
  const float b[3] = { 0.3f, 0.4f, 0.0f };
  const unsigned char mask[3] = { 1, 1, 0 };
  double v = -1.0;
  CHECK(rf_rmse(a, b, 3, 1, mask, &v) == RF_OK);
  CHECK_NEAR(v, sqrt(0.125), 1e-7);
  /* PSNR: 10 log10(1 / 0.125) = 9.0309 dB. */
  CHECK(rf_psnr(a, b, 3, 1, mask, &v) == RF_OK);
  CHECK_NEAR(v, 10.0 * log10(8.0), 1e-5);
}

static void test_clamp_and_mask(void)
{
  /* Values above 1 are what 8-bit output shows as 1: PSNR sees no difference, RMSE does. */
  const float a[2] = { 1.5f, 0.25f };
  const float b[2] = { 1.0f, 0.25f };
  const float nan_outside[2] = { NAN, 0.5f };
  const float other[2] = { 7.0f, 0.5f };
  const unsigned char none[2] = { 0, 0 };
  const unsigned char second[2] = { 0, 1 };
  double v = -1.0;
  CHECK(rf_psnr(a, b, 2, 1, NULL, &v) == RF_OK);
  CHECK_NEAR(v, RF_PSNR_CAP_DB, 0.0);
  CHECK(rf_rmse(a, b, 2, 1, NULL, &v) == RF_OK);
  CHECK_NEAR(v, sqrt(0.25 / 2.0), 1e-7);
  /* Only masked pixels count: the NaN and the 7 lie outside the mask. */
  CHECK(rf_rmse(nan_outside, other, 2, 1, second, &v) == RF_OK);
  CHECK_NEAR(v, 0.0, 0.0);
  CHECK(rf_rmse(nan_outside, other, 2, 1, NULL, &v) == RF_ERR_NOT_FINITE);
  CHECK(rf_rmse(a, b, 2, 1, none, &v) == RF_REF_ERR_NO_SAMPLES);
  CHECK(rf_ssim(a, b, 2, 1, 1, none, &v) == RF_REF_ERR_NO_SAMPLES);
  CHECK(rf_rmse(NULL, b, 2, 1, NULL, &v) == RF_ERR_NULL_ARGUMENT);
  CHECK(rf_rmse(a, b, 2, 0, NULL, &v) == RF_REF_ERR_BAD_OPTION);
  CHECK(rf_ssim(a, b, 2, 1, 2, NULL, &v) == RF_REF_ERR_BAD_OPTION);
  CHECK(rf_ssim(a, b, 0, 1, 1, NULL, &v) == RF_REF_ERR_BAD_OPTION);
}

static void test_ssim_constant(void)
{
  /* Constant images have no variance: SSIM = (2 mu_a mu_b + C1) / (mu_a^2 + mu_b^2 + C1),
   * here (0.48 + 1e-4) / (0.52 + 1e-4) = 0.923092... */
  static float a[N];
  static float b[N];
  double v = -1.0;
  int k;
  for (k = 0; k < N; ++k)
  {
    a[k] = 0.4f;
    b[k] = 0.6f;
  }
  CHECK(rf_ssim(a, b, W, H, 1, NULL, &v) == RF_OK);
  CHECK_NEAR(v, (2.0 * 0.4 * 0.6 + C1) / (0.16 + 0.36 + C1), 1e-6);
}

static void test_ssim_luminance(void)
{
  /* Pure red against pure green: Y = 0.2126 and 0.7152 (Rec. 709), constant images. */
  static float a[3 * N];
  static float b[3 * N];
  const double ya = 0.2126;
  const double yb = 0.7152;
  double v = -1.0;
  int k;
  memset(a, 0, sizeof(a));
  memset(b, 0, sizeof(b));
  for (k = 0; k < N; ++k)
  {
    a[3 * k] = 1.0f;
    b[3 * k + 1] = 1.0f;
  }
  CHECK(rf_ssim(a, b, W, H, 3, NULL, &v) == RF_OK);
  CHECK_NEAR(v, (2.0 * ya * yb + C1) / (ya * ya + yb * yb + C1), 1e-6);
}

static void test_ssim_single_pixel_mask(void)
{
  /* With one masked pixel the window holds that pixel alone (weights are renormalized over
   * the mask): no variance, so SSIM = (2ab + C1) / (a^2 + b^2 + C1), whatever lies around. */
  static float a[N];
  static float b[N];
  static unsigned char mask[N];
  const int k = 7 * W + 11;
  double v = -1.0;
  texture(a, 1);
  texture(b, 1);
  memset(mask, 0, sizeof(mask));
  mask[k] = 1;
  a[k] = 0.3f;
  b[k] = 0.5f;
  CHECK(rf_ssim(a, b, W, H, 1, mask, &v) == RF_OK);
  CHECK_NEAR(v, (2.0 * 0.3 * 0.5 + C1) / (0.09 + 0.25 + C1), 1e-6);
}

static void test_ssim_structure(void)
{
  /* b = 1 - a keeps each local variance and negates the covariance, so the structure term
   * (2 cov + C2) / (var_a + var_b + C2) is about -1: mean SSIM must be negative. Adding a
   * little texture lowers SSIM below 1 but keeps it high; SSIM is symmetric. */
  static float a[N];
  static float b[N];
  static float noisy[N];
  double inverted = 0.0;
  double ab = 0.0;
  double ba = 0.0;
  int k;
  texture(a, 1);
  for (k = 0; k < N; ++k)
  {
    b[k] = 1.0f - a[k];
    noisy[k] = a[k] + 0.02f * (float)(((k * 7919) % 13) - 6) / 6.0f;
  }
  CHECK(rf_ssim(a, b, W, H, 1, NULL, &inverted) == RF_OK);
  CHECK(inverted < -0.5);
  CHECK(rf_ssim(a, noisy, W, H, 1, NULL, &ab) == RF_OK);
  CHECK(rf_ssim(noisy, a, W, H, 1, NULL, &ba) == RF_OK);
  CHECK(ab > 0.5 && ab < 0.999);
  CHECK_NEAR(ab, ba, 1e-12);
}

static void test_angular(void)
{
  /* Angles 0, 45 (unnormalized input), 90 and 180 degrees; one zero vector (invalid) and one
   * unmasked pixel. mean = (0 + 45 + 90 + 180) / 4 = 78.75, p95 = ceil(0.95 * 4) = 4th = 180. */
  const float a[18] = { 0, 0, -1, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0 };
  const float b[18] = { 0, 0, -2, 1, 1, 0, 0, 1, 0, 0, -1, 0, 1, 0, 0, 0, 1, 0 };
  const unsigned char mask[6] = { 1, 1, 1, 1, 1, 0 };
  rf_error_stats s;
  CHECK(rf_angular_error(a, b, 6, mask, &s) == RF_OK);
  CHECK(s.count == 4);
  CHECK(s.invalid == 1);
  CHECK_NEAR(s.mean, 78.75, 1e-9);
  CHECK_NEAR(s.max, 180.0, 1e-9);
  CHECK_NEAR(s.p95, 180.0, 1e-9);
  /* A single 90 degree pair. */
  CHECK(rf_angular_error(a + 6, b + 6, 1, NULL, &s) == RF_OK);
  CHECK_NEAR(s.mean, 90.0, 1e-12);
  /* Small angles stay accurate: 1e-4 rad between (1, 0, 0) and (cos, sin, 0). */
  {
    const float c[3] = { 1.0f, 0.0f, 0.0f };
    const float d[3] = { 1.0f, 1e-4f, 0.0f };
    CHECK(rf_angular_error(c, d, 1, NULL, &s) == RF_OK);
    CHECK_NEAR(s.mean, atan(1e-4) * 180.0 / 3.14159265358979323846, 1e-9);
  }
  CHECK(rf_angular_error(a + 12, b + 12, 1, NULL, &s) == RF_REF_ERR_NO_SAMPLES);
}

static void test_percentile(void)
{
  /* 20 pixels with angles 1..20 degrees about z: p95 = ceil(0.95 * 20) = 19th = 19. */
  float a[60];
  float b[60];
  rf_error_stats s;
  int k;
  for (k = 0; k < 20; ++k)
  {
    const double t = (k + 1) * 3.14159265358979323846 / 180.0;
    a[3 * k] = 1.0f;
    a[3 * k + 1] = 0.0f;
    a[3 * k + 2] = 0.0f;
    b[3 * k] = (float)cos(t);
    b[3 * k + 1] = (float)sin(t);
    b[3 * k + 2] = 0.0f;
  }
  CHECK(rf_angular_error(a, b, 20, NULL, &s) == RF_OK);
  CHECK_NEAR(s.p95, 19.0, 1e-5);
  CHECK_NEAR(s.max, 20.0, 1e-5);
  CHECK_NEAR(s.mean, 10.5, 1e-5);
}

static void test_position(void)
{
  /* |(3, 4, 0)| = 5 against a diagonal of 10: 0.5; the second pixel is exact. */
  const float a[6] = { 0, 0, 0, 1, 1, 1 };
  const float b[6] = { 3, 4, 0, 1, 1, 1 };
  rf_error_stats s;
  double share = -1.0;
  const unsigned char flags[4] = { 0, 1, 0, 1 };
  const unsigned char mask[4] = { 1, 1, 1, 0 };
  CHECK(rf_position_error(a, b, 2, NULL, 10.0, &s) == RF_OK);
  CHECK_NEAR(s.max, 0.5, 1e-12);
  CHECK_NEAR(s.mean, 0.25, 1e-12);
  CHECK(rf_position_error(a, b, 2, NULL, 0.0, &s) == RF_ERR_EMPTY_RANGE);
  CHECK(rf_position_error(a, b, 2, NULL, NAN, &s) == RF_ERR_NOT_FINITE);
  /* One of the three masked pixels is flagged. */
  CHECK(rf_flag_share(flags, 4, mask, &share) == RF_OK);
  CHECK_NEAR(share, 1.0 / 3.0, 1e-12);
  CHECK(rf_flag_share(NULL, 4, mask, &share) == RF_ERR_NULL_ARGUMENT);
}

int main(void)
{
  test_identical();
  test_constant_offset();
  test_rmse_by_hand();
  test_clamp_and_mask();
  test_ssim_constant();
  test_ssim_luminance();
  test_ssim_single_pixel_mask();
  test_ssim_structure();
  test_angular();
  test_percentile();
  test_position();
  return RF_TEST_SUMMARY();
}
