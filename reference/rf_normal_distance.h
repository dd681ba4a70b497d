/* ISR's per-vertex distance d_N (Wyman 2005, "An approximate image-space approach for
 * interactive refraction", eq. 1-2; seed 001 and section 2.1 of seed 000): the distance from
 * each vertex, along its inward normal, to the far side of the mesh. A ray cast per vertex on
 * the CPU with Embree 3 (packets of 8 rays, on every core): this per-vertex precomputation, repeated whenever the points change,
 * is the cost DIR was designed to avoid. */
#ifndef RF_NORMAL_DISTANCE_H
#define RF_NORMAL_DISTANCE_H

#include "rf_reference_status.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* positions and normals: xyz per vertex (normals need not be unit; zero-length normals give a
 * distance of 0); triangles: three vertex indices each. distances[i] receives the distance
 * from vertex i along -normal[i] to the first surface hit, or 0 when the ray leaves the
 * mesh (open meshes, zero normals). The rays are cast in packets of 8 on `threads` threads
 * (at least 1: RF_REF_ERR_BAD_OPTION otherwise), each on a contiguous run of vertices. */
RF_REFERENCE_EXPORT rf_status rf_normal_distances(const float* positions, const float* normals,
  size_t vertex_count, const unsigned* triangles, size_t triangle_count, float* distances,
  int threads);

#ifdef __cplusplus
}
#endif
#endif
