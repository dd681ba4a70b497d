/* rf_tracer.c: the reference ray tracer on Embree 3 (see rf_tracer.h for the model). */
#include "rf_tracer.h"

#include "rf_environment.h"
#include "rf_jobs.h"
#include "rf_optics.h"
#include "rf_vec3.h"

#include <embree3/rtcore.h>

#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Glass objects a ray can be inside at once (nested or overlapping meshes). */
#define RF_MEDIUM_STACK_SIZE 16
/* Retries when a secondary ray finds the triangle it starts on again. */
#define RF_SELF_HIT_RETRIES 4
/* Largest image side: keeps width * height * 3 floats far from size_t overflow. */
#define RF_MAX_IMAGE_SIDE 65536

/* ------------------------------------------------------------------------------------------
 * 4x4 row-major matrices (the layout of vtkMatrix4x4::GetData()). */

/* Gauss-Jordan with partial pivoting; returns 0 for a singular matrix. */
static int rf_mat4_invert(const double m[16], double inverse[16])
{
  double a[4][8];
  int r;
  int c;
  int k;
  for (r = 0; r < 4; ++r)
  {
    for (c = 0; c < 4; ++c)
    {
      a[r][c] = m[r * 4 + c];
      a[r][c + 4] = (r == c) ? 1.0 : 0.0;
    }
  }
  for (k = 0; k < 4; ++k)
  {
    int pivot = k;
    double scale;
    for (r = k + 1; r < 4; ++r)
    {
      if (fabs(a[r][k]) > fabs(a[pivot][k]))
      {
        pivot = r;
      }
    }
    if (!(fabs(a[pivot][k]) > 0.0))
    {
      return 0;
    }
    if (pivot != k)
    {
      for (c = 0; c < 8; ++c)
      {
        const double t = a[k][c];
        a[k][c] = a[pivot][c];
        a[pivot][c] = t;
      }
    }
    scale = 1.0 / a[k][k];
    for (c = 0; c < 8; ++c)
    {
      a[k][c] *= scale;
    }
    for (r = 0; r < 4; ++r)
    {
      if (r != k && a[r][k] != 0.0)
      {
        const double f = a[r][k];
        for (c = 0; c < 8; ++c)
        {
          a[r][c] -= f * a[k][c];
        }
      }
    }
  }
  for (r = 0; r < 4; ++r)
  {
    for (c = 0; c < 4; ++c)
    {
      inverse[r * 4 + c] = a[r][c + 4];
      if (!isfinite(inverse[r * 4 + c]))
      {
        return 0;
      }
    }
  }
  return 1;
}

/* m * (x, y, z, w) followed by the homogeneous divide. */
static rf_vec3 rf_mat4_project(const double m[16], double x, double y, double z, double w)
{
  const double h[4] = { x, y, z, w };
  double o[4];
  int r;
  for (r = 0; r < 4; ++r)
  {
    o[r] = m[r * 4 + 0] * h[0] + m[r * 4 + 1] * h[1] + m[r * 4 + 2] * h[2] + m[r * 4 + 3] * h[3];
  }
  return rf_vec3_make(o[0] / o[3], o[1] / o[3], o[2] / o[3]);
}

static rf_vec3 rf_mat4_point(const double m[16], rf_vec3 p)
{
  return rf_mat4_project(m, p.x, p.y, p.z, 1.0);
}

/* The linear part applied to a direction, renormalized (a view transform is rigid; the
 * renormalization only removes rounding). */
static rf_vec3 rf_mat4_direction(const double m[16], rf_vec3 d)
{
  return rf_vec3_normalize(rf_vec3_make(m[0] * d.x + m[1] * d.y + m[2] * d.z,
    m[4] * d.x + m[5] * d.y + m[6] * d.z, m[8] * d.x + m[9] * d.y + m[10] * d.z));
}

/* ------------------------------------------------------------------------------------------
 * Scene: Embree objects plus what shading needs; read-only while the threads trace. */

