/* The reference tracer with opaque surfaces around the glass (rf_trace_scene) and the
 * renderer's background as environment, against closed forms: VTK's headlight shading
 * (rf_opaque_shade), per-triangle and per-vertex colours, a plane seen directly and through
 * a glass box face-on (the ray crosses it unbent), the Fresnel blend, both modes, an opaque
 * surface in front of the glass, the background's gradient along directions, and rejected
 * opaque meshes. */
#include "rf_reference_test.h"

#include "rf_environment_map.h"

#include "rf_test.h"

#include <stdio.h>
#include <string.h>

#define WIDTH 40
#define HEIGHT 30

/* Parallel camera on +z at distance 5, half height 1.5, half width 2: pixel (i, j) sees
 * x = ((i + 0.5) / 20 - 1) * 2, y = ((j + 0.5) / 15 - 1) * 1.5. */
static rf_camera make_camera(void)
{
  return rft_parallel_camera(5.0, 1.5, WIDTH, HEIGHT, 0.5, 20.0);
}

/* The glass of these tests: a cube of side 1 and index 1.5 at the origin, which the camera
 * sees face-on in its middle. */
static void make_glass_scene(rft_box_scene* scene)
{
  const double centre[3] = { 0.0, 0.0, 0.0 };
  const double half[3] = { 0.5, 0.5, 0.5 };
  rft_box_scene_init(scene, centre, half, NULL, 1.5, make_camera());
}

/* rf_trace_scene of the glass scene with `opaque` around it, into the scene's image. */
static rf_status trace_with(rft_box_scene* scene, const rf_opaque_mesh* opaque,
  size_t opaque_count)
{
  return rf_trace_scene(&scene->glass, 1, opaque, opaque_count, &scene->camera, &scene->options,
    &scene->image);
}

static size_t pixel(int i, int j)
{
  return (size_t)j * WIDTH + (size_t)i;
}

/* Pixels: beside the glass below the plane's diagonal (x 1.05, y -0.95), beside it above
 * (x -1.05, y 0.95), and through the glass below the diagonal (x 0.25, y -0.15). */
#define BESIDE_LOWER pixel(30, 5)
#define BESIDE_UPPER pixel(9, 24)
#define THROUGH_LOWER pixel(22, 13)

static const double kEnvironment[3] = { 0.2, 0.4, 0.6 };

static void constant_environment(const double direction[3], double rgb[3], void* user)
{
  (void)direction;
  (void)user;
  memcpy(rgb, kEnvironment, sizeof(kEnvironment));
}

/* A square 6 x 6 in the plane z = depth facing +z, tilted about x by `tilt`; triangle 0 below
 * the diagonal y = x, triangle 1 above it; counter-clockwise seen from +z unless reversed. */
typedef struct plane
{
  float positions[12];
  float normals[12];
  unsigned triangles[6];
} plane;

static void make_plane(plane* p, double depth, double tilt, int reversed)
{
  const double corners[4][2] = { { -3.0, -3.0 }, { 3.0, -3.0 }, { 3.0, 3.0 }, { -3.0, 3.0 } };
  const unsigned forward[6] = { 0, 1, 2, 0, 2, 3 };
  const unsigned backward[6] = { 0, 2, 1, 0, 3, 2 };
  int k;
  for (k = 0; k < 4; ++k)
  {
    p->positions[3 * k + 0] = (float)corners[k][0];
    p->positions[3 * k + 1] = (float)(corners[k][1] * cos(tilt));
    p->positions[3 * k + 2] = (float)(depth + corners[k][1] * sin(tilt));
    p->normals[3 * k + 0] = 0.f;
    p->normals[3 * k + 1] = 0.f;
    p->normals[3 * k + 2] = 1.f;
  }
  memcpy(p->triangles, reversed ? backward : forward, sizeof(p->triangles));
}

static rf_opaque_material unlit(void)
{
  rf_opaque_material m;
  memset(&m, 0, sizeof(m));
  m.lighting = 0;
  m.diffuse = 1.0;
  m.specular_power = 1.0;
  return m;
}

/* An unlit opaque mesh of the plane made by make_plane; it points into *p, so reshaping the
 * plane with make_plane later moves the mesh too. */
static rf_opaque_mesh make_wall(plane* p, double depth, double tilt, int reversed)
{
  rf_opaque_mesh mesh;
  make_plane(p, depth, tilt, reversed);
  memset(&mesh, 0, sizeof(mesh));
  mesh.positions = p->positions;
  mesh.vertex_count = 4;
  mesh.triangles = p->triangles;
  mesh.triangle_count = 2;
  mesh.material = unlit();
  return mesh;
}

