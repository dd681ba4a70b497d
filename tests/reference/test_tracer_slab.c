/* The reference tracer against the closed forms of a thick slab seen obliquely through a
 * parallel projection (every pixel has the same incident angle):
 *  - the transmitted ray is parallel to the incident one, shifted sideways by
 *    d = t sin(theta_i - theta_t) / cos(theta_t), after a path t / cos(theta_t) inside;
 *  - two-interface colour: R env(reflection) + (1 - R) env(view direction);
 *  - full mode: the sum of all internal reflections (a geometric series),
 *    reflected 2R / (1 + R), transmitted (1 - R) / (1 + R); with absorption (one pass
 *    transmits tau = exp(-a t / cos(theta_t))): R + R (1-R)^2 tau^2 / (1 - R^2 tau^2) and
 *    (1-R)^2 tau / (1 - R^2 tau^2).
 * R is the Fresnel reflectance at theta_i (the same at the exit, by Stokes' relations).
 * The environment is red below the horizon (where the mirror direction goes) and green
 * elsewhere (the view direction), so each colour channel carries one of the two terms. */
#include "rf_reference_test.h"

#include "rf_test.h"

#include <stdio.h>
#include <stdlib.h>

#define WIDTH 64
#define HEIGHT 48
#define IOR 1.5
#define THICKNESS 1.0
#define SCALE 1.5 /* parallel scale: half the view's height */
#define NEAR_D 1.0
#define FAR_D 100.0

static void two_tone(const double d[3], double rgb[3], void* user)
{
  (void)user;
  rgb[0] = d[1] < -0.05 ? 1.0 : 0.0;
  rgb[1] = d[1] < -0.05 ? 0.0 : 1.0;
  rgb[2] = 0.0;
}

typedef struct slab_case
{
  double angle; /* tilt about x = incident angle */
  int normals;  /* per-vertex normals or geometric */
  rf_trace_mode mode;
  double absorption[2];
} slab_case;