typedef struct rf_tracer
{
  RTCDevice device;
  RTCScene scene;        /* the glass; geometry k is meshes[k] */
  RTCScene opaque_scene; /* the opaque surfaces (NULL when there are none); geometry k is
                            opaque[k] */
  const rf_mesh* meshes;
  size_t mesh_count;
  const rf_opaque_mesh* opaque;
  size_t opaque_count;
  const rf_trace_options* options;
  double epsilon; /* ray offset for secondary rays, scaled with the scene */
  double clip_to_view[16];
  double view_to_world[16];
  double world_to_view[16];
  int parallel;          /* parallel projection: the viewer is along +z of the view */
  rf_vec3 eye_world;     /* perspective: the camera position */
  rf_vec3 view_z_world;  /* the view axis toward the viewer, in WORLD space */
  rf_trace_image* out;
} rf_tracer;

typedef struct rf_hit
{
  unsigned geom;
  unsigned prim;
  double t;
  double u;
  double v;
  rf_vec3 point;
} rf_hit;

static void rf_embree_error(void* user, enum RTCError code, const char* message)
{
  (void)user;
  fprintf(stderr, "rf_tracer: Embree error %d: %s\n", (int)code, message ? message : "");
}

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
static int rf_intersect(const rf_tracer* tr, rf_vec3 o, rf_vec3 d, double tnear, double tfar,
  unsigned skip_geom, unsigned skip_prim, rf_hit* hit)
{
  return rf_intersect_in(tr->scene, o, d, tnear, tfar, skip_geom, skip_prim, hit);
}