static void check_colour(const rf_trace_image* image, size_t index, const double rgb[3],
  double tolerance)
{
  int c;
  for (c = 0; c < 3; ++c)
  {
    CHECK_NEAR(image->colour[3 * index + c], rgb[c], tolerance);
  }
}

static void test_shade_formula(void)
{
  rf_opaque_material m = unlit();
  const double scalar[3] = { 0.5, 0.25, 1.0 };
  double rgb[3];
  int c;
  m.ambient = 0.25;
  m.ambient_colour[0] = 1.0;
  m.diffuse = 0.5;
  m.diffuse_colour[1] = 1.0;
  m.specular = 0.5;
  m.specular_colour[2] = 1.0;
  m.specular_power = 4.0;
  /* Unlit: ambient Ca + diffuse Cd, whatever the normal. */
  rf_opaque_shade(&m, NULL, -0.3, rgb);
  CHECK_NEAR(rgb[0], 0.25, 1e-12);
  CHECK_NEAR(rgb[1], 0.5, 1e-12);
  CHECK_NEAR(rgb[2], 0.0, 1e-12);
  /* Lit: diffuse by n_z, specular by n_z^power. */
  m.lighting = 1;
  rf_opaque_shade(&m, NULL, 0.5, rgb);
  CHECK_NEAR(rgb[0], 0.25, 1e-12);
  CHECK_NEAR(rgb[1], 0.25, 1e-12);
  CHECK_NEAR(rgb[2], 0.5 * pow(0.5, 4.0), 1e-12);
  /* Facing away along the view axis: ambient only. */
  rf_opaque_shade(&m, NULL, -0.5, rgb);
  CHECK_NEAR(rgb[0], 0.25, 1e-12);
  CHECK_NEAR(rgb[1], 0.0, 1e-12);
  CHECK_NEAR(rgb[2], 0.0, 1e-12);
  /* A scalar colour replaces the ambient and diffuse colours, not the specular one. */
  rf_opaque_shade(&m, scalar, 1.0, rgb);
  for (c = 0; c < 3; ++c)
  {
    CHECK_NEAR(rgb[c], fmin(1.0, 0.75 * scalar[c] + (c == 2 ? 0.5 : 0.0)), 1e-12);
  }
  /* Clamped to what the framebuffer holds. */
  m.ambient = 3.0;
  rf_opaque_shade(&m, NULL, 1.0, rgb);
  CHECK_NEAR(rgb[0], 1.0, 0.0);
}

static void test_plane_behind_glass(void)
{
  const float triangle_colours[6] = { 1.f, 0.f, 0.f, 0.f, 0.f, 1.f };
  const double lower[3] = { 1.0, 0.0, 0.0 };
  const double upper[3] = { 0.0, 0.0, 1.0 };
  const double fresnel = rft_fresnel(0.0, 1.0, 1.5);
  double blended[3];
  rft_box_scene scene;
  plane back;
  rf_opaque_mesh wall;
  int c;
  make_glass_scene(&scene);
  wall = make_wall(&back, -2.0, 0.0, 0);
  wall.colour_binding = RF_COLOUR_PER_TRIANGLE;
  wall.colours = triangle_colours;
  scene.options.environment = constant_environment;
  scene.options.fresnel = 0;
  CHECK(trace_with(&scene, &wall, 1) == RF_OK);
  /* Beside the glass: the plane itself, flat per triangle. */
  CHECK(scene.image.opaque[BESIDE_LOWER] == 1 && scene.image.hit[BESIDE_LOWER] == 0);
  CHECK(scene.image.opaque[BESIDE_UPPER] == 1 && scene.image.hit[BESIDE_UPPER] == 0);
  check_colour(&scene.image, BESIDE_LOWER, lower, 0.0);
  check_colour(&scene.image, BESIDE_UPPER, upper, 0.0);
  /* Through the glass face-on the ray leaves unbent and meets the plane behind. */
  CHECK(scene.image.hit[THROUGH_LOWER] == 1 && scene.image.opaque[THROUGH_LOWER] == 0);
  check_colour(&scene.image, THROUGH_LOWER, lower, 1e-6);
  /* With Fresnel: F env(R) + (1 - F) plane (R goes back to the environment). */
  scene.options.fresnel = 1;
  CHECK(trace_with(&scene, &wall, 1) == RF_OK);
  for (c = 0; c < 3; ++c)
  {
    blended[c] = fresnel * kEnvironment[c] + (1.0 - fresnel) * lower[c];
  }
  check_colour(&scene.image, THROUGH_LOWER, blended, 1e-6);
  /* Full mode, transmission only: the plane again (no absorption). */
  scene.options.fresnel = 0;
  scene.options.mode = RF_TRACE_FULL;
  CHECK(trace_with(&scene, &wall, 1) == RF_OK);
  check_colour(&scene.image, THROUGH_LOWER, lower, 1e-6);
  check_colour(&scene.image, BESIDE_UPPER, upper, 0.0);
  /* Without the plane the glass shows the environment, and beside it nothing. */
  CHECK(trace_with(&scene, NULL, 0) == RF_OK);
  check_colour(&scene.image, THROUGH_LOWER, kEnvironment, 1e-6);
  CHECK(scene.image.opaque[BESIDE_LOWER] == 0 && scene.image.colour[3 * BESIDE_LOWER] == 0.f);
  /* In front of the glass the plane hides it. */
  make_plane(&back, 2.0, 0.0, 0);
  scene.options.mode = RF_TRACE_TWO_INTERFACE;
  CHECK(trace_with(&scene, &wall, 1) == RF_OK);
  CHECK(scene.image.hit[THROUGH_LOWER] == 0 && scene.image.opaque[THROUGH_LOWER] == 1);
  check_colour(&scene.image, THROUGH_LOWER, lower, 0.0);
  rf_trace_image_free(&scene.image);
}

