/* The built-in environment: a sky/ground/studio pattern made in code, so the demo, the tests
 * and the reference tracer need no image file. The formula is rfk_builtin_environment of
 * kernel/rf_kernel_environment.h, which the shaders compile too. */
#ifndef RF_ENVIRONMENT_H
#define RF_ENVIRONMENT_H

#ifdef __cplusplus
extern "C" {
#endif

/* World space, +y up. The direction need not be unit length; a zero or non-finite direction
 * gives the horizon colour. Colours are linear RGB, at most about 3 (the sun). */
void rf_builtin_environment(const double direction_world[3], double rgb[3]);

/* The same averaged over a cone of directions `width` radians across (the spread of a
 * pixel's rays; 0, negative or NaN: the one direction, exactly rf_builtin_environment). */
void rf_builtin_environment_filtered(
  const double direction_world[3], double width, double rgb[3]);

/* The same averaged over the parallelogram of directions spanned by span_a and span_b about
 * the direction (how far the unit direction turns across a pixel along each of the screen's
 * axes): a footprint long one way is not blurred the other. Zero spans: the one direction,
 * exactly rf_builtin_environment; a span that is not finite counts as none. */
void rf_builtin_environment_footprint(const double direction_world[3],
  const double span_a[3], const double span_b[3], double rgb[3]);

#ifdef __cplusplus
}
#endif
#endif