/* The nearest opaque surface (none when the scene has no opaque mesh). */
static int rf_intersect_opaque(
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
static rf_vec3 rf_winding_normal(const float* positions, const unsigned* tri)
{
  const rf_vec3 p0 = rf_mesh_vector(positions, tri[0]);
  const rf_vec3 p1 = rf_mesh_vector(positions, tri[1]);
  const rf_vec3 p2 = rf_mesh_vector(positions, tri[2]);
  return rf_vec3_normalize(rf_vec3_cross(rf_vec3_sub(p1, p0), rf_vec3_sub(p2, p0)));
}

static rf_vec3 rf_surface_normal(
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

static rf_vec3 rf_shading_normal(const rf_tracer* tr, const rf_hit* hit)
{
  const rf_mesh* mesh = &tr->meshes[hit->geom];
  return rf_surface_normal(mesh->positions, mesh->normals, mesh->triangles, hit);
}

/* ------------------------------------------------------------------------------------------
 * Opaque surfaces: coloured as VTK draws them (rf_opaque_material). */

void rf_opaque_shade(const rf_opaque_material* material, const double* base_colour,
  double normal_view_z, double rgb[3])
{
  const double* ambient = base_colour != NULL ? base_colour : material->ambient_colour;
  const double* diffuse = base_colour != NULL ? base_colour : material->diffuse_colour;
  const double facing = fmax(normal_view_z, 0.0);
  const double shine = material->specular > 0.0 ? pow(facing, material->specular_power) : 0.0;
  int c;
  for (c = 0; c < 3; ++c)
  {
    double value = material->ambient * ambient[c];
    if (material->lighting)
    {
      value += material->diffuse * diffuse[c] * facing +
        material->specular * material->specular_colour[c] * shine;
    }
    else
    {
      value += material->diffuse * diffuse[c];
    }
    rgb[c] = fmin(fmax(value, 0.0), 1.0);
  }
}

/* The scalar colour at a hit: interpolated per vertex, flat per triangle. */
static void rf_opaque_base_colour(const rf_opaque_mesh* mesh, const rf_hit* hit, double rgb[3])
{
  const unsigned* tri = mesh->triangles + 3 * (size_t)hit->prim;
  int c;
  for (c = 0; c < 3; ++c)
  {
    if (mesh->colour_binding == RF_COLOUR_PER_TRIANGLE)
    {
      rgb[c] = mesh->colours[3 * (size_t)hit->prim + c];
    }
    else
    {
      rgb[c] = (1.0 - hit->u - hit->v) * mesh->colours[3 * (size_t)tri[0] + c] +
        hit->u * mesh->colours[3 * (size_t)tri[1] + c] +
        hit->v * mesh->colours[3 * (size_t)tri[2] + c];
    }
  }
}

/* The colour the camera sees at an opaque hit, whichever ray found it: the pass shows what
 * it captured from the camera. VTK flips the normal on back faces (the triangle's winding
 * turns away from the camera) and lights along the view axis. */
static void rf_opaque_colour(const rf_tracer* tr, const rf_hit* hit, double rgb[3])
{
  const rf_opaque_mesh* mesh = &tr->opaque[hit->geom];
  const rf_vec3 toward_viewer =
    tr->parallel ? tr->view_z_world : rf_vec3_sub(tr->eye_world, hit->point);
  const rf_vec3 winding = rf_winding_normal(mesh->positions, mesh->triangles + 3 * (size_t)hit->prim);
  rf_vec3 normal = rf_surface_normal(mesh->positions, mesh->normals, mesh->triangles, hit);
  double base[3];
  if (rf_vec3_dot(winding, toward_viewer) < 0.0)
  {
    normal = rf_vec3_scale(normal, -1.0);
  }
  if (mesh->colour_binding != RF_COLOUR_MATERIAL)
  {
    rf_opaque_base_colour(mesh, hit, base);
  }
  rf_opaque_shade(&mesh->material, mesh->colour_binding != RF_COLOUR_MATERIAL ? base : NULL,
    rf_vec3_dot(normal, tr->view_z_world), rgb);
}

static void rf_environment(const rf_tracer* tr, rf_vec3 d, double rgb[3])
{
  const double w[3] = { d.x, d.y, d.z };
  if (tr->options->environment != NULL)
  {
    tr->options->environment(w, rgb, tr->options->environment_user);
  }
  else
  {
    rf_builtin_environment(w, rgb);
  }
}

/* Refraction with a TIR policy; returns 1 under TIR. An invalid interface (a degenerate
 * normal, which rf_shading_normal already avoids) lets the ray pass unbent. */
static int rf_refract_policy(rf_vec3 incident, rf_vec3 normal, double eta, int clamp,
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

/* ------------------------------------------------------------------------------------------
 * Per-pixel results before they are written to the image. */

typedef struct rf_pixel
{
  int hit;
  int opaque;
  double colour[3];
  rf_vec3 p1;
  rf_vec3 p2;
  rf_vec3 t2;
  double thickness;
  int bounces;
  int tir;
} rf_pixel;

/* Shades an opaque surface met by the primary ray before tfar (where glass would start);
 * returns 1 when there is one. */
static int rf_shade_primary_opaque(
  const rf_tracer* tr, rf_vec3 origin, rf_vec3 view_dir, double tfar, rf_pixel* px)
{
  rf_hit h;
  if (!rf_intersect_opaque(tr, origin, view_dir, 0.0, tfar, &h))
  {
    return 0;
  }
  px->opaque = 1;
  rf_opaque_colour(tr, &h, px->colour);
  return 1;
}

/* What a ray leaving the glass at o along d shows in the two-interface model: the first
 * opaque surface (the pass's captured scene), else the environment. */
static void rf_behind(const rf_tracer* tr, rf_vec3 o, rf_vec3 d, double rgb[3])
{
  rf_hit h;
  if (rf_intersect_opaque(tr, o, d, tr->epsilon, INFINITY, &h))
  {
    rf_opaque_colour(tr, &h, rgb);
  }
  else
  {
    rf_environment(tr, d, rgb);
  }
}

/* The GPU's formula (rfRefractionFS.glsl) with the true exit point. */
static void rf_shade_two_interface(const rf_tracer* tr, rf_vec3 origin, rf_vec3 view_dir,
  double tfar, rf_pixel* px)
{
  rf_hit h1;
  rf_hit h2;
  const rf_mesh* mesh;
  rf_vec3 n1;
  rf_vec3 t1;
  rf_vec3 reflected;
  double eta;
  double fresnel;
  double env_r[3];
  double env_t[3];
  int c;
  const int clamp = tr->options->tir_clamp != 0;
  if (!rf_intersect(tr, origin, view_dir, 0.0, tfar, RTC_INVALID_GEOMETRY_ID,
        RTC_INVALID_GEOMETRY_ID, &h1))
  {
    rf_shade_primary_opaque(tr, origin, view_dir, tfar, px);
    return;
  }
  if (rf_shade_primary_opaque(tr, origin, view_dir, h1.t, px))
  {
    return;
  }
  mesh = &tr->meshes[h1.geom];
  px->hit = 1;
  px->p1 = h1.point;
  n1 = rf_shading_normal(tr, &h1);
  if (rf_vec3_dot(n1, view_dir) > 0.0)
  {
    n1 = rf_vec3_scale(n1, -1.0); /* facing the viewer, as rfN1 */
  }
  eta = 1.0 / mesh->ior;
  fresnel = tr->options->fresnel ? rf_fresnel_dielectric(-rf_vec3_dot(view_dir, n1), eta) : 0.0;
  reflected = rf_reflect(view_dir, n1);
  rf_refract_policy(view_dir, n1, eta, clamp, &t1);
  px->t2 = t1;
  px->p2 = h1.point;
  px->bounces = 1;
  if (rf_intersect(tr, h1.point, t1, tr->epsilon, INFINITY, h1.geom, h1.prim, &h2))
  {
    /* refract(T1, -N2, ior): leaving the glass; the normal is oriented against T1 inside. */
    px->tir = rf_refract_policy(t1, rf_shading_normal(tr, &h2), mesh->ior, clamp, &px->t2);
    px->p2 = h2.point;
    px->bounces = 2;
  }
  px->thickness = rf_vec3_length(rf_vec3_sub(px->p2, px->p1));
  rf_behind(tr, h1.point, reflected, env_r);
  rf_behind(tr, px->p2, px->t2, env_t);
  for (c = 0; c < 3; ++c)
  {
    const double absorbed = exp(-mesh->absorption[c] * px->thickness);
    px->colour[c] = fresnel * env_r[c] + (1.0 - fresnel) * absorbed * env_t[c];
  }
}

/* ------------------------------------------------------------------------------------------
 * Full mode: Whitted recursion. */

typedef struct rf_media
{
  int count;
  unsigned mesh[RF_MEDIUM_STACK_SIZE]; /* the glass the ray is inside, innermost last */
} rf_media;

/* The dominant path's record (see rf_trace_image). */
typedef struct rf_path
{
  int bounces;
  int tir;
  double inside_length;
  rf_vec3 exit_point;
  rf_vec3 direction;
} rf_path;

static double rf_media_ior(const rf_tracer* tr, const rf_media* media)
{
  return media->count > 0 ? tr->meshes[media->mesh[media->count - 1]].ior : 1.0;
}

static void rf_interface(const rf_tracer* tr, const rf_hit* hit, rf_vec3 d,
  const rf_media* media, int depth, double weight, rf_path* path, double rgb[3]);

/* Radiance arriving at a point along -d from a ray leaving it along d, after `depth`
 * interfaces. */
static void rf_radiance(const rf_tracer* tr, rf_vec3 o, rf_vec3 d, const rf_hit* from,
  const rf_media* media, int depth, double weight, rf_path* path, double rgb[3])
{
  rf_hit hit;
  rf_hit wall;
  const double* absorption =
    media->count > 0 ? tr->meshes[media->mesh[media->count - 1]].absorption : NULL;
  double attenuation[3] = { 1.0, 1.0, 1.0 };
  double strongest = 0.0;
  int glass;
  int c;
  if (path != NULL)
  {
    path->direction = d;
  }
  if (depth >= tr->options->max_depth || weight < RF_TRACE_MIN_WEIGHT)
  {
    /* The path ends: straight on into the scene around the glass. */
    rf_behind(tr, o, d, rgb);
    return;
  }
  glass = rf_intersect(tr, o, d, tr->epsilon, INFINITY, from->geom, from->prim, &hit);
  if (rf_intersect_opaque(tr, o, d, tr->epsilon, glass ? hit.t : INFINITY, &wall))
  {
    rf_opaque_colour(tr, &wall, rgb);
    for (c = 0; c < 3; ++c)
    {
      rgb[c] *= absorption != NULL ? exp(-absorption[c] * wall.t) : 1.0;
    }
    if (path != NULL && absorption != NULL)
    {
      path->inside_length += wall.t;
    }
    return;
  }
  if (!glass)
  {
    rf_environment(tr, d, rgb);
    if (absorption != NULL)
    {
      /* Inside an open mesh the light travels an unbounded distance through glass. */
      for (c = 0; c < 3; ++c)
      {
        rgb[c] = absorption[c] > 0.0 ? 0.0 : rgb[c];
      }
    }
    return;
  }
  if (absorption != NULL)
  {
    for (c = 0; c < 3; ++c)
    {
      attenuation[c] = exp(-absorption[c] * hit.t); /* Beer-Lambert */
    }
    if (path != NULL)
    {
      path->inside_length += hit.t;
    }
  }
  for (c = 0; c < 3; ++c)
  {
    strongest = fmax(strongest, attenuation[c]);
  }
  rf_interface(tr, &hit, d, media, depth, weight * strongest, path, rgb);
  for (c = 0; c < 3; ++c)
  {
    rgb[c] *= attenuation[c];
  }
}

/* One interface: Fresnel split into reflection and transmission (rf_fresnel_dielectric),
 * TIR reflects everything. The medium beyond is found from the stack of glass the ray is
 * in: hitting a mesh it is inside leaves that mesh, any other mesh is entered. */
static void rf_interface(const rf_tracer* tr, const rf_hit* hit, rf_vec3 d,
  const rf_media* media, int depth, double weight, rf_path* path, double rgb[3])
{
  rf_media beyond = *media;
  rf_vec3 normal;
  rf_vec3 transmitted;
  double eta;
  double fresnel;
  int tir;
  int inside = -1;
  int i;
  int c;
  int transmit_dominant;
  for (i = 0; i < media->count; ++i)
  {
    if (media->mesh[i] == hit->geom)
    {
      inside = i;
    }
  }
  if (inside >= 0)
  {
    for (i = inside; i + 1 < beyond.count; ++i)
    {
      beyond.mesh[i] = beyond.mesh[i + 1];
    }
    --beyond.count;
  }
  else if (beyond.count < RF_MEDIUM_STACK_SIZE)
  {
    beyond.mesh[beyond.count++] = hit->geom;
  }
  eta = rf_media_ior(tr, media) / rf_media_ior(tr, &beyond);
  normal = rf_shading_normal(tr, hit);
  if (rf_vec3_dot(normal, d) > 0.0)
  {
    normal = rf_vec3_scale(normal, -1.0);
  }
  tir = rf_refract_policy(d, normal, eta, 0, &transmitted);
  fresnel = tir ? 1.0
                : (tr->options->fresnel ? rf_fresnel_dielectric(-rf_vec3_dot(d, normal), eta)
                                        : 0.0);
  transmit_dominant = fresnel < 1.0;
  if (path != NULL)
  {
    path->bounces += 1;
    path->tir = path->tir || tir;
    if (transmit_dominant && beyond.count == 0)
    {
      path->exit_point = hit->point;
    }
  }
  for (c = 0; c < 3; ++c)
  {
    rgb[c] = 0.0;
  }
  if (fresnel < 1.0)
  {
    double t_rgb[3];
    rf_radiance(tr, hit->point, transmitted, hit, &beyond, depth + 1, weight * (1.0 - fresnel),
      transmit_dominant ? path : NULL, t_rgb);
    for (c = 0; c < 3; ++c)
    {
      rgb[c] += (1.0 - fresnel) * t_rgb[c];
    }
  }
  if (fresnel > 0.0)
  {
    double r_rgb[3];
    rf_radiance(tr, hit->point, rf_reflect(d, normal), hit, media, depth + 1, weight * fresnel,
      transmit_dominant ? NULL : path, r_rgb);
    for (c = 0; c < 3; ++c)
    {
      rgb[c] += fresnel * r_rgb[c];
    }
  }
}

static void rf_shade_full(const rf_tracer* tr, rf_vec3 origin, rf_vec3 view_dir, double tfar,
  rf_pixel* px)
{
  rf_hit h1;
  rf_media air;
  rf_path path;
  if (!rf_intersect(tr, origin, view_dir, 0.0, tfar, RTC_INVALID_GEOMETRY_ID,
        RTC_INVALID_GEOMETRY_ID, &h1))
  {
    rf_shade_primary_opaque(tr, origin, view_dir, tfar, px);
    return;
  }
  if (rf_shade_primary_opaque(tr, origin, view_dir, h1.t, px))
  {
    return;
  }
  air.count = 0;
  path.bounces = 0;
  path.tir = 0;
  path.inside_length = 0.0;
  path.exit_point = h1.point;
  path.direction = view_dir;
  rf_interface(tr, &h1, view_dir, &air, 0, 1.0, &path, px->colour);
  px->hit = 1;
  px->p1 = h1.point;
  px->p2 = path.exit_point;
  px->t2 = path.direction;
  px->thickness = path.inside_length;
  px->bounces = path.bounces;
  px->tir = path.tir;
}

/* ------------------------------------------------------------------------------------------
 * Image loop. */

static void rf_store_vec3(float* array, size_t index, rf_vec3 v)
{
  if (array != NULL)
  {
    array[3 * index + 0] = (float)v.x;
    array[3 * index + 1] = (float)v.y;
    array[3 * index + 2] = (float)v.z;
  }
}

/* Shades the primary ray through NDC (x, y): from the near plane to the far plane. */
static void rf_trace_primary(const rf_tracer* tr, double x, double y, rf_pixel* px)
{
  const rf_vec3 near_view = rf_mat4_project(tr->clip_to_view, x, y, -1.0, 1.0);
  const rf_vec3 far_view = rf_mat4_project(tr->clip_to_view, x, y, 1.0, 1.0);
  const rf_vec3 near_world = rf_mat4_point(tr->view_to_world, near_view);
  const rf_vec3 far_world = rf_mat4_point(tr->view_to_world, far_view);
  const rf_vec3 span = rf_vec3_sub(far_world, near_world);
  const rf_vec3 dir = rf_vec3_normalize(span);
  memset(px, 0, sizeof(*px));
  if (rf_vec3_length(dir) > 0.0)
  {
    if (tr->options->mode == RF_TRACE_FULL)
    {
      rf_shade_full(tr, near_world, dir, rf_vec3_length(span), px);
    }
    else
    {
      rf_shade_two_interface(tr, near_world, dir, rf_vec3_length(span), px);
    }
  }
}

static void rf_trace_pixel(const rf_tracer* tr, int i, int j)
{
  rf_trace_image* out = tr->out;
  const size_t index = (size_t)j * (size_t)out->width + (size_t)i;
  const int n = tr->options->samples_per_side;
  rf_pixel px;
  double colour[3];
  double coverage;
  int c;
  /* OpenGL's pixel centres (rasterization samples at the centre). */
  rf_trace_primary(
    tr, (i + 0.5) / out->width * 2.0 - 1.0, (j + 0.5) / out->height * 2.0 - 1.0, &px);
  for (c = 0; c < 3; ++c)
  {
    colour[c] = px.colour[c];
  }
  coverage = px.hit ? 1.0 : 0.0;
  if (n > 1)
  {
    int a;
    int b;
    int hits = 0;
    for (c = 0; c < 3; ++c)
    {
      colour[c] = 0.0;
    }
    for (b = 0; b < n; ++b)
    {
      for (a = 0; a < n; ++a)
      {
        rf_pixel sample;
        rf_trace_primary(tr, (i + (a + 0.5) / n) / out->width * 2.0 - 1.0,
          (j + (b + 0.5) / n) / out->height * 2.0 - 1.0, &sample);
        hits += sample.hit;
        for (c = 0; c < 3; ++c)
        {
          colour[c] += sample.hit || sample.opaque ? sample.colour[c] : tr->options->background[c];
        }
      }
    }
    for (c = 0; c < 3; ++c)
    {
      colour[c] /= (double)(n * n);
    }
    coverage = (double)hits / (double)(n * n);
  }
  if (out->colour != NULL)
  {
    out->colour[3 * index + 0] = (float)colour[0];
    out->colour[3 * index + 1] = (float)colour[1];
    out->colour[3 * index + 2] = (float)colour[2];
  }
  if (out->coverage != NULL)
  {
    out->coverage[index] = (float)coverage;
  }
  if (px.hit)
  {
    rf_store_vec3(out->p1, index, rf_mat4_point(tr->world_to_view, px.p1));
    rf_store_vec3(out->p2, index, rf_mat4_point(tr->world_to_view, px.p2));
    rf_store_vec3(out->t2, index, rf_mat4_direction(tr->world_to_view, px.t2));
  }
  else
  {
    const rf_vec3 zero = rf_vec3_make(0.0, 0.0, 0.0);
    rf_store_vec3(out->p1, index, zero);
    rf_store_vec3(out->p2, index, zero);
    rf_store_vec3(out->t2, index, zero);
  }
  if (out->thickness != NULL)
  {
    out->thickness[index] = (float)px.thickness;
  }
  if (out->bounces != NULL)
  {
    out->bounces[index] = px.bounces;
  }
  if (out->tir != NULL)
  {
    out->tir[index] = (unsigned char)(px.tir ? 1 : 0);
  }
  if (out->hit != NULL)
  {
    out->hit[index] = (unsigned char)(px.hit ? 1 : 0);
  }
  if (out->opaque != NULL)
  {
    out->opaque[index] = (unsigned char)(px.opaque ? 1 : 0);
  }
}

typedef struct rf_worker
{
  const rf_tracer* tracer;
  int first_row;
  int row_step;
  int report_progress; /* the worker on the calling thread */
} rf_worker;

/* Rows are interleaved over the workers so that each gets a similar share of the object. */
static void* rf_worker_run(void* arg)
{
  const rf_worker* w = (const rf_worker*)arg;
  const int width = w->tracer->out->width;
  const int height = w->tracer->out->height;
  int j;
  int i;
  for (j = w->first_row; j < height; j += w->row_step)
  {
    for (i = 0; i < width; ++i)
    {
      rf_trace_pixel(w->tracer, i, j);
    }
    /* Rows are interleaved, so the calling thread's share of rows stands for all of them. */
    if (w->report_progress && w->tracer->options->progress != NULL)
    {
      w->tracer->options->progress(
        (double)(j + 1) / (double)height, w->tracer->options->progress_user);
    }
  }
  return NULL;
}

static rf_status rf_run_workers(const rf_tracer* tr, int threads)
{
  rf_worker* workers;
  int ran;
  int k;
  if (threads > tr->out->height)
  {
    threads = tr->out->height;
  }
  workers = (rf_worker*)calloc((size_t)threads, sizeof(rf_worker));
  if (workers == NULL)
  {
    return RF_REF_ERR_OUT_OF_MEMORY;
  }
  for (k = 0; k < threads; ++k)
  {
    workers[k].tracer = tr;
    workers[k].first_row = k;
    workers[k].row_step = threads;
    workers[k].report_progress = k == 0;
  }
  ran = rf_run_jobs(workers, sizeof(rf_worker), threads, rf_worker_run);
  free(workers);
  return ran ? RF_OK : RF_REF_ERR_OUT_OF_MEMORY;
}

/* ------------------------------------------------------------------------------------------
 * Validation and scene construction. */

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

static rf_status rf_validate_inputs(const rf_mesh* meshes, size_t mesh_count,
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

/* Secondary rays start this far along: well above float rounding at the scene's
 * coordinates (Embree intersects in float, about 6e-8 relative) and well below the
 * size of any feature a ray could meet. */
static double rf_scene_epsilon(const rf_mesh* meshes, size_t mesh_count)
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

static rf_status rf_build_scene(rf_tracer* tr)
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

static void rf_release_scene(rf_tracer* tr)
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

/* ------------------------------------------------------------------------------------------
 * Public API. */

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