/* A lit plane tilted by 60 degrees: n_z = cos 60 = 0.5 with its own normals, two-sided (the
 * reversed winding gives the same colour); with point normals all along +z, n_z = 1. */
static void test_lit_plane(void)
{
  const double tilt = 60.0 * RFT_DEG;
  const double cd[3] = { 0.2, 0.6, 1.0 };
  const float vertex_colours[12] = { 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f,
    0.5f, 0.5f, 0.5f };
  double expected[3];
  rft_box_scene scene;
  plane back;
  rf_opaque_mesh wall;
  int reversed;
  int c;
  make_glass_scene(&scene);
  for (reversed = 0; reversed < 2; ++reversed)
  {
    wall = make_wall(&back, -2.0, tilt, reversed);
    wall.material.lighting = 1;
    wall.material.ambient = 0.1;
    wall.material.diffuse = 0.8;
    wall.material.specular = 0.5;
    wall.material.specular_power = 4.0;
    memcpy(wall.material.ambient_colour, cd, sizeof(cd));
    memcpy(wall.material.diffuse_colour, cd, sizeof(cd));
    wall.material.specular_colour[0] = wall.material.specular_colour[1] =
      wall.material.specular_colour[2] = 1.0;
    CHECK(trace_with(&scene, &wall, 1) == RF_OK);
    for (c = 0; c < 3; ++c)
    {
      expected[c] = 0.1 * cd[c] + 0.8 * cd[c] * 0.5 + 0.5 * pow(0.5, 4.0);
    }
    check_colour(&scene.image, BESIDE_LOWER, expected, 1e-6);
  }
  /* Interpolated point normals (all +z) and per-vertex colours (all 0.5). */
  make_plane(&back, -2.0, tilt, 0);
  wall.normals = back.normals;
  wall.colour_binding = RF_COLOUR_PER_VERTEX;
  wall.colours = vertex_colours;
  CHECK(trace_with(&scene, &wall, 1) == RF_OK);
  for (c = 0; c < 3; ++c)
  {
    expected[c] = 0.9 * 0.5 + 0.5;
  }
  check_colour(&scene.image, BESIDE_LOWER, expected, 1e-6);
  rf_trace_image_free(&scene.image);
}

