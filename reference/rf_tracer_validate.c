/* rf_tracer_validate.c: the checks of the tracer's inputs (see rf_tracer_validate.h). */
#include "rf_tracer_validate.h"

#include <limits.h>
#include <math.h>
#include <stddef.h>

static int rf_all_finite(const double* v, size_t n)
{
  size_t i;
  for (i = 0; i < n; ++i)
  {
    if (!isfinite(v[i]))
    {
      return 0;
    }
  }
  return 1;
}

static int rf_all_finite_f(const float* v, size_t n)
{
  size_t i;
  for (i = 0; i < n; ++i)
  {
    if (!isfinite(v[i]))
    {
      return 0;
    }
  }
  return 1;
}

static rf_status rf_validate_mesh(const rf_mesh* mesh)
{
  size_t i;
  rf_status s = rf_validate_ior(mesh->ior);
  if (s != RF_OK)
  {
    return s;
  }
  s = rf_validate_absorption(mesh->absorption);
  if (s != RF_OK)
  {
    return s;
  }
  if (mesh->triangle_count == 0)
  {
    return RF_OK;
  }
  if (mesh->positions == NULL || mesh->triangles == NULL)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  if (mesh->triangle_count > UINT_MAX / 3 || mesh->vertex_count > UINT_MAX)
  {
    return RF_REF_ERR_BAD_OPTION; /* beyond Embree's 32-bit indices */
  }
  for (i = 0; i < 3 * mesh->triangle_count; ++i)
  {
    if (mesh->triangles[i] >= mesh->vertex_count)
    {
      return RF_REF_ERR_INDEX_OUT_OF_RANGE;
    }
  }
  if (!rf_all_finite_f(mesh->positions, 3 * mesh->vertex_count) ||
    (mesh->normals != NULL && !rf_all_finite_f(mesh->normals, 3 * mesh->vertex_count)))
  {
    return RF_ERR_NOT_FINITE;
  }
  return RF_OK;
}

static int rf_in_unit_range(const double* v, size_t n)
{
  size_t i;
  for (i = 0; i < n; ++i)
  {
    if (!(v[i] >= 0.0 && v[i] <= 1.0))
    {
      return 0;
    }
  }
  return 1;
}

static rf_status rf_validate_material(const rf_opaque_material* m)
{
  const double factors[4] = { m->ambient, m->diffuse, m->specular, m->specular_power };
  if (!rf_all_finite(factors, 4) || !rf_all_finite(m->ambient_colour, 3) ||
    !rf_all_finite(m->diffuse_colour, 3) || !rf_all_finite(m->specular_colour, 3))
  {
    return RF_ERR_NOT_FINITE;
  }
  if (m->ambient < 0.0 || m->diffuse < 0.0 || m->specular < 0.0 || m->specular_power < 0.0 ||
    !rf_in_unit_range(m->ambient_colour, 3) || !rf_in_unit_range(m->diffuse_colour, 3) ||
    !rf_in_unit_range(m->specular_colour, 3))
  {
    return RF_REF_ERR_BAD_OPTION;
  }
  return RF_OK;
}

static rf_status rf_validate_opaque_mesh(const rf_opaque_mesh* mesh)
{
  size_t colour_count = 0;
  size_t i;
  const rf_status s = rf_validate_material(&mesh->material);
  if (s != RF_OK)
  {
    return s;
  }
  switch (mesh->colour_binding)
  {
    case RF_COLOUR_MATERIAL:
      break;
    case RF_COLOUR_PER_VERTEX:
      colour_count = mesh->vertex_count;
      break;
    case RF_COLOUR_PER_TRIANGLE:
      colour_count = mesh->triangle_count;
      break;
    default:
      return RF_REF_ERR_BAD_OPTION;
  }
  if (mesh->triangle_count == 0)
  {
    return RF_OK;
  }
  if (mesh->positions == NULL || mesh->triangles == NULL ||
    (mesh->colour_binding != RF_COLOUR_MATERIAL && mesh->colours == NULL))
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  if (mesh->triangle_count > UINT_MAX / 3 || mesh->vertex_count > UINT_MAX)
  {
    return RF_REF_ERR_BAD_OPTION;
  }
  for (i = 0; i < 3 * mesh->triangle_count; ++i)
  {
    if (mesh->triangles[i] >= mesh->vertex_count)
    {
      return RF_REF_ERR_INDEX_OUT_OF_RANGE;
    }
  }
  if (!rf_all_finite_f(mesh->positions, 3 * mesh->vertex_count) ||
    (mesh->normals != NULL && !rf_all_finite_f(mesh->normals, 3 * mesh->vertex_count)) ||
    (colour_count > 0 && !rf_all_finite_f(mesh->colours, 3 * colour_count)))
  {
    return RF_ERR_NOT_FINITE;
  }
  for (i = 0; i < 3 * colour_count; ++i)
  {
    if (!(mesh->colours[i] >= 0.f && mesh->colours[i] <= 1.f))
    {
      return RF_REF_ERR_BAD_OPTION;
    }
  }
  return RF_OK;
}

rf_status rf_validate_inputs(const rf_mesh* meshes, size_t mesh_count,
  const rf_opaque_mesh* opaque, size_t opaque_count, const rf_camera* camera,
  const rf_trace_options* options, const rf_trace_image* out)
{
  size_t m;
  if ((meshes == NULL && mesh_count > 0) || (opaque == NULL && opaque_count > 0) ||
    camera == NULL || options == NULL || out == NULL)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  if (mesh_count > UINT_MAX - 1 || opaque_count > UINT_MAX - 1)
  {
    return RF_REF_ERR_BAD_OPTION;
  }
  if ((options->mode != RF_TRACE_TWO_INTERFACE && options->mode != RF_TRACE_FULL) ||
    options->max_depth < 1 || options->max_depth > RF_TRACE_MAX_DEPTH_LIMIT ||
    options->threads < 1 || options->samples_per_side < 1 ||
    options->samples_per_side > RF_TRACE_MAX_SAMPLES_PER_SIDE)
  {
    return RF_REF_ERR_BAD_OPTION;
  }
  if (!rf_all_finite(options->background, 3))
  {
    return RF_ERR_NOT_FINITE;
  }
  if (camera->width <= 0 || camera->height <= 0 || camera->width > RF_MAX_IMAGE_SIDE ||
    camera->height > RF_MAX_IMAGE_SIDE || out->width != camera->width ||
    out->height != camera->height)
  {
    return RF_REF_ERR_BAD_OPTION;
  }
  if (!rf_all_finite(camera->view, 16) || !rf_all_finite(camera->projection, 16))
  {
    return RF_ERR_NOT_FINITE;
  }
  for (m = 0; m < mesh_count; ++m)
  {
    const rf_status s = rf_validate_mesh(&meshes[m]);
    if (s != RF_OK)
    {
      return s;
    }
  }
  for (m = 0; m < opaque_count; ++m)
  {
    const rf_status s = rf_validate_opaque_mesh(&opaque[m]);
    if (s != RF_OK)
    {
      return s;
    }
  }
  return RF_OK;
}
