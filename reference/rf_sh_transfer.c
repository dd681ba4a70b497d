/* rf_sh_transfer.c: the SH method's per-vertex precomputation with Embree 3 (see the header). */
#include "rf_sh_transfer.h"

#include "rf_jobs.h"
#include "rf_mesh_scene.h"
#include "rf_optics.h"
#include "rf_sh.h"
#include "rf_vec3.h"

#include <embree3/rtcore.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The glass as Embree sees it, and what a path needs of the mesh. */
typedef struct rf_sh_scene
{
  rf_mesh_scene mesh;
  const float* positions;
  const float* normals;
  const unsigned* triangles;
  size_t vertex_count;
  double ior;
  double epsilon; /* a path's segments start this far from their surface */
} rf_sh_scene;

static rf_vec3 rf_sh_vertex_vector(const float* xyz, size_t index)
{
  return rf_vec3_make(xyz[3 * index], xyz[3 * index + 1], xyz[3 * index + 2]);
}

static rf_status rf_sh_scene_build(rf_sh_scene* s, const float* positions, const float* normals,
  size_t vertex_count, const unsigned* triangles, size_t triangle_count, double ior)
{
  rf_status status;
  size_t i;
  memset(s, 0, sizeof(*s));
  if (!positions || !normals || !triangles)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  if (!(ior > 0.0) || !isfinite(ior))
  {
    return RF_ERR_IOR_NOT_POSITIVE;
  }
  for (i = 0; i < 3 * vertex_count; ++i)
  {
    if (!isfinite(normals[i]))
    {
      return RF_ERR_NOT_FINITE;
    }
  }
  status = rf_mesh_scene_build(&s->mesh, positions, vertex_count, triangles, triangle_count);
  if (status != RF_OK)
  {
    return status;
  }
  s->positions = positions;
  s->normals = normals;
  s->triangles = triangles;
  s->vertex_count = vertex_count;
  s->ior = ior;
  s->epsilon = 1e-4 * (s->mesh.extent > 0.0 ? s->mesh.extent : 1.0);
  return RF_OK;
}

static void rf_sh_scene_release(rf_sh_scene* s)
{
  rf_mesh_scene_release(&s->mesh);
  memset(s, 0, sizeof(*s));
}

/* The first surface along o + t d (t > epsilon): its point, its interpolated outward normal
 * (the geometric one where the vertex normals cancel), and t. False when nothing is hit. */
