/* rf_metrics.c: RMSE, PSNR, SSIM, angular and position errors on masked pixels. */
#include "rf_metrics.h"

#include <math.h>
#include <stdlib.h>

/* SSIM (Wang et al. 2004, section III.C): 11x11 circular-symmetric Gaussian, sigma 1.5,
 * K1 = 0.01, K2 = 0.03, dynamic range L = 1. */
#define RF_SSIM_RADIUS 5
#define RF_SSIM_SIGMA 1.5
#define RF_SSIM_C1 (0.01 * 0.01)
#define RF_SSIM_C2 (0.03 * 0.03)
#define RF_PI 3.14159265358979323846

static int rf_masked(const unsigned char* mask, size_t k)
{
  return mask == NULL || mask[k] != 0;
}

static double rf_clamp01(double x)
{
  return x < 0.0 ? 0.0 : (x > 1.0 ? 1.0 : x);
}

/* Mean squared difference over masked pixels and all channels, optionally clamped. */
static rf_status rf_mean_squared(const float* a, const float* b, size_t pixel_count,
  int channels, const unsigned char* mask, int clamp, double* mse)
{
  double sum = 0.0;
  size_t count = 0;
  size_t k;
  int c;
  if (a == NULL || b == NULL || mse == NULL)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  if (channels < 1)
  {
    return RF_REF_ERR_BAD_OPTION;
  }
  for (k = 0; k < pixel_count; ++k)
  {
    if (!rf_masked(mask, k))
    {
      continue;
    }
    for (c = 0; c < channels; ++c)
    {
      double x = a[k * (size_t)channels + (size_t)c];
      double y = b[k * (size_t)channels + (size_t)c];
      if (!isfinite(x) || !isfinite(y))
      {
        return RF_ERR_NOT_FINITE;
      }
      if (clamp)
      {
        x = rf_clamp01(x);
        y = rf_clamp01(y);
      }
      sum += (x - y) * (x - y);
    }
    ++count;
  }
  if (count == 0)
  {
    return RF_REF_ERR_NO_SAMPLES;
  }
  *mse = sum / ((double)count * channels);
  return RF_OK;
}

rf_status rf_rmse(const float* a, const float* b, size_t pixel_count, int channels,
  const unsigned char* mask, double* rmse)
{
  double mse = 0.0;
  const rf_status s = rf_mean_squared(a, b, pixel_count, channels, mask, 0, &mse);
  if (s == RF_OK)
  {
    *rmse = sqrt(mse);
  }
  return s;
}

rf_status rf_psnr(const float* a, const float* b, size_t pixel_count, int channels,
  const unsigned char* mask, double* psnr_db)
{
  double mse = 0.0;
  const rf_status s = rf_mean_squared(a, b, pixel_count, channels, mask, 1, &mse);
  if (s == RF_OK)
  {
    /* 10 log10(peak^2 / MSE) with peak 1; capped (identical images give +inf). */
    *psnr_db = mse > 0.0 ? fmin(-10.0 * log10(mse), RF_PSNR_CAP_DB) : RF_PSNR_CAP_DB;
  }
  return s;
}

/* Clamped luminance of every pixel; NULL on allocation failure, *finite = 0 when a masked
 * value is not finite. */
static double* rf_luminance(const float* image, size_t n, int channels,
  const unsigned char* mask, int* finite)
{
  double* y = (double*)malloc(n * sizeof(double));
  size_t k;
  if (y == NULL)
  {
    return NULL;
  }
  for (k = 0; k < n; ++k)
  {
    const float* p = image + k * (size_t)channels;
    const double value =
      channels == 1 ? p[0] : 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; /* Rec. 709 */
    if (!isfinite(value))
    {
      if (rf_masked(mask, k))
      {
        *finite = 0;
      }
      y[k] = 0.0;
      continue;
    }
    y[k] = channels == 1 ? rf_clamp01(value)
                         : 0.2126 * rf_clamp01(p[0]) + 0.7152 * rf_clamp01(p[1]) +
        0.0722 * rf_clamp01(p[2]);
  }
  return y;
}

