/* rf_tracer_full.h: the full mode (RF_TRACE_FULL, see rf_tracer.h): Whitted recursion with
 * Fresnel splits, TIR and Beer-Lambert absorption through nested glass (private). */
#ifndef RF_TRACER_FULL_H
#define RF_TRACER_FULL_H

#include "rf_tracer_state.h"

/* Shades the ray from origin along view_dir (up to tfar, the far plane) into px; p2, t2,
 * thickness, bounces and tir describe the dominant path. */
void rf_shade_full(const rf_tracer* tr, rf_vec3 origin, rf_vec3 view_dir, double tfar,
  rf_pixel* px);

#endif /* RF_TRACER_FULL_H */
