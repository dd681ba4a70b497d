/* The reference tracer's contract: rejected inputs and their status codes, an open mesh,
 * several meshes, and results independent of the number of threads. */
#include "rf_reference_test.h"

#include "rf_environment.h"

#include "rf_test.h"

#include <stdio.h>
#include <string.h>

#define WIDTH 40
#define HEIGHT 30

/* A camera on the +z axis at distance 5 looking at the origin, parallel projection. */
static rf_camera make_camera(void)
{
  return rft_parallel_camera(5.0, 1.5, WIDTH, HEIGHT, 0.5, 20.0);
}

static void test_rejected_inputs(void)
{
  const double centre[3] = { 0.0, 0.0, 0.0 };
  const double half[3] = { 1.0, 1.0, 1.0 };
  rft_box_scene scene;
  /* Short names for the scene's valid inputs, which each check below varies one at a time. */
  const rft_box* const box = &scene.box;
  const rf_mesh* const mesh = &scene.glass;
  const rf_camera* const camera = &scene.camera;
  const rf_trace_options* const options = &scene.options;
  rf_trace_image* const image = &scene.image;
  rft_box broken;
  unsigned bad_triangles[36];
  rf_mesh bad;
  rf_camera bad_camera;
  rf_trace_options bad_options;
  rf_trace_image small;
  /* Asserts that rf_trace_options_default and rf_trace_image_alloc succeed. */
  rft_box_scene_init(&scene, centre, half, NULL, 1.5, make_camera());
  CHECK(rf_trace_options_default(NULL) == RF_ERR_NULL_ARGUMENT);
  CHECK(rf_trace_image_alloc(&small, 0, 5) == RF_REF_ERR_BAD_OPTION);
  CHECK(small.colour == NULL && small.width == 0);
  CHECK(rf_trace_image_alloc(NULL, 4, 4) == RF_ERR_NULL_ARGUMENT);

  CHECK(rf_trace(mesh, 1, camera, options, image) == RF_OK);
  CHECK(rf_trace(NULL, 1, camera, options, image) == RF_ERR_NULL_ARGUMENT);
  CHECK(rf_trace(mesh, 1, NULL, options, image) == RF_ERR_NULL_ARGUMENT);
  CHECK(rf_trace(mesh, 1, camera, NULL, image) == RF_ERR_NULL_ARGUMENT);
  CHECK(rf_trace(mesh, 1, camera, options, NULL) == RF_ERR_NULL_ARGUMENT);

  /* Meshes. */
  broken = *box;
  broken.positions[7] = NAN;
  bad = rft_box_mesh(&broken, 1.5, 1);
  CHECK(rf_trace(&bad, 1, camera, options, image) == RF_ERR_NOT_FINITE);
  broken = *box;
  broken.normals[4] = INFINITY;
  bad = rft_box_mesh(&broken, 1.5, 1);
  CHECK(rf_trace(&bad, 1, camera, options, image) == RF_ERR_NOT_FINITE);
  memcpy(bad_triangles, box->triangles, sizeof(bad_triangles));
  bad_triangles[17] = 24;
  bad = *mesh;
  bad.triangles = bad_triangles;
  CHECK(rf_trace(&bad, 1, camera, options, image) == RF_REF_ERR_INDEX_OUT_OF_RANGE);
  bad = *mesh;
  bad.ior = 0.0;
  CHECK(rf_trace(&bad, 1, camera, options, image) == RF_ERR_IOR_NOT_POSITIVE);
  bad.ior = NAN;
  CHECK(rf_trace(&bad, 1, camera, options, image) == RF_ERR_NOT_FINITE);
  bad = *mesh;
  bad.absorption[2] = -0.1;
  CHECK(rf_trace(&bad, 1, camera, options, image) == RF_ERR_ABSORPTION_NEGATIVE);
  bad = *mesh;
  bad.positions = NULL;
  CHECK(rf_trace(&bad, 1, camera, options, image) == RF_ERR_NULL_ARGUMENT);

  /* Options and camera. */
  bad_options = *options;
  bad_options.max_depth = 0;
  CHECK(rf_trace(mesh, 1, camera, &bad_options, image) == RF_REF_ERR_BAD_OPTION);
  bad_options.max_depth = RF_TRACE_MAX_DEPTH_LIMIT + 1;
  CHECK(rf_trace(mesh, 1, camera, &bad_options, image) == RF_REF_ERR_BAD_OPTION);
  bad_options = *options;
  bad_options.threads = 0;
  CHECK(rf_trace(mesh, 1, camera, &bad_options, image) == RF_REF_ERR_BAD_OPTION);
  bad_options = *options;
  bad_options.mode = (rf_trace_mode)7;
  CHECK(rf_trace(mesh, 1, camera, &bad_options, image) == RF_REF_ERR_BAD_OPTION);
  bad_camera = *camera;
  bad_camera.width = WIDTH + 1; /* differs from the image */
  CHECK(rf_trace(mesh, 1, &bad_camera, options, image) == RF_REF_ERR_BAD_OPTION);
  bad_camera = *camera;
  memset(bad_camera.projection, 0, sizeof(bad_camera.projection));
  CHECK(rf_trace(mesh, 1, &bad_camera, options, image) == RF_REF_ERR_BAD_OPTION);
  bad_camera = *camera;
  bad_camera.view[3] = NAN;
  CHECK(rf_trace(mesh, 1, &bad_camera, options, image) == RF_ERR_NOT_FINITE);

  /* Messages exist for the extra codes and fall through to the core's for the others. */
  CHECK(strcmp(rf_reference_status_message(RF_REF_ERR_EMBREE), "unknown status") != 0);
  CHECK(strcmp(rf_reference_status_message(RF_REF_ERR_NO_SAMPLES), "unknown status") != 0);
  CHECK(strcmp(rf_reference_status_message(RF_OK), "success") == 0);

  /* No mesh at all: nothing is hit. */
  {
    size_t k;
    int hits = 0;
    CHECK(rf_trace(NULL, 0, camera, options, image) == RF_OK);
    for (k = 0; k < (size_t)WIDTH * HEIGHT; ++k)
    {
      hits += image->hit[k];
    }
    CHECK(hits == 0);
  }
  rf_trace_image_free(image);
  rf_trace_image_free(image); /* freeing twice is harmless */
  rf_trace_image_free(NULL);
}

