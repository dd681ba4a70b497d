/* rf_metrics.h: error measures between a method's image and the reference (DESIGN.md,
 * section 5), on the object's pixels only.
 *
 * Images are float arrays, `channels` values per pixel, pixel k at k * channels; a mask
 * (one byte per pixel, nonzero = measured; NULL = every pixel) selects the pixels, e.g.
 * those where both images show glass. No dependency beyond the C library. */
#ifndef RF_METRICS_H
#define RF_METRICS_H

#include "rf_reference_status.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* PSNR of identical images (RMSE 0) is infinite; it is reported as this cap so tables and
 * plots stay finite. 100 dB is an RMSE of 1e-5, far below one 8-bit step (48 dB). */
#define RF_PSNR_CAP_DB 100.0

/* Summary of a per-pixel error. */
typedef struct rf_error_stats
{
  double mean;
  double p95;     /* nearest rank: the ceil(0.95 n)-th smallest value */
  double max;
  size_t count;   /* pixels measured */
  size_t invalid; /* masked pixels left out: zero-length or non-finite data */
} rf_error_stats;

/* Root mean square difference over the masked pixels and all their channels, on the
 * values as given. Errors: RF_ERR_NULL_ARGUMENT, RF_REF_ERR_BAD_OPTION (channels < 1),
 * RF_ERR_NOT_FINITE (a masked value), RF_REF_ERR_NO_SAMPLES. */
RF_REFERENCE_EXPORT rf_status rf_rmse(const float* a, const float* b, size_t pixel_count,
  int channels, const unsigned char* mask, double* rmse);

/* Peak signal-to-noise ratio 20 log10(1 / RMSE) in dB, peak 1.0, with every value clamped
 * to [0, 1] first (the GPU writes 8-bit colour, so the reference's values above 1, such as
 * the sun, are compared as the GPU can show them). RMSE 0 gives RF_PSNR_CAP_DB, and no
 * result exceeds it. Errors as rf_rmse. */
RF_REFERENCE_EXPORT rf_status rf_psnr(const float* a, const float* b, size_t pixel_count,
  int channels, const unsigned char* mask, double* psnr_db);

/* Mean SSIM (Wang, Bovik, Sheikh, Simoncelli 2004, eq. 13 with their constants) over the
 * masked pixels, on luminance: the value itself for channels == 1, else
 * Y = 0.2126 R + 0.7152 G + 0.0722 B of the first three channels, after clamping to [0, 1]
 * (dynamic range L = 1, C1 = (0.01 L)^2, C2 = (0.03 L)^2). Local statistics use the 11x11
 * Gaussian window of sigma 1.5, restricted to masked pixels inside the image and
 * renormalized, so what lies outside the mask (the GPU draws the environment there, the
 * reference 0) does not matter; where the window is all masked this is Wang et al.'s SSIM.
 * Images are width x height, row-major. Errors: RF_ERR_NULL_ARGUMENT,
 * RF_REF_ERR_BAD_OPTION (size <= 0, channels 2 or < 1), RF_ERR_NOT_FINITE,
 * RF_REF_ERR_NO_SAMPLES, RF_REF_ERR_OUT_OF_MEMORY. */
RF_REFERENCE_EXPORT rf_status rf_ssim(const float* a, const float* b, int width, int height,
  int channels, const unsigned char* mask, double* ssim);

/* Angle in DEGREES between the direction images a and b (3 floats per pixel, not
 * necessarily unit): mean, p95, max over the masked pixels. Pixels where either direction
 * is zero or not finite are left out and counted in stats->invalid. Errors:
 * RF_ERR_NULL_ARGUMENT, RF_REF_ERR_NO_SAMPLES (no valid pixel),
 * RF_REF_ERR_OUT_OF_MEMORY. */
RF_REFERENCE_EXPORT rf_status rf_angular_error(const float* a, const float* b,
  size_t pixel_count, const unsigned char* mask, rf_error_stats* stats);

/* Distance |a - b| between the position images a and b (3 floats per pixel) divided by
 * reference_length (e.g. the bounding-box diagonal of the glass): mean, p95, max over the
 * masked pixels. Non-finite pixels are left out and counted in stats->invalid. Errors:
 * RF_ERR_NULL_ARGUMENT, RF_ERR_NOT_FINITE / RF_ERR_EMPTY_RANGE (reference_length not
 * finite / not > 0), RF_REF_ERR_NO_SAMPLES, RF_REF_ERR_OUT_OF_MEMORY. */
RF_REFERENCE_EXPORT rf_status rf_position_error(const float* a, const float* b,
  size_t pixel_count, const unsigned char* mask, double reference_length,
  rf_error_stats* stats);

/* Share of the masked pixels whose flag is nonzero (e.g. the TIR flag), in [0, 1].
 * Errors: RF_ERR_NULL_ARGUMENT, RF_REF_ERR_NO_SAMPLES. */
RF_REFERENCE_EXPORT rf_status rf_flag_share(const unsigned char* flags, size_t pixel_count,
  const unsigned char* mask, double* share);

#ifdef __cplusplus
}
#endif

#endif /* RF_METRICS_H */
