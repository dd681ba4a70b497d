/* rf_tracer_build.c: the Embree scenes (see rf_tracer_build.h). */
#include "rf_tracer_build.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static void rf_embree_error(void* user, enum RTCError code, const char* message)
{
  (void)user;
  fprintf(stderr, "rf_tracer: Embree error %d: %s\n", (int)code, message ? message : "");
}

/* Secondary rays start this far along: well above float rounding at the scene's
 * coordinates (Embree intersects in float, about 6e-8 relative) and well below the
 * size of any feature a ray could meet. */
double rf_scene_epsilon(const rf_mesh* meshes, size_t mesh_count)
{
  double lo[3] = { INFINITY, INFINITY, INFINITY };
  double hi[3] = { -INFINITY, -INFINITY, -INFINITY };
  double largest = 0.0;
  double diagonal = 0.0;
  size_t m;
  size_t v;
  int c;
  for (m = 0; m < mesh_count; ++m)
  {
    if (meshes[m].triangle_count == 0)
    {
      continue;
    }
    for (v = 0; v < meshes[m].vertex_count; ++v)
    {
      for (c = 0; c < 3; ++c)
      {
        const double x = meshes[m].positions[3 * v + c];
        lo[c] = fmin(lo[c], x);
        hi[c] = fmax(hi[c], x);
        largest = fmax(largest, fabs(x));
      }
    }
  }
  for (c = 0; c < 3; ++c)
  {
    if (hi[c] >= lo[c])
    {
      diagonal += (hi[c] - lo[c]) * (hi[c] - lo[c]);
    }
  }
  diagonal = sqrt(diagonal);
  return fmax(1e-6 * diagonal, 1e-6 * largest) + 1e-30;
}

/* A triangle geometry in scene under the given ID (so a hit finds its mesh directly). */
static rf_status rf_attach_triangles(RTCDevice device, RTCScene scene, const float* positions,
  size_t vertex_count, const unsigned* triangles, size_t triangle_count, unsigned id)
{
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  float* vertices;
  unsigned* indices;
  if (geometry == NULL)
  {
    return RF_REF_ERR_EMBREE;
  }
  /* Copies (not shared buffers): Embree reads vertex buffers with 16-byte loads past the
   * last vertex, which a caller's array need not allow. */
  vertices = (float*)rtcSetNewGeometryBuffer(
    geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), vertex_count);
  indices = (unsigned*)rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0,
    RTC_FORMAT_UINT3, 3 * sizeof(unsigned), triangle_count);
  if (vertices == NULL || indices == NULL)
  {
    rtcReleaseGeometry(geometry);
    return RF_REF_ERR_OUT_OF_MEMORY;
  }
  memcpy(vertices, positions, 3 * sizeof(float) * vertex_count);
  memcpy(indices, triangles, 3 * sizeof(unsigned) * triangle_count);
  rtcCommitGeometry(geometry);
  rtcAttachGeometryByID(scene, geometry, id);
  rtcReleaseGeometry(geometry);
  return RF_OK;
}

static RTCScene rf_new_scene(RTCDevice device)
{
  RTCScene scene = rtcNewScene(device);
  if (scene != NULL)
  {
    /* Robust (watertight) traversal: a ray through a shared edge or vertex must not slip
     * between triangles, or a closed mesh would leak. */
    rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
  }
  return scene;
}

/* The opaque surfaces in a scene of their own: the two-interface mode looks for them alone
 * along the rays leaving the glass. */
static rf_status rf_build_opaque_scene(rf_tracer* tr)
{
  size_t m;
  int any = 0;
  for (m = 0; m < tr->opaque_count; ++m)
  {
    any = any || tr->opaque[m].triangle_count > 0;
  }
  if (!any)
  {
    return RF_OK;
  }
  tr->opaque_scene = rf_new_scene(tr->device);
  if (tr->opaque_scene == NULL)
  {
    return RF_REF_ERR_EMBREE;
  }
  for (m = 0; m < tr->opaque_count; ++m)
  {
    const rf_opaque_mesh* mesh = &tr->opaque[m];
    if (mesh->triangle_count > 0)
    {
      const rf_status s = rf_attach_triangles(tr->device, tr->opaque_scene, mesh->positions,
        mesh->vertex_count, mesh->triangles, mesh->triangle_count, (unsigned)m);
      if (s != RF_OK)
      {
        return s;
      }
    }
  }
  rtcCommitScene(tr->opaque_scene);
  return RF_OK;
}

rf_status rf_build_scene(rf_tracer* tr)
{
  size_t m;
  rf_status s;
  char config[64];
  snprintf(config, sizeof(config), "threads=%d", tr->options->threads);
  tr->device = rtcNewDevice(config);
  if (tr->device == NULL)
  {
    return RF_REF_ERR_EMBREE;
  }
  rtcSetDeviceErrorFunction(tr->device, rf_embree_error, NULL);
  tr->scene = rf_new_scene(tr->device);
  if (tr->scene == NULL)
  {
    return RF_REF_ERR_EMBREE;
  }
  for (m = 0; m < tr->mesh_count; ++m)
  {
    const rf_mesh* mesh = &tr->meshes[m];
    if (mesh->triangle_count > 0)
    {
      s = rf_attach_triangles(tr->device, tr->scene, mesh->positions, mesh->vertex_count,
        mesh->triangles, mesh->triangle_count, (unsigned)m);
      if (s != RF_OK)
      {
        return s;
      }
    }
  }
  rtcCommitScene(tr->scene);
  s = rf_build_opaque_scene(tr);
  if (s != RF_OK)
  {
    return s;
  }
  if (rtcGetDeviceError(tr->device) != RTC_ERROR_NONE)
  {
    return RF_REF_ERR_EMBREE;
  }
  return RF_OK;
}

void rf_release_scene(rf_tracer* tr)
{
  if (tr->scene != NULL)
  {
    rtcReleaseScene(tr->scene);
  }
  if (tr->opaque_scene != NULL)
  {
    rtcReleaseScene(tr->opaque_scene);
  }
  if (tr->device != NULL)
  {
    rtcReleaseDevice(tr->device);
  }
}