/* One triangle tilted by 40 degrees about x: the refracted ray finds no exit, so the
 * two-interface mode reports T2 = T1, P2 = P1, thickness 0 and one interface. */
static void test_open_mesh(void)
{
  const double tilt = 40.0 * RFT_DEG;
  const float positions[9] = { -3.0f, (float)(-3.0 * cos(tilt)), (float)(-3.0 * sin(tilt)),
    3.0f, (float)(-3.0 * cos(tilt)), (float)(-3.0 * sin(tilt)), 0.0f, (float)(3.0 * cos(tilt)),
    (float)(3.0 * sin(tilt)) };
  const unsigned triangle[3] = { 0, 1, 2 };
  const double theta_t = rft_snell(tilt, 1.0, 1.5);
  rf_mesh mesh;
  rf_camera camera;
  rf_trace_options options;
  rf_trace_image image;
  const size_t centre = (size_t)(HEIGHT / 2) * WIDTH + WIDTH / 2;
  memset(&mesh, 0, sizeof(mesh));
  mesh.positions = positions;
  mesh.vertex_count = 3;
  mesh.triangles = triangle;
  mesh.triangle_count = 1;
  mesh.ior = 1.5;
  camera = make_camera();
  CHECK(rf_trace_options_default(&options) == RF_OK);
  CHECK(rf_trace_image_alloc(&image, WIDTH, HEIGHT) == RF_OK);
  CHECK(rf_trace(&mesh, 1, &camera, &options, &image) == RF_OK);
  CHECK(image.hit[centre] == 1);
  CHECK(image.bounces[centre] == 1);
  CHECK_NEAR(image.thickness[centre], 0.0, 0.0);
  CHECK_NEAR(rft_distance(rft_load(image.p1, centre), rft_load(image.p2, centre)), 0.0, 0.0);
  /* The view ray (0, 0, -1) meets the plane at 40 degrees; T1 is bent to theta_t from the
   * normal, i.e. by 40 - theta_t degrees from the view direction. */
  CHECK_NEAR(rft_angle_deg(rft_load(image.t2, centre), rf_vec3_make(0.0, 0.0, -1.0)),
    (tilt - theta_t) / RFT_DEG, 1e-4);
  /* Full mode: the transmitted ray leaves into the environment from inside the open glass
   * (clear, so unattenuated); the path has one interface. */
  options.mode = RF_TRACE_FULL;
  CHECK(rf_trace(&mesh, 1, &camera, &options, &image) == RF_OK);
  CHECK(image.hit[centre] == 1);
  CHECK(image.bounces[centre] == 1);
  CHECK(image.colour[3 * centre] > 0.0f);
  rf_trace_image_free(&image);
}

