/* rf_tracer_surfaces.h: where a ray ends outside the glass (private): an opaque surface,
 * coloured as VTK draws it (rf_opaque_shade, rf_opaque_material), or the environment. */
#ifndef RF_TRACER_SURFACES_H
#define RF_TRACER_SURFACES_H

#include "rf_tracer_state.h"

/* The colour the camera sees at an opaque hit, whichever ray found it. */
void rf_opaque_colour(const rf_tracer* tr, const rf_hit* hit, double rgb[3]);

/* The environment along the WORLD direction d (the options' function or the built-in one). */
void rf_environment(const rf_tracer* tr, rf_vec3 d, double rgb[3]);

/* Shades an opaque surface met by the primary ray before tfar (where glass would start);
 * returns 1 when there is one. */
int rf_shade_primary_opaque(
  const rf_tracer* tr, rf_vec3 origin, rf_vec3 view_dir, double tfar, rf_pixel* px);

/* What a ray leaving the glass at o along d shows: the first opaque surface, else the
 * environment. */
void rf_behind(const rf_tracer* tr, rf_vec3 o, rf_vec3 d, double rgb[3]);

#endif /* RF_TRACER_SURFACES_H */
