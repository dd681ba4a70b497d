/* rf_tracer_rays.c: rays against the scene (see rf_tracer_rays.h). */
#include "rf_tracer_rays.h"

#include "rf_optics.h"

#include <limits.h>
#include <math.h>
#include <string.h>


/* Retries when a secondary ray finds the triangle it starts on again. */
#define RF_SELF_HIT_RETRIES 4

/* Nearest hit of o + t d for t in (tnear, tfar). A hit on the triangle (skip_geom, skip_prim)
 * the ray starts from is skipped: a ray leaving a flat triangle cannot meet it again, so
 * such a hit is rounding, and stepping tnear past it is more robust than a larger epsilon
 * (which would skip genuine hits in thin parts). */
static int rf_intersect_in(RTCScene scene, rf_vec3 o, rf_vec3 d, double tnear, double tfar,
  unsigned skip_geom, unsigned skip_prim, rf_hit* hit)
{
  int attempt;
  float near_f = (float)tnear;
  for (attempt = 0; attempt < RF_SELF_HIT_RETRIES; ++attempt)
  {
    struct RTCIntersectContext context;
    struct RTCRayHit rh;
    rtcInitIntersectContext(&context);
    memset(&rh, 0, sizeof(rh));
    rh.ray.org_x = (float)o.x;
    rh.ray.org_y = (float)o.y;
    rh.ray.org_z = (float)o.z;
    rh.ray.dir_x = (float)d.x;
    rh.ray.dir_y = (float)d.y;
    rh.ray.dir_z = (float)d.z;
    rh.ray.tnear = near_f;
    rh.ray.tfar = (float)tfar;
    rh.ray.mask = UINT_MAX;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID)
    {
      return 0;
    }
    if (rh.hit.geomID == skip_geom && rh.hit.primID == skip_prim)
    {
      near_f = nextafterf(rh.ray.tfar, INFINITY);
      continue;
    }
    hit->geom = rh.hit.geomID;
    hit->prim = rh.hit.primID;
    hit->t = rh.ray.tfar;
    hit->u = rh.hit.u;
    hit->v = rh.hit.v;
    hit->point = rf_vec3_add(o, rf_vec3_scale(d, hit->t));
    return 1;
  }
  return 0;
}

/* The nearest glass surface. */
int rf_intersect(const rf_tracer* tr, rf_vec3 o, rf_vec3 d, double tnear, double tfar,
  unsigned skip_geom, unsigned skip_prim, rf_hit* hit)
{
  return rf_intersect_in(tr->scene, o, d, tnear, tfar, skip_geom, skip_prim, hit);
}

/* The nearest opaque surface (none when the scene has no opaque mesh). */
int rf_intersect_opaque(
  const rf_tracer* tr, rf_vec3 o, rf_vec3 d, double tnear, double tfar, rf_hit* hit)
{
  return tr->opaque_scene != NULL &&
    rf_intersect_in(tr->opaque_scene, o, d, tnear, tfar, RTC_INVALID_GEOMETRY_ID,
      RTC_INVALID_GEOMETRY_ID, hit);
}

static rf_vec3 rf_mesh_vector(const float* xyz, unsigned index)
{
  const float* p = xyz + 3 * (size_t)index;
  return rf_vec3_make(p[0], p[1], p[2]);
}

/* Unit normal at the hit, not oriented: barycentric interpolation of the vertex normals
 * (Embree's u, v: hit = (1-u-v) v0 + u v1 + v v2), which is what the rasterizer
 * interpolates for the GPU; the geometric normal when the mesh has no normals or the
 * interpolated one vanishes. */
/* The unit normal of a triangle from its winding (counter-clockwise seen from the side it
 * points to, OpenGL's front face). */
rf_vec3 rf_winding_normal(const float* positions, const unsigned* tri)
{
  const rf_vec3 p0 = rf_mesh_vector(positions, tri[0]);
  const rf_vec3 p1 = rf_mesh_vector(positions, tri[1]);
  const rf_vec3 p2 = rf_mesh_vector(positions, tri[2]);
  return rf_vec3_normalize(rf_vec3_cross(rf_vec3_sub(p1, p0), rf_vec3_sub(p2, p0)));
}

rf_vec3 rf_surface_normal(
  const float* positions, const float* normals, const unsigned* triangles, const rf_hit* hit)
{
  const unsigned* tri = triangles + 3 * (size_t)hit->prim;
  if (normals != NULL)
  {
    rf_vec3 n =
      rf_vec3_add(rf_vec3_scale(rf_mesh_vector(normals, tri[0]), 1.0 - hit->u - hit->v),
        rf_vec3_add(rf_vec3_scale(rf_mesh_vector(normals, tri[1]), hit->u),
          rf_vec3_scale(rf_mesh_vector(normals, tri[2]), hit->v)));
    n = rf_vec3_normalize(n);
    if (rf_vec3_length(n) > 0.0)
    {
      return n;
    }
  }
  return rf_winding_normal(positions, tri);
}

rf_vec3 rf_shading_normal(const rf_tracer* tr, const rf_hit* hit)
{
  const rf_mesh* mesh = &tr->meshes[hit->geom];
  return rf_surface_normal(mesh->positions, mesh->normals, mesh->triangles, hit);
}

/* Refraction with a TIR policy; returns 1 under TIR. An invalid interface (a degenerate
 * normal, which rf_shading_normal already avoids) lets the ray pass unbent. */
int rf_refract_policy(rf_vec3 incident, rf_vec3 normal, double eta, int clamp,
  rf_vec3* transmitted)
{
  const rf_status s = clamp ? rf_refract_clamped(incident, normal, eta, transmitted)
                            : rf_refract(incident, normal, eta, transmitted);
  if (s == RF_TIR)
  {
    return 1;
  }
  if (s != RF_OK)
  {
    *transmitted = incident;
  }
  return 0;
}
