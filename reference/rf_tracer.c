/* rf_tracer.c: the reference ray tracer on Embree 3 (see rf_tracer.h for the model). */
#include "rf_tracer.h"

#include "rf_tracer_build.h"
#include "rf_tracer_camera.h"
#include "rf_tracer_pixels.h"
#include "rf_tracer_state.h"
#include "rf_tracer_validate.h"

#include <stdlib.h>
#include <string.h>

/* The tracer in pieces: rf_tracer_validate (the inputs), rf_tracer_build (Embree's scenes),
 * rf_tracer_pixels (the image loop and supersampling), rf_tracer_camera (matrices, primary
 * rays), rf_tracer_two_interface and rf_tracer_full (the two modes), rf_tracer_rays (hits,
 * normals, refraction) and rf_tracer_surfaces (opaque surfaces, the environment). */

rf_status rf_trace_options_default(rf_trace_options* options)
{
  if (options == NULL)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  options->mode = RF_TRACE_TWO_INTERFACE;
  options->tir_clamp = 1;
  options->max_depth = 8;
  options->fresnel = 1;
  options->threads = 2;
  options->environment = NULL;
  options->environment_user = NULL;
  options->samples_per_side = 1;
  options->background[0] = 0.0;
  options->background[1] = 0.0;
  options->background[2] = 0.0;
  options->progress = NULL;
  options->progress_user = NULL;
  return RF_OK;
}

rf_status rf_trace_image_alloc(rf_trace_image* img, int w, int h)
{
  size_t n;
  if (img == NULL)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  memset(img, 0, sizeof(*img));
  if (w <= 0 || h <= 0 || w > RF_MAX_IMAGE_SIDE || h > RF_MAX_IMAGE_SIDE)
  {
    return RF_REF_ERR_BAD_OPTION;
  }
  n = (size_t)w * (size_t)h;
  img->width = w;
  img->height = h;
  img->colour = (float*)calloc(3 * n, sizeof(float));
  img->coverage = (float*)calloc(n, sizeof(float));
  img->p1 = (float*)calloc(3 * n, sizeof(float));
  img->p2 = (float*)calloc(3 * n, sizeof(float));
  img->t2 = (float*)calloc(3 * n, sizeof(float));
  img->thickness = (float*)calloc(n, sizeof(float));
  img->bounces = (int*)calloc(n, sizeof(int));
  img->tir = (unsigned char*)calloc(n, 1);
  img->hit = (unsigned char*)calloc(n, 1);
  img->opaque = (unsigned char*)calloc(n, 1);
  if (img->colour == NULL || img->coverage == NULL || img->p1 == NULL || img->p2 == NULL ||
    img->t2 == NULL || img->thickness == NULL || img->bounces == NULL || img->tir == NULL ||
    img->hit == NULL || img->opaque == NULL)
  {
    rf_trace_image_free(img);
    return RF_REF_ERR_OUT_OF_MEMORY;
  }
  return RF_OK;
}

void rf_trace_image_free(rf_trace_image* img)
{
  if (img == NULL)
  {
    return;
  }
  free(img->colour);
  free(img->coverage);
  free(img->p1);
  free(img->p2);
  free(img->t2);
  free(img->thickness);
  free(img->bounces);
  free(img->tir);
  free(img->hit);
  free(img->opaque);
  memset(img, 0, sizeof(*img));
}

rf_status rf_trace(const rf_mesh* meshes, size_t mesh_count, const rf_camera* camera,
  const rf_trace_options* options, rf_trace_image* out)
{
  return rf_trace_scene(meshes, mesh_count, NULL, 0, camera, options, out);
}

rf_status rf_trace_scene(const rf_mesh* meshes, size_t mesh_count,
  const rf_opaque_mesh* opaque, size_t opaque_count, const rf_camera* camera,
  const rf_trace_options* options, rf_trace_image* out)
{
  rf_tracer tr;
  rf_status s =
    rf_validate_inputs(meshes, mesh_count, opaque, opaque_count, camera, options, out);
  if (s != RF_OK)
  {
    return s;
  }
  memset(&tr, 0, sizeof(tr));
  tr.meshes = meshes;
  tr.mesh_count = mesh_count;
  tr.opaque = opaque;
  tr.opaque_count = opaque_count;
  tr.options = options;
  tr.out = out;
  memcpy(tr.world_to_view, camera->view, sizeof(tr.world_to_view));
  if (!rf_mat4_invert(camera->projection, tr.clip_to_view) ||
    !rf_mat4_invert(camera->view, tr.view_to_world))
  {
    return RF_REF_ERR_BAD_OPTION;
  }
  /* Perspective projections map w from -z (row 3 is (0, 0, -1, 0)); parallel ones keep w. */
  tr.parallel = camera->projection[14] == 0.0;
  tr.eye_world = rf_mat4_point(tr.view_to_world, rf_vec3_make(0.0, 0.0, 0.0));
  tr.view_z_world = rf_vec3_normalize(rf_vec3_make(
    tr.world_to_view[8], tr.world_to_view[9], tr.world_to_view[10]));
  /* The glass alone sets the ray offset: opaque surfaces leave the glass's rays unchanged. */
  tr.epsilon = rf_scene_epsilon(meshes, mesh_count);
  s = rf_build_scene(&tr);
  if (s == RF_OK)
  {
    s = rf_run_workers(&tr, options->threads);
  }
  rf_release_scene(&tr);
  return s;
}
