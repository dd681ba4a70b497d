/* rf_tracer_camera.h: the camera's matrices (4x4 row-major, the layout of
 * vtkMatrix4x4::GetData()) and the primary ray through a point of the image (private). */
#ifndef RF_TRACER_CAMERA_H
#define RF_TRACER_CAMERA_H

#include "rf_tracer_state.h"

/* Gauss-Jordan with partial pivoting; returns 0 for a singular matrix. */
int rf_mat4_invert(const double m[16], double inverse[16]);

/* m * (x, y, z, 1) followed by the homogeneous divide. */
rf_vec3 rf_mat4_point(const double m[16], rf_vec3 p);

/* The linear part applied to a direction, renormalized. */
rf_vec3 rf_mat4_direction(const double m[16], rf_vec3 d);

/* Shades the primary ray through NDC (x, y) in the options' mode into px. */
void rf_trace_primary(const rf_tracer* tr, double x, double y, rf_pixel* px);

#endif /* RF_TRACER_CAMERA_H */
