/* rf_tracer_full.c: the full mode, Whitted recursion (see rf_tracer_full.h). */
#include "rf_tracer_full.h"

#include "rf_optics.h"
#include "rf_tracer_rays.h"
#include "rf_tracer_surfaces.h"

#include <math.h>


/* Glass objects a ray can be inside at once (nested or overlapping meshes). */
#define RF_MEDIUM_STACK_SIZE 16

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

void rf_shade_full(const rf_tracer* tr, rf_vec3 origin, rf_vec3 view_dir, double tfar,
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
