/* rf_validate.h: status codes of the refraction core and the checks of the
 * user-facing parameters, kept in one place so the render pass and the core
 * reject the same inputs with the same messages. */
#ifndef RF_VALIDATE_H
#define RF_VALIDATE_H

#ifdef __cplusplus
extern "C" {
#endif

typedef enum rf_status
{
  RF_OK = 0,
  RF_TIR = 1, /* not an error: total internal reflection occurred */
  RF_ERR_NULL_ARGUMENT,
  RF_ERR_NOT_FINITE,
  RF_ERR_IOR_NOT_POSITIVE,
  RF_ERR_STEPS_OUT_OF_RANGE,
  RF_ERR_ABSORPTION_NEGATIVE,
  RF_ERR_DEGENERATE_DIRECTION,
  RF_ERR_EMPTY_RANGE,
  RF_ERR_BAD_MESH /* a mesh's counts or ids out of range (rf_pieces) */
} rf_status;

/* The paper bounds the CBS error by 0.5^steps (section 3.3); 16 steps already
 * resolve the search below 1/65536 of the segment, finer than any depth map. */
#define RF_CBS_MAX_STEPS 16

/* Index of refraction (or a ratio of them): finite and > 0. Values below 1
 * are legal (e.g. an air bubble inside water). */
rf_status rf_validate_ior(double ior);

/* Number of conservative binary search steps: 0..RF_CBS_MAX_STEPS. */
rf_status rf_validate_cbs_steps(int steps);

/* Per-channel absorption coefficients (Beer-Lambert): finite and >= 0. */
rf_status rf_validate_absorption(const double rgb[3]);

/* Depth range of the back surface as POSITIVE distances in front of the
 * camera: finite and 0 < z_min <= z_max. Both a reversed range and a range
 * touching or behind the camera give RF_ERR_EMPTY_RANGE, because no part of
 * the requested interval lies in front of the camera in the right order. */
rf_status rf_validate_depth_range(double z_min, double z_max);

/* A sentence describing s; never NULL ("unknown status" for bad values). */
const char* rf_status_message(rf_status s);

#ifdef __cplusplus
}
#endif

#endif /* RF_VALIDATE_H */
