/* rf_mesh_scene.c: one triangle mesh as a watertight Embree 3 scene (see the header). */
#include "rf_mesh_scene.h"

#include <math.h>
#include <string.h>

rf_status rf_mesh_scene_build(rf_mesh_scene* s, const float* positions, size_t vertex_count,
  const unsigned* triangles, size_t triangle_count)
{
  RTCGeometry geometry;
  float* vertex_buffer;
  unsigned* index_buffer;
  double lo[3] = { INFINITY, INFINITY, INFINITY };
  double hi[3] = { -INFINITY, -INFINITY, -INFINITY };
  size_t i;
  int k;
  memset(s, 0, sizeof(*s));
  for (i = 0; i < 3 * vertex_count; ++i)
  {
    /* Beyond, Embree takes a ray as invalid (a failed assertion in Debian's build): as good
     * as infinite to a float ray tracer. */
    if (!(fabsf(positions[i]) < RF_MESH_SCENE_LARGEST))
    {
      return RF_ERR_NOT_FINITE;
    }
  }
  for (i = 0; i < 3 * triangle_count; ++i)
  {
    if (triangles[i] >= vertex_count)
    {
      return RF_REF_ERR_INDEX_OUT_OF_RANGE;
    }
  }
  for (i = 0; i < vertex_count; ++i)
  {
    for (k = 0; k < 3; ++k)
    {
      lo[k] = fmin(lo[k], positions[3 * i + k]);
      hi[k] = fmax(hi[k], positions[3 * i + k]);
    }
  }
  for (k = 0; k < 3; ++k)
  {
    s->extent = fmax(s->extent, hi[k] - lo[k]);
  }
  s->device = rtcNewDevice(NULL);
  if (!s->device)
  {
    return RF_REF_ERR_EMBREE;
  }
  s->scene = rtcNewScene(s->device);
  rtcSetSceneFlags(s->scene, RTC_SCENE_FLAG_ROBUST);
  if (triangle_count > 0)
  {
    geometry = rtcNewGeometry(s->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    vertex_buffer = (float*)rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), vertex_count);
    index_buffer = (unsigned*)rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0,
      RTC_FORMAT_UINT3, 3 * sizeof(unsigned), triangle_count);
    if (!vertex_buffer || !index_buffer)
    {
      rtcReleaseGeometry(geometry);
      rf_mesh_scene_release(s);
      return RF_REF_ERR_EMBREE;
    }
    memcpy(vertex_buffer, positions, 3 * vertex_count * sizeof(float));
    memcpy(index_buffer, triangles, 3 * triangle_count * sizeof(unsigned));
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(s->scene, geometry);
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(s->scene);
  if (rtcGetDeviceError(s->device) != RTC_ERROR_NONE)
  {
    rf_mesh_scene_release(s);
    return RF_REF_ERR_EMBREE;
  }
  return RF_OK;
}

void rf_mesh_scene_release(rf_mesh_scene* s)
{
  if (s->scene)
  {
    rtcReleaseScene(s->scene);
  }
  if (s->device)
  {
    rtcReleaseDevice(s->device);
  }
  memset(s, 0, sizeof(*s));
}