rf_status rf_ssim(const float* a, const float* b, int width, int height, int channels,
  const unsigned char* mask, double* ssim)
{
  double weight[2 * RF_SSIM_RADIUS + 1];
  double* ya;
  double* yb;
  double total = 0.0;
  size_t count = 0;
  size_t n;
  int finite = 1;
  int x;
  int y;
  int i;
  if (a == NULL || b == NULL || ssim == NULL)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  if (width <= 0 || height <= 0 || channels < 1 || channels == 2)
  {
    return RF_REF_ERR_BAD_OPTION;
  }
  n = (size_t)width * (size_t)height;
  /* The 2D window is the product of two 1D Gaussians; normalization happens per pixel. */
  for (i = -RF_SSIM_RADIUS; i <= RF_SSIM_RADIUS; ++i)
  {
    weight[i + RF_SSIM_RADIUS] = exp(-(double)(i * i) / (2.0 * RF_SSIM_SIGMA * RF_SSIM_SIGMA));
  }
  ya = rf_luminance(a, n, channels, mask, &finite);
  yb = rf_luminance(b, n, channels, mask, &finite);
  if (ya == NULL || yb == NULL)
  {
    free(ya);
    free(yb);
    return RF_REF_ERR_OUT_OF_MEMORY;
  }
  if (!finite)
  {
    free(ya);
    free(yb);
    return RF_ERR_NOT_FINITE;
  }
  for (y = 0; y < height; ++y)
  {
    for (x = 0; x < width; ++x)
    {
      const size_t k = (size_t)y * (size_t)width + (size_t)x;
      double sw = 0.0, sa = 0.0, sb = 0.0, saa = 0.0, sbb = 0.0, sab = 0.0;
      double mua, mub, va, vb, cov;
      int dx;
      int dy;
      if (!rf_masked(mask, k))
      {
        continue;
      }
      for (dy = -RF_SSIM_RADIUS; dy <= RF_SSIM_RADIUS; ++dy)
      {
        const int qy = y + dy;
        if (qy < 0 || qy >= height)
        {
          continue;
        }
        for (dx = -RF_SSIM_RADIUS; dx <= RF_SSIM_RADIUS; ++dx)
        {
          const int qx = x + dx;
          size_t q;
          double w;
          if (qx < 0 || qx >= width)
          {
            continue;
          }
          q = (size_t)qy * (size_t)width + (size_t)qx;
          if (!rf_masked(mask, q))
          {
            continue;
          }
          w = weight[dx + RF_SSIM_RADIUS] * weight[dy + RF_SSIM_RADIUS];
          sw += w;
          sa += w * ya[q];
          sb += w * yb[q];
          saa += w * ya[q] * ya[q];
          sbb += w * yb[q] * yb[q];
          sab += w * ya[q] * yb[q];
        }
      }
      /* Weighted means, variances and covariance (eq. 14-16 with normalized weights). */
      mua = sa / sw;
      mub = sb / sw;
      va = fmax(saa / sw - mua * mua, 0.0);
      vb = fmax(sbb / sw - mub * mub, 0.0);
      cov = sab / sw - mua * mub;
      total += ((2.0 * mua * mub + RF_SSIM_C1) * (2.0 * cov + RF_SSIM_C2)) /
        ((mua * mua + mub * mub + RF_SSIM_C1) * (va + vb + RF_SSIM_C2));
      ++count;
    }
  }
  free(ya);
  free(yb);
  if (count == 0)
  {
    return RF_REF_ERR_NO_SAMPLES;
  }
  *ssim = total / (double)count;
  return RF_OK;
}

static int rf_compare_doubles(const void* pa, const void* pb)
{
  const double a = *(const double*)pa;
  const double b = *(const double*)pb;
  return (a > b) - (a < b);
}

/* Mean, nearest-rank p95 and max of values[0..count); sorts values. */
static void rf_summarize(double* values, size_t count, rf_error_stats* stats)
{
  double sum = 0.0;
  size_t k;
  size_t rank;
  qsort(values, count, sizeof(double), rf_compare_doubles);
  for (k = 0; k < count; ++k)
  {
    sum += values[k];
  }
  rank = (size_t)ceil(0.95 * (double)count); /* 1-based */
  stats->mean = sum / (double)count;
  stats->p95 = values[(rank > 0 ? rank : 1) - 1];
  stats->max = values[count - 1];
  stats->count = count;
}

