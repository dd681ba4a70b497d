/* rf_tracer_two_interface.c: the two-interface mode (see rf_tracer_two_interface.h). */
#include "rf_tracer_two_interface.h"

#include "rf_optics.h"
#include "rf_tracer_rays.h"
#include "rf_tracer_surfaces.h"

#include <math.h>

/* The GPU's formula (rfRefractionFS.glsl) with the true exit point. */
void rf_shade_two_interface(const rf_tracer* tr, rf_vec3 origin, rf_vec3 view_dir,
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
