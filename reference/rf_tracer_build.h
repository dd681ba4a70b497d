/* rf_tracer_build.h: the Embree scenes of a trace (private): the glass in one, the opaque
 * surfaces in another, and the ray offset that suits the scene's size. */
#ifndef RF_TRACER_BUILD_H
#define RF_TRACER_BUILD_H

#include "rf_tracer_state.h"

/* The offset secondary rays start at, from the glass meshes' extent. */
double rf_scene_epsilon(const rf_mesh* meshes, size_t mesh_count);

/* Makes tr's Embree device and scenes from its meshes; release them with rf_release_scene
 * whatever it returns. */
rf_status rf_build_scene(rf_tracer* tr);

/* Releases what rf_build_scene made. */
void rf_release_scene(rf_tracer* tr);

#endif /* RF_TRACER_BUILD_H */