/* The shared loop of the two vector errors: per masked pixel, measure(a, b) or a negative
 * value for invalid data. */
typedef double (*rf_pixel_error_fn)(const float* a, const float* b, double parameter);

static rf_status rf_vector_error(const float* a, const float* b, size_t pixel_count,
  const unsigned char* mask, rf_pixel_error_fn measure, double parameter, rf_error_stats* stats)
{
  double* values;
  size_t count = 0;
  size_t invalid = 0;
  size_t k;
  if (a == NULL || b == NULL || stats == NULL)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  values = (double*)malloc((pixel_count > 0 ? pixel_count : 1) * sizeof(double));
  if (values == NULL)
  {
    return RF_REF_ERR_OUT_OF_MEMORY;
  }
  for (k = 0; k < pixel_count; ++k)
  {
    double e;
    if (!rf_masked(mask, k))
    {
      continue;
    }
    e = measure(a + 3 * k, b + 3 * k, parameter);
    if (e >= 0.0)
    {
      values[count++] = e;
    }
    else
    {
      ++invalid;
    }
  }
  stats->invalid = invalid;
  stats->count = 0;
  if (count == 0)
  {
    free(values);
    return RF_REF_ERR_NO_SAMPLES;
  }
  rf_summarize(values, count, stats);
  free(values);
  return RF_OK;
}

/* atan2(|a x b|, a . b): accurate at small angles, where acos of a dot product loses half
 * its digits. */
static double rf_angle_degrees(const float* a, const float* b, double unused)
{
  const double ax = a[0], ay = a[1], az = a[2];
  const double bx = b[0], by = b[1], bz = b[2];
  const double cx = ay * bz - az * by;
  const double cy = az * bx - ax * bz;
  const double cz = ax * by - ay * bx;
  const double la = sqrt(ax * ax + ay * ay + az * az);
  const double lb = sqrt(bx * bx + by * by + bz * bz);
  (void)unused;
  if (!isfinite(la) || !isfinite(lb) || !(la > 0.0) || !(lb > 0.0))
  {
    return -1.0;
  }
  return atan2(sqrt(cx * cx + cy * cy + cz * cz), ax * bx + ay * by + az * bz) * (180.0 / RF_PI);
}

static double rf_relative_distance(const float* a, const float* b, double length)
{
  const double dx = (double)a[0] - b[0];
  const double dy = (double)a[1] - b[1];
  const double dz = (double)a[2] - b[2];
  const double d = sqrt(dx * dx + dy * dy + dz * dz);
  return isfinite(d) ? d / length : -1.0;
}

rf_status rf_angular_error(const float* a, const float* b, size_t pixel_count,
  const unsigned char* mask, rf_error_stats* stats)
{
  return rf_vector_error(a, b, pixel_count, mask, rf_angle_degrees, 0.0, stats);
}

rf_status rf_position_error(const float* a, const float* b, size_t pixel_count,
  const unsigned char* mask, double reference_length, rf_error_stats* stats)
{
  if (!isfinite(reference_length))
  {
    return RF_ERR_NOT_FINITE;
  }
  if (!(reference_length > 0.0))
  {
    return RF_ERR_EMPTY_RANGE;
  }
  return rf_vector_error(a, b, pixel_count, mask, rf_relative_distance, reference_length, stats);
}

rf_status rf_flag_share(const unsigned char* flags, size_t pixel_count,
  const unsigned char* mask, double* share)
{
  size_t count = 0;
  size_t set = 0;
  size_t k;
  if (flags == NULL || share == NULL)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  for (k = 0; k < pixel_count; ++k)
  {
    if (rf_masked(mask, k))
    {
      ++count;
      set += flags[k] != 0 ? 1u : 0u;
    }
  }
  if (count == 0)
  {
    return RF_REF_ERR_NO_SAMPLES;
  }
  *share = (double)set / (double)count;
  return RF_OK;
}
