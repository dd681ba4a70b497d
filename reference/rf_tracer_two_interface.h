/* rf_tracer_two_interface.h: the two-interface mode (RF_TRACE_TWO_INTERFACE, see
 * rf_tracer.h): the GPU's formula with the true exit point (private). */
#ifndef RF_TRACER_TWO_INTERFACE_H
#define RF_TRACER_TWO_INTERFACE_H

#include "rf_tracer_state.h"

/* Shades the ray from origin along view_dir (up to tfar, the far plane) into px. */
void rf_shade_two_interface(const rf_tracer* tr, rf_vec3 origin, rf_vec3 view_dir,
  double tfar, rf_pixel* px);

#endif /* RF_TRACER_TWO_INTERFACE_H */
