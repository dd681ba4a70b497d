/* rf_tracer_state.h: what the pieces of the reference tracer share (private): the traced
 * scene, a ray's hit, and one pixel's results before they are written to the image. See
 * rf_tracer.h for the model; rf_tracer.c for how the pieces are put together. */
#ifndef RF_TRACER_STATE_H
#define RF_TRACER_STATE_H

#include "rf_tracer.h"
#include "rf_vec3.h"

#include <embree3/rtcore.h>

/* Scene: Embree objects plus what shading needs; read-only while the threads trace. */

typedef struct rf_tracer
{
  RTCDevice device;
  RTCScene scene;        /* the glass; geometry k is meshes[k] */
  RTCScene opaque_scene; /* the opaque surfaces (NULL when there are none); geometry k is
                            opaque[k] */
  const rf_mesh* meshes;
  size_t mesh_count;
  const rf_opaque_mesh* opaque;
  size_t opaque_count;
  const rf_trace_options* options;
  double epsilon; /* ray offset for secondary rays, scaled with the scene */
  double clip_to_view[16];
  double view_to_world[16];
  double world_to_view[16];
  int parallel;          /* parallel projection: the viewer is along +z of the view */
  rf_vec3 eye_world;     /* perspective: the camera position */
  rf_vec3 view_z_world;  /* the view axis toward the viewer, in WORLD space */
  rf_trace_image* out;
} rf_tracer;

typedef struct rf_hit
{
  unsigned geom;
  unsigned prim;
  double t;
  double u;
  double v;
  rf_vec3 point;
} rf_hit;

/* Per-pixel results before they are written to the image. */
typedef struct rf_pixel
{
  int hit;
  int opaque;
  double colour[3];
  rf_vec3 p1;
  rf_vec3 p2;
  rf_vec3 t2;
  double thickness;
  int bounces;
  int tir;
} rf_pixel;

#endif /* RF_TRACER_STATE_H */
