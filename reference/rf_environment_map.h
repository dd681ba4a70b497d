/* rf_environment_map.h: an image environment for the reference tracer, looked up as the
 * pass's shader looks up the renderer's environment (shaders/rfRefractionFS.glsl,
 * rfEnvironment): texture(cube, envMatrix * directionWorld).
 *
 *  - The frame. envMatrix is built by vtkRefractionPass::UpdateCameraUniforms from the
 *    renderer's EnvironmentRight and EnvironmentUp: its rows are right, up and
 *    front = right x up, so the lookup direction is (right.w, up.w, front.w).
 *  - A cube map follows OpenGL's face selection (GL 4.5 spec, table 8.19): the major axis
 *    picks the face (+X, -X, +Y, -Y, +Z, -Z, the order of GL_TEXTURE_CUBE_MAP_POSITIVE_X + i
 *    and of a vtkTexture's six inputs), (sc/|ma| + 1)/2 and (tc/|ma| + 1)/2 are the face's
 *    s and t; row 0 of a face is t = 0 (the first row uploaded, the bottom row of a
 *    vtkImageData). Filtering inside a face, edges clamped (the half texel along a face's
 *    border is where a seamless GL cube map, which blends across faces, differs).
 *  - A lat-long image is mapped as vtkEquirectangularToCubeMapTexture maps it (its
 *    toSpherical, with its constants): u = atan2(d.z, d.x) * 0.1591 + 0.5 along the row,
 *    v = asin(d.y / |d|) * 0.3183 + 0.5 across rows (row 0 at v = 0). Sampled directly it is
 *    the environment itself; rf_environment_cube_from_latlong resamples it into the cube
 *    map that VTK's filter renders, which is what the pass then samples.
 *  - Filtering as GL_NEAREST or GL_LINEAR (texel centres at (k + 0.5) / size), wrap as
 *    GL_REPEAT or GL_CLAMP_TO_EDGE (lat-long only; cube faces always clamp).
 * Texels are linear RGB floats, 3 per texel, row by row. */
#ifndef RF_ENVIRONMENT_MAP_H
#define RF_ENVIRONMENT_MAP_H

#include "rf_reference_status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum rf_environment_layout
{
  RF_ENVIRONMENT_LATLONG = 0,
  RF_ENVIRONMENT_CUBE = 1
} rf_environment_layout;

typedef struct rf_environment_map
{
  rf_environment_layout layout;
  int width, height;       /* lat-long: the image; cube: each face (width == height) */
  const float* texels[6];  /* lat-long: texels[0]; cube: the faces +X, -X, +Y, -Y, +Z, -Z */
  int linear;              /* 1: GL_LINEAR, 0: GL_NEAREST */
  int repeat;              /* lat-long: 1 GL_REPEAT (vtkTexture's default), 0 clamp to edge */
  double frame[9];         /* world -> lookup, row-major: rows right, up, right x up */
} rf_environment_map;

/* The lookup frame of the renderer's EnvironmentUp and EnvironmentRight (not normalized,
 * as the pass passes them). Errors: RF_ERR_NULL_ARGUMENT, RF_ERR_NOT_FINITE, and
 * RF_REF_ERR_BAD_OPTION when up and right are parallel or zero. */
RF_REFERENCE_EXPORT rf_status rf_environment_map_frame(
  const double up[3], const double right[3], double frame[9]);

/* Checks a map before it is used from rf_trace (sizes, pointers, frame).
 * Errors: RF_ERR_NULL_ARGUMENT, RF_ERR_NOT_FINITE, RF_REF_ERR_BAD_OPTION. */
RF_REFERENCE_EXPORT rf_status rf_environment_map_validate(const rf_environment_map* map);

/* rf_environment_fn for rf_trace_options.environment, with a validated map as user data.
 * A zero or non-finite direction gives black. */
RF_REFERENCE_EXPORT void rf_environment_map_lookup(
  const double direction_world[3], double rgb[3], void* map);

/* Resamples a lat-long image (width x height, 3 floats per texel, filtered and wrapped as
 * the map's linear and repeat say) into six side x side faces, texel by texel as
 * vtkEquirectangularToCubeMapTexture renders them (face texel centre -> direction ->
 * lat-long lookup). faces[k] must hold 3 * side * side floats.
 * Errors: RF_ERR_NULL_ARGUMENT, RF_REF_ERR_BAD_OPTION (sizes, or a map that is not lat-long). */
RF_REFERENCE_EXPORT rf_status rf_environment_cube_from_latlong(
  const rf_environment_map* latlong, int side, float* const faces[6]);

/* The renderer's background as the environment, as the pass's shader computes it without a
 * cube map in vtkRefractionPass::ENVIRONMENT_RENDERER (shaders/rfEnvironment.glsl,
 * RF_ENV_BACKGROUND): the colour the screen shows in a direction. The view-space direction d
 * is projected as a point at infinity, c = projection (d, 0); where it lies in front of the
 * camera (c.w > 1e-6 |d|) its height on the screen is up = 0.5 + 0.5 c.y / c.w, else
 * (behind, or any direction under a parallel projection) up = 1 for d.y >= 0 and 0 below;
 * the colour is bottom + (top - bottom) clamp(up, 0, 1). A solid background has top = bottom.
 * VTK's gradient runs from Background at the bottom of the viewport to Background2 at the
 * top. */
typedef struct rf_background_environment
{
  double world_to_view[9]; /* the view's rotation, row-major (vtkCamera's view matrix) */
  double projection[16];   /* view -> clip, row-major, as rf_camera.projection */
  double bottom[3];        /* the renderer's Background */
  double top[3];           /* Background2 with GradientBackground on, else Background */
} rf_background_environment;

/* rf_environment_fn for rf_trace_options.environment, with an rf_background_environment as
 * user data. As in the shader, a zero direction gives the top colour; a non-finite one the
 * bottom colour. */
RF_REFERENCE_EXPORT void rf_background_environment_lookup(
  const double direction_world[3], double rgb[3], void* background);

#ifdef __cplusplus
}
#endif

#endif /* RF_ENVIRONMENT_MAP_H */