static void run_case(const slab_case* sc)
{
  const double centre[3] = { 0.0, 0.0, -10.0 };
  const double half[3] = { 20.0, 20.0, 0.5 * THICKNESS };
  double rotation[9];
  rft_box_scene scene;
  const rf_trace_image* const image = &scene.image;
  const rf_vec3 view_dir = rf_vec3_make(0.0, 0.0, -1.0);
  rf_vec3 normal;
  rf_vec3 tangent;
  rf_vec3 t1;
  const double theta_i = sc->angle * RFT_DEG;
  const double theta_t = rft_snell(theta_i, 1.0, IOR);
  const double r = rft_fresnel(theta_i, 1.0, IOR);
  const double inside = THICKNESS / cos(theta_t);
  const double shift = THICKNESS * sin(theta_i - theta_t) / cos(theta_t);
  double tau[2];
  double expected_colour[2];
  /* length: the worst of the sideways shift's and the thickness's errors */
  rft_pixel_errors worst = { 0, 0, 0.0, 0.0, 0.0, 0.0 };
  int i;
  int j;
  int c;

  rft_rotation_x(theta_i, rotation);
  rft_box_scene_init(&scene, centre, half, rotation, IOR,
    rft_parallel_camera(0.0, SCALE, WIDTH, HEIGHT, NEAR_D, FAR_D));
  if (!sc->normals)
  {
    scene.glass.normals = NULL; /* geometric normals */
  }
  scene.glass.absorption[0] = sc->absorption[0];
  scene.glass.absorption[1] = sc->absorption[1];
  scene.options.mode = sc->mode;
  scene.options.environment = two_tone;
  CHECK(rft_box_scene_trace(&scene) == RF_OK);

  /* The front face's outward normal R (0, 0, 1), and the refracted ray in the plane of
   * incidence: sin(theta_t) along the surface, cos(theta_t) into it. */
  normal = rf_vec3_make(rotation[2], rotation[5], rotation[8]);
  tangent = rf_vec3_normalize(
    rf_vec3_sub(view_dir, rf_vec3_scale(normal, rf_vec3_dot(view_dir, normal))));
  t1 = rf_vec3_add(rf_vec3_scale(tangent, sin(theta_t)), rf_vec3_scale(normal, -cos(theta_t)));
  for (c = 0; c < 2; ++c)
  {
    tau[c] = exp(-sc->absorption[c] * inside);
  }
  if (sc->mode == RF_TRACE_FULL)
  {
    expected_colour[0] = r + r * (1.0 - r) * (1.0 - r) * tau[0] * tau[0] /
      (1.0 - r * r * tau[0] * tau[0]);
    expected_colour[1] = (1.0 - r) * (1.0 - r) * tau[1] / (1.0 - r * r * tau[1] * tau[1]);
  }
  else
  {
    expected_colour[0] = r;
    expected_colour[1] = (1.0 - r) * tau[1];
  }

  for (j = 0; j < HEIGHT; ++j)
  {
    for (i = 0; i < WIDTH; ++i)
    {
      const size_t k = (size_t)j * WIDTH + i;
      /* The pixel's ray, from the pixel centre on the near plane along -z. */
      const rf_vec3 origin = rf_vec3_make(((i + 0.5) / WIDTH * 2.0 - 1.0) * SCALE * WIDTH / HEIGHT,
        ((j + 0.5) / HEIGHT * 2.0 - 1.0) * SCALE, -NEAR_D);
      const rf_vec3 front = rf_vec3_add(
        rf_vec3_make(centre[0], centre[1], centre[2]), rf_vec3_scale(normal, 0.5 * THICKNESS));
      const double t = rf_vec3_dot(rf_vec3_sub(front, origin), normal) /
        rf_vec3_dot(view_dir, normal);
      const rf_vec3 p1 = rf_vec3_add(origin, rf_vec3_scale(view_dir, t));
      const rf_vec3 p2 = rf_vec3_add(p1, rf_vec3_scale(t1, inside));
      const rf_vec3 got_p1 = rft_load(image->p1, k);
      const rf_vec3 got_p2 = rft_load(image->p2, k);
      const rf_vec3 got_t2 = rft_load(image->t2, k);
      const rf_vec3 offset = rf_vec3_sub(got_p2, got_p1);
      const double got_shift = rf_vec3_length(rf_vec3_cross(offset, view_dir));
      CHECK(image->hit[k] == 1);
      CHECK(image->bounces[k] == 2);
      CHECK(image->tir[k] == 0);
      worst.position =
        fmax(worst.position, fmax(rft_distance(got_p1, p1), rft_distance(got_p2, p2)));
      worst.angle = fmax(worst.angle, rft_angle_deg(got_t2, view_dir));
      worst.length = fmax(worst.length, fabs(got_shift - shift));
      worst.length = fmax(worst.length, fabs(image->thickness[k] - inside));
      for (c = 0; c < 2; ++c)
      {
        worst.colour = fmax(worst.colour, fabs(image->colour[3 * k + c] - expected_colour[c]));
      }
      worst.colour = fmax(worst.colour, fabs(image->colour[3 * k + 2]));
      ++worst.checked;
    }
  }
  printf("slab %4.1f deg, %s normals, %s, absorption (%.2f, %.2f): %d px, shift %.6f "
         "(theta_t %.3f deg, R %.5f): |P error| max %.2e, T2 angle max %.2e deg, "
         "|shift/thickness error| max %.2e, |colour error| max %.2e\n",
    sc->angle, sc->normals ? "vertex" : "geometric",
    sc->mode == RF_TRACE_FULL ? "full" : "two-interface", sc->absorption[0], sc->absorption[1],
    worst.checked, shift, theta_t / RFT_DEG, r, worst.position, worst.angle, worst.length,
    worst.colour);
  /* Float storage of coordinates near 10 (about 1e-6) bounds the geometry (measured: 4e-6
   * at most); the full mode's colour differs by the paths ended below RF_TRACE_MIN_WEIGHT
   * (measured: 7e-6 at most), the two-interface colour only by rounding (4e-7). */
  CHECK(worst.checked == WIDTH * HEIGHT);
  CHECK(worst.position < 2e-5);
  CHECK(worst.angle < 1e-3);
  CHECK(worst.length < 2e-5);
  CHECK(worst.colour < (sc->mode == RF_TRACE_FULL ? 5e-5 : 5e-6));
  rf_trace_image_free(&scene.image);
}

int main(void)
{
  const double angles[3] = { 20.0, 45.0, 70.0 };
  int a;
  for (a = 0; a < 3; ++a)
  {
    slab_case sc;
    sc.angle = angles[a];
    sc.absorption[0] = 0.0;
    sc.absorption[1] = 0.0;
    sc.normals = 1;
    sc.mode = RF_TRACE_TWO_INTERFACE;
    run_case(&sc);
    sc.mode = RF_TRACE_FULL;
    run_case(&sc);
    sc.normals = 0;
    run_case(&sc);
    sc.absorption[0] = 0.3;
    sc.absorption[1] = 0.7;
    run_case(&sc);
    sc.mode = RF_TRACE_TWO_INTERFACE;
    run_case(&sc);
  }
  return RF_TEST_SUMMARY();
}
