/* rf_tracer_rays.h: a ray against the scene (private): the nearest glass or opaque hit
 * through Embree, the normal at a hit, and the refraction at an interface with a TIR policy. */
#ifndef RF_TRACER_RAYS_H
#define RF_TRACER_RAYS_H

#include "rf_tracer_state.h"

/* The nearest glass surface along o + t d, t in (tnear, tfar), skipping a hit on the
 * triangle (skip_geom, skip_prim) the ray starts from; 1 when there is one. */
int rf_intersect(const rf_tracer* tr, rf_vec3 o, rf_vec3 d, double tnear, double tfar,
  unsigned skip_geom, unsigned skip_prim, rf_hit* hit);

/* The nearest opaque surface (none when the scene has no opaque mesh). */
int rf_intersect_opaque(
  const rf_tracer* tr, rf_vec3 o, rf_vec3 d, double tnear, double tfar, rf_hit* hit);

/* The unit normal of a triangle from its winding (OpenGL's front face). */
rf_vec3 rf_winding_normal(const float* positions, const unsigned* tri);

/* Unit normal at the hit, not oriented: the vertex normals interpolated, or the geometric one. */
rf_vec3 rf_surface_normal(
  const float* positions, const float* normals, const unsigned* triangles, const rf_hit* hit);

/* rf_surface_normal of a glass hit. */
rf_vec3 rf_shading_normal(const rf_tracer* tr, const rf_hit* hit);

/* Refraction with a TIR policy (clamp: rf_refract_clamped); returns 1 under TIR. */
int rf_refract_policy(rf_vec3 incident, rf_vec3 normal, double eta, int clamp,
  rf_vec3* transmitted);

#endif /* RF_TRACER_RAYS_H */
