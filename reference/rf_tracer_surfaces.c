/* rf_tracer_surfaces.c: opaque surfaces and the environment (see rf_tracer_surfaces.h). */
#include "rf_tracer_surfaces.h"

#include "rf_environment.h"
#include "rf_tracer_rays.h"

#include <math.h>
#include <stddef.h>

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
void rf_opaque_colour(const rf_tracer* tr, const rf_hit* hit, double rgb[3])
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

void rf_environment(const rf_tracer* tr, rf_vec3 d, double rgb[3])
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

/* Shades an opaque surface met by the primary ray before tfar (where glass would start);
 * returns 1 when there is one. */
int rf_shade_primary_opaque(
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
void rf_behind(const rf_tracer* tr, rf_vec3 o, rf_vec3 d, double rgb[3])
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
