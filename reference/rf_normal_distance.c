#include "rf_normal_distance.h"

#include "rf_jobs.h"
#include "rf_mesh_scene.h"

#include <embree3/rtcore.h>
#include <math.h>
#include <stdlib.h>

/* One thread's share: the vertices [first, end), contiguous so that neighbouring rays (and
 * the BVH nodes they visit) stay together, cast 8 at a time (Embree's packets). */
typedef struct
{
  const rf_mesh_scene* mesh;
  const float* positions;
  const float* normals;
  float* distances;
  size_t first;
  size_t end;
} rf_normal_distance_job;

/* The inward unit normal of vertex i into dir; 0 when the normal is zero or not finite. */
static int rf_inward_direction(const float* normals, size_t i, float dir[3])
{
  const float* n = normals + 3 * i;
  const float len = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (!(len > 0.0f) || !isfinite(len))
  {
    return 0;
  }
  dir[0] = -n[0] / len;
  dir[1] = -n[1] / len;
  dir[2] = -n[2] / len;
  return 1;
}

/* A ray that ends exactly on a vertex or an edge of the far side (the antipode of a UV
 * sphere's vertex is a vertex) can slip through between its triangles in float: cast again
 * with the direction tilted by 1e-4 radians, which moves the hit by 1e-4 d at most. */
static float rf_retry_tilted(const rf_mesh_scene* mesh, const float* origin, const float dir[3])
{
  const float tilt = 1e-4f;
  struct RTCIntersectContext context;
  struct RTCRayHit rh;
  int k;
  rtcInitIntersectContext(&context);
  for (k = 0; k < 2; ++k)
  {
    rh.ray.org_x = origin[0];
    rh.ray.org_y = origin[1];
    rh.ray.org_z = origin[2];
    rh.ray.dir_x = dir[0] + (k == 0 ? tilt : 0.0f);
    rh.ray.dir_y = dir[1] + (k == 1 ? tilt : 0.0f);
    rh.ray.dir_z = dir[2] + tilt;
    rh.ray.tnear = 1e-4f * (float)mesh->extent;
    rh.ray.tfar = INFINITY;
    rh.ray.time = 0.0f;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(mesh->scene, &context, &rh);
    if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID)
    {
      return rh.ray.tfar;
    }
  }
  return 0.0f;
}

static void* rf_normal_distance_run(void* argument)
{
  const rf_normal_distance_job* job = (const rf_normal_distance_job*)argument;
  const float extent = (float)job->mesh->extent;
  struct RTCIntersectContext context;
  size_t base;
  rtcInitIntersectContext(&context);
  for (base = job->first; base < job->end; base += 8)
  {
    RTC_ALIGN(32) struct RTCRayHit8 packet;
    RTC_ALIGN(32) int valid[8];
    float dirs[8][3];
    int lane;
    for (lane = 0; lane < 8; ++lane)
    {
      const size_t i = base + (size_t)lane;
      const float* p = job->positions + 3 * (i < job->end ? i : base);
      valid[lane] = i < job->end && rf_inward_direction(job->normals, i, dirs[lane]) ? -1 : 0;
      if (!valid[lane])
      {
        dirs[lane][0] = 0.0f;
        dirs[lane][1] = 0.0f;
        dirs[lane][2] = -1.0f;
      }
      packet.ray.org_x[lane] = p[0];
      packet.ray.org_y[lane] = p[1];
      packet.ray.org_z[lane] = p[2];
      packet.ray.dir_x[lane] = dirs[lane][0];
      packet.ray.dir_y[lane] = dirs[lane][1];
      packet.ray.dir_z[lane] = dirs[lane][2];
      /* The ray starts on the surface: skip the triangles that share the vertex. */
      packet.ray.tnear[lane] = 1e-4f * extent;
      packet.ray.tfar[lane] = INFINITY;
      packet.ray.time[lane] = 0.0f;
      packet.ray.mask[lane] = 0xFFFFFFFFu;
      packet.ray.id[lane] = (unsigned)lane;
      packet.ray.flags[lane] = 0;
      packet.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
      packet.hit.instID[0][lane] = RTC_INVALID_GEOMETRY_ID;
    }
    rtcIntersect8(valid, job->mesh->scene, &context, &packet);
    for (lane = 0; lane < 8 && base + (size_t)lane < job->end; ++lane)
    {
      const size_t i = base + (size_t)lane;
      if (!valid[lane])
      {
        continue;
      }
      job->distances[i] = packet.hit.geomID[lane] != RTC_INVALID_GEOMETRY_ID
        ? packet.ray.tfar[lane]
        : rf_retry_tilted(job->mesh, job->positions + 3 * i, dirs[lane]);
    }
  }
  return NULL;
}

rf_status rf_normal_distances(const float* positions, const float* normals, size_t vertex_count,
  const unsigned* triangles, size_t triangle_count, float* distances, int threads)
{
  rf_mesh_scene mesh;
  rf_normal_distance_job* jobs;
  rf_status status;
  size_t i;
  int k;

  if (!positions || !normals || !triangles || !distances)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  if (threads < 1)
  {
    return RF_REF_ERR_BAD_OPTION;
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
  /* No more threads than packets of 8. */
  if ((size_t)threads > (vertex_count + 7) / 8)
  {
    threads = (int)((vertex_count + 7) / 8);
  }
  jobs = (rf_normal_distance_job*)calloc((size_t)threads, sizeof(rf_normal_distance_job));
  if (!jobs)
  {
    rf_mesh_scene_release(&mesh);
    return RF_REF_ERR_OUT_OF_MEMORY;
  }
  for (k = 0; k < threads; ++k)
  {
    jobs[k].mesh = &mesh;
    jobs[k].positions = positions;
    jobs[k].normals = normals;
    jobs[k].distances = distances;
    jobs[k].first = vertex_count * (size_t)k / (size_t)threads;
    jobs[k].end = vertex_count * (size_t)(k + 1) / (size_t)threads;
  }
  status = rf_run_jobs(jobs, sizeof(rf_normal_distance_job), threads, rf_normal_distance_run)
    ? RF_OK
    : RF_REF_ERR_OUT_OF_MEMORY;
  free(jobs);
  rf_mesh_scene_release(&mesh);
  return status;
}
