/* rf_tracer_validate.h: the checks of rf_trace_scene's inputs (private). */
#ifndef RF_TRACER_VALIDATE_H
#define RF_TRACER_VALIDATE_H

#include "rf_tracer.h"


/* Largest image side: keeps width * height * 3 floats far from size_t overflow. */
#define RF_MAX_IMAGE_SIDE 65536

/* RF_OK, or the first error of the inputs (see rf_trace_scene). */
rf_status rf_validate_inputs(const rf_mesh* meshes, size_t mesh_count,
  const rf_opaque_mesh* opaque, size_t opaque_count, const rf_camera* camera,
  const rf_trace_options* options, const rf_trace_image* out);

#endif /* RF_TRACER_VALIDATE_H */