static int rf_sh_next_surface(
  const rf_sh_scene* s, rf_vec3 o, rf_vec3 d, rf_vec3* point, rf_vec3* normal, double* t)
{
  struct RTCIntersectContext context;
  struct RTCRayHit rh;
  const unsigned* tri;
  double u;
  double v;
  rf_vec3 n;
  rtcInitIntersectContext(&context);
  rh.ray.org_x = (float)o.x;
  rh.ray.org_y = (float)o.y;
  rh.ray.org_z = (float)o.z;
  rh.ray.dir_x = (float)d.x;
  rh.ray.dir_y = (float)d.y;
  rh.ray.dir_z = (float)d.z;
  rh.ray.tnear = (float)s->epsilon;
  rh.ray.tfar = INFINITY;
  rh.ray.time = 0.0f;
  rh.ray.mask = 0xFFFFFFFFu;
  rh.ray.id = 0;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(s->mesh.scene, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID)
  {
    return 0;
  }
  tri = s->triangles + 3 * (size_t)rh.hit.primID;
  u = rh.hit.u;
  v = rh.hit.v;
  n = rf_vec3_add(rf_vec3_add(rf_vec3_scale(rf_sh_vertex_vector(s->normals, tri[0]), 1.0 - u - v),
                    rf_vec3_scale(rf_sh_vertex_vector(s->normals, tri[1]), u)),
    rf_vec3_scale(rf_sh_vertex_vector(s->normals, tri[2]), v));
  if (!(rf_vec3_length(n) > 0.0))
  {
    n = rf_vec3_make(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
  }
  *normal = rf_vec3_normalize(n);
  *t = rh.ray.tfar;
  *point = rf_vec3_add(o, rf_vec3_scale(d, rh.ray.tfar));
  return 1;
}

/* The path of view direction V entering at vertex i (see rf_sh_transfer_path): every surface
 * met is an interface, glass inside it (the outward normal says which side the path is on);
 * the length counts the segments inside. */
static void rf_sh_path(const rf_sh_scene* s, size_t i, rf_vec3 V, int max_bounces,
  rf_vec3* exit_direction, double* length)
{
  rf_vec3 n = rf_vec3_normalize(rf_sh_vertex_vector(s->normals, i));
  rf_vec3 p = rf_sh_vertex_vector(s->positions, i);
  rf_vec3 d;
  int bounces = 0;
  int inside = 1;
  int k;
  *length = 0.0;
  if (rf_refract(V, n, 1.0 / s->ior, &d) != RF_OK)
  {
    *exit_direction = d; /* reflected outside (an index below 1 at grazing incidence) */
    return;
  }
  for (k = 0; k < max_bounces + 64; ++k)
  {
    rf_vec3 hit;
    rf_vec3 normal;
    rf_vec3 next;
    double t;
    rf_status status;
    int leaving;
    int found = rf_sh_next_surface(s, p, d, &hit, &normal, &t);
    /* Inside, a path that ends exactly on a vertex or an edge (through a UV sphere's centre,
     * the antipode of a vertex is a vertex) can slip between the triangles in float even with
     * the robust intersector: it is retried tilted by 1e-4 radians. */
    int tilt;
    for (tilt = 0; tilt < 2 && !found && inside; ++tilt)
    {
      const rf_vec3 tilted = rf_vec3_normalize(rf_vec3_add(d,
        tilt == 0 ? rf_vec3_make(1e-4, 0.0, 1e-4) : rf_vec3_make(0.0, 1e-4, -1e-4)));
      found = rf_sh_next_surface(s, p, tilted, &hit, &normal, &t);
    }
    if (!found)
    {
      break; /* out of the glass for good, or an open mesh */
    }
    leaving = rf_vec3_dot(d, normal) > 0.0;
    if (leaving)
    {
      *length += t;
    }
    p = hit;
    status = rf_refract(d, normal, leaving ? s->ior : 1.0 / s->ior, &next);
    if (status == RF_TIR)
    {
      d = next;
      if (bounces >= max_bounces)
      {
        break;
      }
      ++bounces;
      continue;
    }
    if (status != RF_OK)
    {
      break;
    }
    d = next;
    inside = !leaving;
  }
  *exit_direction = d;
}

/* Directions spread evenly over the hemisphere around +z (a Fibonacci spiral): the k-th of
 * count, unit. */
static rf_vec3 rf_sh_hemisphere_direction(int k, int count)
{
  const double golden = 3.14159265358979323846 * (3.0 - sqrt(5.0));
  const double z = 1.0 - (k + 0.5) / count;
  const double r = sqrt(fmax(1.0 - z * z, 0.0));
  return rf_vec3_make(r * cos(golden * k), r * sin(golden * k), z);
}

/* An orthonormal frame with w = n. */
static void rf_sh_frame(rf_vec3 n, rf_vec3* u, rf_vec3* v)
{
  const rf_vec3 helper = fabs(n.x) < 0.7 ? rf_vec3_make(1.0, 0.0, 0.0) : rf_vec3_make(0.0, 1.0, 0.0);
  *u = rf_vec3_normalize(rf_vec3_cross(helper, n));
  *v = rf_vec3_cross(n, *u);
}

typedef struct rf_sh_job
{
  const rf_sh_scene* scene;
  const rf_sh_transfer_options* options;
  float* coefficients;
  size_t first;
  size_t step;
  int report_progress;
} rf_sh_job;

static void* rf_sh_job_run(void* arg)
{
  const rf_sh_job* job = (const rf_sh_job*)arg;
  const rf_sh_scene* s = job->scene;
  const int order = job->options->order;
  const int count = rf_sh_coefficient_count(order);
  const int directions = job->options->directions;
  /* Each sample stands for 2 pi / directions of the hemisphere (uniform in z). */
  const double weight = 2.0 * 3.14159265358979323846 / directions;
  double sums[RF_SH_TRANSFER_FUNCTIONS][(RF_SH_ORDER_MAX + 1) * (RF_SH_ORDER_MAX + 1)];
  size_t i;
  for (i = job->first; i < s->vertex_count; i += job->step)
  {
    const rf_vec3 normal = rf_sh_vertex_vector(s->normals, i);
    float* out = job->coefficients + i * RF_SH_TRANSFER_FUNCTIONS * (size_t)count;
    rf_vec3 n;
    rf_vec3 u;
    rf_vec3 v;
    int k;
    int f;
    int c;
    memset(sums, 0, sizeof(sums));
    if (rf_vec3_length(normal) > 0.0)
    {
      n = rf_vec3_normalize(normal);
      rf_sh_frame(n, &u, &v);
      for (k = 0; k < directions; ++k)
      {
        /* w over the outer hemisphere; the view direction comes from outside: V = -w. */
        const rf_vec3 h = rf_sh_hemisphere_direction(k, directions);
        const rf_vec3 w =
          rf_vec3_add(rf_vec3_add(rf_vec3_scale(u, h.x), rf_vec3_scale(v, h.y)), rf_vec3_scale(n, h.z));
        const rf_vec3 V = rf_vec3_scale(w, -1.0);
        /* Its mirror across the tangent plane, on the inner hemisphere, takes the same values. */
        const rf_vec3 mirrored = rf_vec3_sub(V, rf_vec3_scale(n, 2.0 * rf_vec3_dot(V, n)));
        rf_vec3 out_direction;
        double length;
        double values[RF_SH_TRANSFER_FUNCTIONS];
        double basis[(RF_SH_ORDER_MAX + 1) * (RF_SH_ORDER_MAX + 1)];
        double mirrored_basis[(RF_SH_ORDER_MAX + 1) * (RF_SH_ORDER_MAX + 1)];
        const double at[3] = { V.x, V.y, V.z };
        const double at_mirror[3] = { mirrored.x, mirrored.y, mirrored.z };
        rf_sh_path(s, i, V, job->options->max_bounces, &out_direction, &length);
        values[0] = out_direction.x;
        values[1] = out_direction.y;
        values[2] = out_direction.z;
        values[3] = length;
        if (rf_sh_basis(order, at, basis) != RF_OK ||
          rf_sh_basis(order, at_mirror, mirrored_basis) != RF_OK)
        {
          continue;
        }
        for (f = 0; f < RF_SH_TRANSFER_FUNCTIONS; ++f)
        {
          for (c = 0; c < count; ++c)
          {
            sums[f][c] += weight * values[f] * (basis[c] + mirrored_basis[c]);
          }
        }
      }
    }
    for (f = 0; f < RF_SH_TRANSFER_FUNCTIONS; ++f)
    {
      for (c = 0; c < count; ++c)
      {
        out[f * count + c] = (float)sums[f][c];
      }
    }
    if (job->report_progress && job->options->progress)
    {
      job->options->progress((double)(i + 1) / (double)s->vertex_count, job->options->progress_user);
    }
  }
  return NULL;
}

rf_status rf_sh_transfer(const float* positions, const float* normals, size_t vertex_count,
  const unsigned* triangles, size_t triangle_count, double ior,
  const rf_sh_transfer_options* options, float* coefficients)
{
  rf_sh_scene scene;
  rf_sh_job* jobs;
  rf_status status;
  int threads;
  int ran;
  int k;
  if (!options || !coefficients)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  if (rf_sh_coefficient_count(options->order) == 0 || options->directions < 16 ||
    options->max_bounces < 0 || options->max_bounces > 64 || options->threads < 1)
  {
    return RF_REF_ERR_BAD_OPTION;
  }
  status = rf_sh_scene_build(&scene, positions, normals, vertex_count, triangles,
    triangle_count, ior);
  if (status != RF_OK)
  {
    rf_sh_scene_release(&scene);
    return status;
  }
  threads = options->threads;
  jobs = (rf_sh_job*)calloc((size_t)threads, sizeof(rf_sh_job));
  if (!jobs)
  {
    rf_sh_scene_release(&scene);
    return RF_REF_ERR_OUT_OF_MEMORY;
  }
  for (k = 0; k < threads; ++k)
  {
    jobs[k].scene = &scene;
    jobs[k].options = options;
    jobs[k].coefficients = coefficients;
    jobs[k].first = (size_t)k;
    jobs[k].step = (size_t)threads;
    jobs[k].report_progress = k == 0; /* job 0 runs on the calling thread */
  }
  ran = rf_run_jobs(jobs, sizeof(rf_sh_job), threads, rf_sh_job_run);
  free(jobs);
  rf_sh_scene_release(&scene);
  return ran ? RF_OK : RF_REF_ERR_OUT_OF_MEMORY;
}

rf_status rf_sh_transfer_path(const float* positions, const float* normals, size_t vertex_count,
  const unsigned* triangles, size_t triangle_count, double ior, int max_bounces, size_t vertex,
  const double view[3], double exit_direction[3], double* length)
{
  rf_sh_scene scene;
  rf_vec3 d;
  rf_status status;
  if (!view || !exit_direction || !length)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  if (vertex >= vertex_count || max_bounces < 0 || max_bounces > 64)
  {
    return RF_REF_ERR_BAD_OPTION;
  }
  status = rf_sh_scene_build(&scene, positions, normals, vertex_count, triangles,
    triangle_count, ior);
  if (status == RF_OK)
  {
    rf_sh_path(&scene, vertex, rf_vec3_normalize(rf_vec3_make(view[0], view[1], view[2])),
      max_bounces, &d, length);
    exit_direction[0] = d.x;
    exit_direction[1] = d.y;
    exit_direction[2] = d.z;
  }
  rf_sh_scene_release(&scene);
  return status;
}