static void test_rejected_opaque(void)
{
  float colours[6] = { 1.f, 0.f, 0.f, 0.f, 0.f, 1.f };
  rft_box_scene scene;
  plane back;
  rf_opaque_mesh good;
  rf_opaque_mesh bad;
  make_glass_scene(&scene);
  good = make_wall(&back, -2.0, 0.0, 0);
  CHECK(trace_with(&scene, &good, 1) == RF_OK);
  CHECK(trace_with(&scene, NULL, 1) == RF_ERR_NULL_ARGUMENT);
  bad = good;
  bad.colour_binding = RF_COLOUR_PER_TRIANGLE;
  CHECK(trace_with(&scene, &bad, 1) == RF_ERR_NULL_ARGUMENT);
  bad.colours = colours;
  CHECK(trace_with(&scene, &bad, 1) == RF_OK);
  colours[2] = 1.5f;
  CHECK(trace_with(&scene, &bad, 1) == RF_REF_ERR_BAD_OPTION);
  colours[2] = NAN;
  CHECK(trace_with(&scene, &bad, 1) == RF_ERR_NOT_FINITE);
  bad = good;
  bad.colour_binding = (rf_colour_binding)7;
  CHECK(trace_with(&scene, &bad, 1) == RF_REF_ERR_BAD_OPTION);
  bad = good;
  bad.material.ambient = -1.0;
  CHECK(trace_with(&scene, &bad, 1) == RF_REF_ERR_BAD_OPTION);
  bad.material.ambient = INFINITY;
  CHECK(trace_with(&scene, &bad, 1) == RF_ERR_NOT_FINITE);
  bad = good;
  back.triangles[4] = 9;
  CHECK(trace_with(&scene, &bad, 1) == RF_REF_ERR_INDEX_OUT_OF_RANGE);
  back.triangles[4] = 2;
  back.positions[1] = NAN;
  CHECK(trace_with(&scene, &bad, 1) == RF_ERR_NOT_FINITE);
  rf_trace_image_free(&scene.image);
}

/* VTK's perspective projection (vtkPerspectiveTransform::Perspective): view angle 2 atan(t). */
static void perspective(double t, double aspect, double near_d, double far_d, double m[16])
{
  memset(m, 0, 16 * sizeof(double));
  m[0] = 1.0 / (t * aspect);
  m[5] = 1.0 / t;
  m[10] = -(far_d + near_d) / (far_d - near_d);
  m[11] = -2.0 * far_d * near_d / (far_d - near_d);
  m[14] = -1.0;
}

static void test_background(void)
{
  const double t = tan(15.0 * RFT_DEG);
  rf_background_environment b;
  double rgb[3];
  double d[3];
  int c;
  memset(&b, 0, sizeof(b));
  b.world_to_view[0] = b.world_to_view[4] = b.world_to_view[8] = 1.0;
  perspective(t, 1.5, 0.1, 100.0, b.projection);
  for (c = 0; c < 3; ++c)
  {
    b.bottom[c] = 0.1 * (c + 1);
    b.top[c] = 0.9 - 0.1 * c;
  }
  /* Ahead: the middle of the screen; a quarter up; the top edge and beyond it. */
  d[0] = 0.3; d[1] = 0.0; d[2] = -1.0;
  rf_background_environment_lookup(d, rgb, &b);
  CHECK_NEAR(rgb[0], 0.5 * (b.bottom[0] + b.top[0]), 1e-12);
  d[1] = 0.5 * t;
  rf_background_environment_lookup(d, rgb, &b);
  CHECK_NEAR(rgb[1], 0.25 * b.bottom[1] + 0.75 * b.top[1], 1e-12);
  d[1] = 3.0 * t;
  rf_background_environment_lookup(d, rgb, &b);
  CHECK_NEAR(rgb[2], b.top[2], 1e-12);
  /* Behind the camera: the top for directions up, the bottom for directions down. */
  d[1] = -0.1; d[2] = 1.0;
  rf_background_environment_lookup(d, rgb, &b);
  CHECK_NEAR(rgb[0], b.bottom[0], 1e-12);
  d[1] = 0.1;
  rf_background_environment_lookup(d, rgb, &b);
  CHECK_NEAR(rgb[0], b.top[0], 1e-12);
  /* The view's rotation applies: turned 180 degrees about x, the camera sees world
   * (0, -0.5 t, 1) as view (0, 0.5 t, -1), a quarter up. */
  b.world_to_view[4] = -1.0;
  b.world_to_view[8] = -1.0;
  d[0] = 0.0; d[1] = -0.5 * t; d[2] = 1.0;
  rf_background_environment_lookup(d, rgb, &b);
  CHECK_NEAR(rgb[1], 0.25 * b.bottom[1] + 0.75 * b.top[1], 1e-12);
  /* Parallel projection: no direction projects; up or down by the sign of y. */
  rft_ortho(1.5, 1.5, 0.1, 100.0, b.projection);
  d[1] = -0.01; /* view y = +0.01 */
  rf_background_environment_lookup(d, rgb, &b);
  CHECK_NEAR(rgb[2], b.top[2], 1e-12);
}

int main(void)
{
  test_shade_formula();
  test_plane_behind_glass();
  test_lit_plane();
  test_rejected_opaque();
  test_background();
  return RF_TEST_SUMMARY();
}
