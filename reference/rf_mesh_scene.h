/* rf_mesh_scene.h: one triangle mesh as a watertight Embree 3 scene (ISR's normal distances,
 * the SH precomputation's paths). Private to the reference library. */
#ifndef RF_MESH_SCENE_H
#define RF_MESH_SCENE_H

#include "rf_reference_status.h"

#include <embree3/rtcore.h>
#include <stddef.h>

typedef struct rf_mesh_scene
{
  RTCDevice device;
  RTCScene scene;
  double extent; /* the largest side of the mesh's bounding box (0 for a point or none) */
} rf_mesh_scene;

/* Embree's valid rays and vertices stay below its FLT_LARGE (about 1.8e18) in magnitude: the
 * largest coordinate a mesh may have, with room for a ray's origin plus its length. */
#define RF_MESH_SCENE_LARGEST 1e17f

/* Checks the mesh (finite positions below RF_MESH_SCENE_LARGEST in magnitude:
 * RF_ERR_NOT_FINITE; indices below vertex_count:
 * RF_REF_ERR_INDEX_OUT_OF_RANGE) and builds its scene with the robust (watertight)
 * intersector: a path through a vertex or an edge must not slip between triangles. A mesh
 * without triangles gives an empty scene. On any error s holds nothing to release;
 * otherwise release it with rf_mesh_scene_release. */
rf_status rf_mesh_scene_build(rf_mesh_scene* s, const float* positions, size_t vertex_count,
  const unsigned* triangles, size_t triangle_count);

void rf_mesh_scene_release(rf_mesh_scene* s);

#endif /* RF_MESH_SCENE_H */
