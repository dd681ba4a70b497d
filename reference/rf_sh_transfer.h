/* rf_sh_transfer.h: the precomputation of the SH method (Genevaux et al., seed 003). For each
 * vertex of a closed glass mesh, the view direction V (from the eye toward the vertex, over
 * the hemisphere that sees the vertex from outside) is mapped to the direction in which the
 * light path leaves the glass and to the length it travels inside; both are projected on
 * real spherical harmonics (module/core/rf_sh.h) and evaluated at render time.
 *
 * The path: refracted at the vertex (the vertex's normal), then followed with Embree through
 * the mesh, refracted where it leaves and reflected where it cannot (TIR), up to max_bounces
 * reflections; at a Fresnel split the transmitted part is followed (the paper keeps the most
 * significant path; here transmission, which carries most of the light except near the
 * critical angle, where TIR takes over). A path that finds no surface (an open mesh) leaves
 * with its direction. The functions are defined on the outer hemisphere only; they are
 * extended to the whole sphere by mirroring across the tangent plane (V' = V - 2 (V.n) n),
 * which keeps them continuous, so that the projection does not ring at the horizon. */
#ifndef RF_SH_TRANSFER_H
#define RF_SH_TRANSFER_H

#include "rf_reference_status.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The functions per vertex, in this order, each with rf_sh_coefficient_count(order)
 * coefficients: the exit direction's x, y, z (model space) and the path length inside. */
#define RF_SH_TRANSFER_FUNCTIONS 4

typedef void (*rf_sh_progress_fn)(double fraction, void* user);

typedef struct rf_sh_transfer_options
{
  int order;       /* 0..RF_SH_ORDER_MAX (the paper: 8) */
  int directions;  /* view directions per vertex over the hemisphere, >= 16 (the paper: ~2000) */
  int max_bounces; /* total internal reflections followed, 0..64 */
  int threads;     /* worker threads, >= 1 */
  rf_sh_progress_fn progress; /* NULL: none; called on the calling thread */
  void* progress_user;
} rf_sh_transfer_options;

/* positions, normals: xyz per vertex (normals outward, need not be unit); triangles: three
 * vertex indices each; ior > 0. coefficients receives vertex_count * 4 *
 * rf_sh_coefficient_count(order) values: vertex-major, then function, then coefficient.
 * A vertex with a zero normal gets zero coefficients.
 * Errors: RF_ERR_NULL_ARGUMENT, RF_ERR_NOT_FINITE, RF_ERR_IOR_NOT_POSITIVE,
 * RF_REF_ERR_INDEX_OUT_OF_RANGE, RF_REF_ERR_BAD_OPTION, RF_REF_ERR_OUT_OF_MEMORY,
 * RF_REF_ERR_EMBREE. */
RF_REFERENCE_EXPORT rf_status rf_sh_transfer(const float* positions, const float* normals,
  size_t vertex_count, const unsigned* triangles, size_t triangle_count, double ior,
  const rf_sh_transfer_options* options, float* coefficients);

/* The path of one view direction V (unit, dot(V, n) < 0) entering at vertex `vertex`: the
 * exit direction and the length inside, as rf_sh_transfer samples it (for tests). */
RF_REFERENCE_EXPORT rf_status rf_sh_transfer_path(const float* positions, const float* normals,
  size_t vertex_count, const unsigned* triangles, size_t triangle_count, double ior,
  int max_bounces, size_t vertex, const double view[3], double exit_direction[3],
  double* length);

#ifdef __cplusplus
}
#endif

#endif /* RF_SH_TRANSFER_H */
