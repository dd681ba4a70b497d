#include "rf_normal_distance.h"

#include "rf_mesh_scene.h"

#include <embree3/rtcore.h>
#include <math.h>

rf_status rf_normal_distances(const float* positions, const float* normals, size_t vertex_count,
  const unsigned* triangles, size_t triangle_count, float* distances)
{
  rf_mesh_scene mesh;
  float extent;
  struct RTCIntersectContext context;
  rf_status status;
  size_t i;
  int k;

  if (!positions || !normals || !triangles || !distances)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  for (i = 0; i < vertex_count; ++i)
  {
    distances[i] = 0.0f;
  }
  if (vertex_count == 0 || triangle_count == 0)
  {
    return RF_OK;
  }
  /* Rays through the centre of a sphere end exactly on the opposite pole vertex: only the
   * robust (watertight) intersector the scene uses is sure to report such edge and vertex
   * hits. */
  status = rf_mesh_scene_build(&mesh, positions, vertex_count, triangles, triangle_count);
  if (status != RF_OK)
  {
    return status;
  }
  extent = (float)mesh.extent;
  rtcInitIntersectContext(&context);

  for (i = 0; i < vertex_count; ++i)
  {
    const float* n = normals + 3 * i;
    const float len = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    struct RTCRayHit rh;
    if (!(len > 0.0f) || !isfinite(len))
    {
      continue;
    }
    rh.ray.org_x = positions[3 * i];
    rh.ray.org_y = positions[3 * i + 1];
    rh.ray.org_z = positions[3 * i + 2];
    rh.ray.dir_x = -n[0] / len;
    rh.ray.dir_y = -n[1] / len;
    rh.ray.dir_z = -n[2] / len;
    /* The ray starts on the surface: skip the triangles that share the vertex. */
    rh.ray.tnear = 1e-4f * extent;
    rh.ray.tfar = INFINITY;
    rh.ray.time = 0.0f;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(mesh.scene, &context, &rh);
    /* A ray that ends exactly on a vertex or an edge of the far side (the antipode of a UV
     * sphere's vertex is a vertex) can slip through between its triangles in float: retry
     * with the direction tilted by 1e-4 radians, which moves the hit by 1e-4 d at most. */
    for (k = 0; k < 2 && rh.hit.geomID == RTC_INVALID_GEOMETRY_ID; ++k)
    {
      const float tilt = 1e-4f;
      rh.ray.dir_x = -n[0] / len + (k == 0 ? tilt : 0.0f);
      rh.ray.dir_y = -n[1] / len + (k == 1 ? tilt : 0.0f);
      rh.ray.dir_z = -n[2] / len + tilt;
      rh.ray.tfar = INFINITY;
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(mesh.scene, &context, &rh);
    }
    if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID)
    {
      distances[i] = rh.ray.tfar;
    }
  }
  rf_mesh_scene_release(&mesh);
  return RF_OK;
}
