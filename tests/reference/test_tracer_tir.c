/* Total internal reflection in a glass cube (n = 1.5), against the closed form.
 *
 * The cube [-1, 1]^3 is seen through a parallel projection along d = (sin ti, 0, -cos ti):
 * rays enter the face z = +1 at theta_i and travel inside along
 * T1 = (sin tt, 0, -cos tt), sin tt = sin ti / 1.5. Where T1 meets the side face x = +1
 * its angle of incidence there is 90 - tt degrees, beyond the critical angle
 * asin(1 / 1.5) = 41.8 degrees for any tt, so it is totally reflected to
 * (-sin tt, 0, -cos tt), reaches the back face z = -1 at tt and leaves along
 * (-sin ti, 0, -cos ti), after 2 / cos(tt) inside. Checked for pixels whose path stays
 * clear of the cube's edges:
 *  - full mode: TIR flagged, 3 interfaces, exit point and direction, length inside; with the
 *    Fresnel term off the colour is exactly env(exit direction), looked up in WORLD space;
 *  - two-interface mode: the exit is the side face; TIR_REFLECT gives the mirror direction,
 *    TIR_CLAMP the grazing direction (0, 0, -1) (the paper's clamp). */
#include "rf_reference_test.h"

#include "rf_test.h"

#include <stdio.h>

#define WIDTH 64
#define HEIGHT 48
#define IOR 1.5
#define SCALE 1.6
#define NEAR_D 1.0
#define FAR_D 30.0
#define MARGIN 0.02

/* Encodes the world direction as a colour, so the colour tells where the ray went. */
static void direction_colour(const double d[3], double rgb[3], void* user)
{
  const double length = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  int c;
  (void)user;
  for (c = 0; c < 3; ++c)
  {
    rgb[c] = 0.5 * (d[c] / length + 1.0);
  }
}

typedef struct tir_case
{
  double angle;
  rf_trace_mode mode;
  int tir_clamp;
  int normals;
} tir_case;