/* Two meshes (the first one empty, skipped) and two cubes one behind the other: the near
 * one is seen, and its index of refraction is the one used. */
static void test_several_meshes(void)
{
  const double near_centre[3] = { 0.0, 0.0, 1.0 };
  const double far_centre[3] = { 0.0, 0.0, -3.0 };
  const double half[3] = { 0.5, 0.5, 0.5 };
  rft_box near_box;
  rft_box far_box;
  rf_mesh meshes[3];
  rf_camera camera;
  rf_trace_options options;
  rf_trace_image image;
  const size_t centre = (size_t)(HEIGHT / 2) * WIDTH + WIDTH / 2;
  rft_make_box(&near_box, near_centre, half, NULL);
  rft_make_box(&far_box, far_centre, half, NULL);
  memset(&meshes[0], 0, sizeof(meshes[0]));
  meshes[0].ior = 1.0;
  meshes[1] = rft_box_mesh(&far_box, 1.2, 1);
  meshes[2] = rft_box_mesh(&near_box, 1.5, 1);
  camera = make_camera();
  CHECK(rf_trace_options_default(&options) == RF_OK);
  CHECK(rf_trace_image_alloc(&image, WIDTH, HEIGHT) == RF_OK);
  CHECK(rf_trace(meshes, 3, &camera, &options, &image) == RF_OK);
  /* Near face of the near cube: z = 1.5 in world, -3.5 in view; the exit is its back face. */
  CHECK(image.hit[centre] == 1);
  CHECK_NEAR(image.p1[3 * centre + 2], -3.5, 1e-6);
  CHECK_NEAR(image.p2[3 * centre + 2], -4.5, 1e-6);
  /* Normal incidence: the two-interface colour is R env(back) + (1 - R) env(forward) with
   * R = ((1.5 - 1) / (1.5 + 1))^2 = 0.04 of the near cube (the far one would give 0.0083). */
  {
    double forward[3];
    double back[3];
    const double dir_forward[3] = { 0.0, 0.0, -1.0 };
    const double dir_back[3] = { 0.0, 0.0, 1.0 };
    int c;
    rf_builtin_environment(dir_forward, forward);
    rf_builtin_environment(dir_back, back);
    for (c = 0; c < 3; ++c)
    {
      CHECK_NEAR(image.colour[3 * centre + c], 0.04 * back[c] + 0.96 * forward[c], 1e-6);
    }
  }
  rf_trace_image_free(&image);
}

/* Rows are split over threads: any number of threads gives the same bytes. */
static void test_threads(void)
{
  const double centre[3] = { 0.2, -0.1, 0.0 };
  const double half[3] = { 1.0, 0.7, 0.8 };
  double rotation[9];
  rft_box_scene scene;
  const rf_trace_image* const one = &scene.image;
  rf_trace_image three;
  const size_t n = (size_t)WIDTH * HEIGHT;
  rft_rotation_x(0.6, rotation);
  rft_box_scene_init(&scene, centre, half, rotation, 1.5, make_camera());
  scene.glass.normals = NULL; /* geometric normals */
  scene.options.mode = RF_TRACE_FULL;
  CHECK(rf_trace_image_alloc(&three, WIDTH, HEIGHT) == RF_OK);
  scene.options.threads = 1;
  CHECK(rft_box_scene_trace(&scene) == RF_OK);
  scene.options.threads = 3;
  CHECK(rf_trace(&scene.glass, 1, &scene.camera, &scene.options, &three) == RF_OK);
  CHECK(memcmp(one->colour, three.colour, 3 * n * sizeof(float)) == 0);
  CHECK(memcmp(one->t2, three.t2, 3 * n * sizeof(float)) == 0);
  CHECK(memcmp(one->hit, three.hit, n) == 0);
  rf_trace_image_free(&scene.image);
  rf_trace_image_free(&three);
}

int main(void)
{
  test_rejected_inputs();
  test_open_mesh();
  test_several_meshes();
  test_threads();
  return RF_TEST_SUMMARY();
}