static void run_case(const tir_case* tc)
{
  const double centre[3] = { 0.0, 0.0, 0.0 };
  const double half[3] = { 1.0, 1.0, 1.0 };
  const double ti = tc->angle * RFT_DEG;
  const double tt = rft_snell(ti, 1.0, IOR);
  const rf_vec3 d = rf_vec3_make(sin(ti), 0.0, -cos(ti));
  const rf_vec3 up = rf_vec3_make(0.0, 1.0, 0.0);
  const rf_vec3 eye = rf_vec3_scale(d, -10.0);
  const rf_vec3 right = rf_vec3_normalize(rf_vec3_cross(d, up));
  const rf_vec3 t1 = rf_vec3_make(sin(tt), 0.0, -cos(tt));
  const rf_vec3 t1_mirrored = rf_vec3_make(-sin(tt), 0.0, -cos(tt));
  const rf_vec3 grazing = rf_vec3_make(0.0, 0.0, -1.0);
  const rf_vec3 leaving = rf_vec3_make(-sin(ti), 0.0, -cos(ti));
  rft_box_scene scene;
  const rf_trace_image* const image = &scene.image;
  const double* const view = scene.camera.view;
  rft_pixel_errors worst = { 0, 0, 0.0, 0.0, 0.0, 0.0 };
  int i;
  int j;

  rft_box_scene_init(&scene, centre, half, NULL, IOR,
    rft_parallel_camera(0.0, SCALE, WIDTH, HEIGHT, NEAR_D, FAR_D));
  rft_look_along(eye, d, up, scene.camera.view); /* the eye is on -d, not on +z */
  if (!tc->normals)
  {
    scene.glass.normals = NULL; /* geometric normals */
  }
  scene.options.mode = tc->mode;
  scene.options.tir_clamp = tc->tir_clamp;
  scene.options.fresnel = 0;
  scene.options.environment = direction_colour;
  CHECK(rft_box_scene_trace(&scene) == RF_OK);

  for (j = 0; j < HEIGHT; ++j)
  {
    for (i = 0; i < WIDTH; ++i)
    {
      const size_t k = (size_t)j * WIDTH + i;
      const double x = ((i + 0.5) / WIDTH * 2.0 - 1.0) * SCALE * WIDTH / HEIGHT;
      const double y = ((j + 0.5) / HEIGHT * 2.0 - 1.0) * SCALE;
      const rf_vec3 origin = rf_vec3_add(eye, rf_vec3_add(rf_vec3_scale(right, x),
        rf_vec3_add(rf_vec3_scale(up, y), rf_vec3_scale(d, NEAR_D))));
      const rf_vec3 p1 = rf_vec3_add(origin, rf_vec3_scale(d, (1.0 - origin.z) / d.z));
      const rf_vec3 pa = rf_vec3_add(p1, rf_vec3_scale(t1, (1.0 - p1.x) / t1.x));
      const rf_vec3 pb = rf_vec3_add(pa, rf_vec3_scale(t1_mirrored, (pa.z + 1.0) / cos(tt)));
      rf_vec3 p2;
      rf_vec3 t2;
      double length;
      int bounces;
      if (fabs(p1.x) > 1.0 - MARGIN || fabs(p1.y) > 1.0 - MARGIN || pa.z < -1.0 + MARGIN ||
        pb.x < -1.0 + MARGIN)
      {
        continue; /* not this path, or too close to an edge */
      }
      if (tc->mode == RF_TRACE_FULL)
      {
        p2 = pb;
        t2 = leaving;
        length = 2.0 / cos(tt);
        bounces = 3;
      }
      else
      {
        p2 = pa;
        t2 = tc->tir_clamp ? grazing : t1_mirrored;
        length = rft_distance(pa, p1);
        bounces = 2;
      }
      worst.flags_wrong +=
        !(image->hit[k] == 1 && image->tir[k] == 1 && image->bounces[k] == bounces);
      worst.position = fmax(worst.position,
        rft_distance(rft_load(image->p1, k), rft_to_view_point(view, p1)));
      worst.position = fmax(worst.position,
        rft_distance(rft_load(image->p2, k), rft_to_view_point(view, p2)));
      worst.angle =
        fmax(worst.angle, rft_angle_deg(rft_load(image->t2, k), rft_to_view_dir(view, t2)));
      worst.length = fmax(worst.length, fabs(image->thickness[k] - length));
      /* No Fresnel split: all light follows this path, into env(t2) in world space. */
      worst.colour = fmax(worst.colour, fabs(image->colour[3 * k + 0] - 0.5 * (t2.x + 1.0)));
      worst.colour = fmax(worst.colour, fabs(image->colour[3 * k + 1] - 0.5 * (t2.y + 1.0)));
      worst.colour = fmax(worst.colour, fabs(image->colour[3 * k + 2] - 0.5 * (t2.z + 1.0)));
      ++worst.checked;
    }
  }
  printf("cube TIR, theta_i %.0f deg (theta_t %.2f, incidence on the side %.2f > critical "
         "%.2f), %s%s, %s normals: %d px, flags wrong %d, |P error| max %.2e, T2 angle max "
         "%.2e deg, length error max %.2e, colour error max %.2e\n",
    tc->angle, tt / RFT_DEG, 90.0 - tt / RFT_DEG, asin(1.0 / IOR) / RFT_DEG,
    tc->mode == RF_TRACE_FULL ? "full" : "two-interface",
    tc->mode == RF_TRACE_FULL ? "" : (tc->tir_clamp ? " TIR_CLAMP" : " TIR_REFLECT"),
    tc->normals ? "vertex" : "geometric", worst.checked, worst.flags_wrong, worst.position,
    worst.angle, worst.length, worst.colour);
  CHECK(worst.checked > 150);
  CHECK(worst.flags_wrong == 0);
  CHECK(worst.position < 1e-5);
  CHECK(worst.angle < 1e-4);
  CHECK(worst.length < 1e-5);
  CHECK(worst.colour < 1e-6);
  rf_trace_image_free(&scene.image);
}

int main(void)
{
  const double angles[2] = { 30.0, 60.0 };
  int a;
  for (a = 0; a < 2; ++a)
  {
    tir_case tc;
    tc.angle = angles[a];
    tc.normals = a; /* one angle each way */
    tc.mode = RF_TRACE_FULL;
    tc.tir_clamp = 0;
    run_case(&tc);
    tc.mode = RF_TRACE_TWO_INTERFACE;
    run_case(&tc);
    tc.tir_clamp = 1;
    run_case(&tc);
  }
  return RF_TEST_SUMMARY();
}
