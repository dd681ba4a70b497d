/* Image environments (rf_environment_map.h) against closed forms: a constant map reads the
 * constant everywhere; a lat-long image whose texels hold a smooth function of their own
 * direction (written here from VTK's toSpherical, inverted) reads that function back at any
 * direction, through a renderer frame that is not the identity; a cube whose faces hold
 * their texel directions (written from the OpenGL specification's face table, not from the
 * code under test) reads the direction back; the cube VTK's filter would make of a lat-long
 * image reads what the image reads. Expected values come from the formulas here. */
#include "rf_environment_map.h"

#include "rf_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define LATLONG_W 256
#define LATLONG_H 128
#define CUBE_SIDE 64
#define DIRECTIONS 2000

/* A reproducible direction spread over the sphere (Fibonacci lattice). */
static void direction(int k, double d[3])
{
  const double z = 1.0 - (2.0 * k + 1.0) / DIRECTIONS;
  const double r = sqrt(1.0 - z * z);
  const double phi = k * PI * (3.0 - sqrt(5.0));
  d[0] = r * cos(phi);
  d[1] = r * sin(phi);
  d[2] = z;
}

/* VTK's toSpherical inverted at the texel centre (i, j): the texel's direction. */
static void latlong_texel_direction(int i, int j, double d[3])
{
  const double theta = (((i + 0.5) / LATLONG_W) - 0.5) / 0.1591;
  const double phi = (((j + 0.5) / LATLONG_H) - 0.5) / 0.3183;
  d[0] = cos(phi) * cos(theta);
  d[1] = sin(phi);
  d[2] = cos(phi) * sin(theta);
}

/* The OpenGL face table (GL 4.5, table 8.19) solved for the direction at (s, t). */
static void cube_texel_direction(int face, double s, double t, double d[3])
{
  const double sc = 2.0 * s - 1.0;
  const double tc = 2.0 * t - 1.0;
  double length;
  int c;
  switch (face)
  {
    case 0: d[0] = 1.0; d[1] = -tc; d[2] = -sc; break;
    case 1: d[0] = -1.0; d[1] = -tc; d[2] = sc; break;
    case 2: d[0] = sc; d[1] = 1.0; d[2] = tc; break;
    case 3: d[0] = sc; d[1] = -1.0; d[2] = -tc; break;
    case 4: d[0] = sc; d[1] = -tc; d[2] = 1.0; break;
    default: d[0] = -sc; d[1] = -tc; d[2] = -1.0; break;
  }
  length = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  for (c = 0; c < 3; ++c)
  {
    d[c] /= length;
  }
}

/* A texel's colour as a function of the direction it stands for. */
typedef void (*texel_colour_fn)(const double d[3], float rgb[3]);

/* Fills a LATLONG_W x LATLONG_H image: every texel the colour of its own direction. */
static void fill_latlong(float* latlong, texel_colour_fn colour)
{
  int i;
  int j;
  for (j = 0; j < LATLONG_H; ++j)
  {
    for (i = 0; i < LATLONG_W; ++i)
    {
      double d[3];
      latlong_texel_direction(i, j, d);
      colour(d, latlong + 3 * (j * LATLONG_W + i));
    }
  }
}

/* Fills `count` texels with one colour. */
static void fill_constant(float* texels, int count, const float colour[3])
{
  int k;
  for (k = 0; k < count; ++k)
  {
    memcpy(texels + 3 * k, colour, 3 * sizeof(float));
  }
}

/* A map over `texels` (a lat-long map's image, or a cube's six faces, width x width each)
 * with no other field set; its frame is the caller's to set. */
static rf_environment_map make_map(rf_environment_layout layout, int width, int height,
  float* const* texels, int linear, int repeat)
{
  rf_environment_map map;
  int f;
  memset(&map, 0, sizeof(map));
  map.layout = layout;
  map.width = width;
  map.height = height;
  for (f = 0; f < (layout == RF_ENVIRONMENT_CUBE ? 6 : 1); ++f)
  {
    map.texels[f] = texels[f];
  }
  map.linear = linear;
  map.repeat = repeat;
  return map;
}

static void identity_frame(rf_environment_map* map)
{
  const double up[3] = { 0.0, 1.0, 0.0 };
  const double right[3] = { 1.0, 0.0, 0.0 };
  CHECK(rf_environment_map_frame(up, right, map->frame) == RF_OK);
}

/* How far the colour `rgb` a map reads at direction w is from what a test expects there
 * (`expected`: whatever the test needs to say what that is). */
typedef double (*lookup_error_fn)(const double w[3], const double rgb[3], const void* expected);

/* The largest lookup error over the DIRECTIONS directions. `map` is not const only because
 * the lookup, an rf_environment_fn, takes it as plain user data. */
static double worst_lookup_error(rf_environment_map* map, lookup_error_fn error,
  const void* expected)
{
  double worst = 0.0;
  int n;
  for (n = 0; n < DIRECTIONS; ++n)
  {
    double w[3];
    double rgb[3];
    direction(n, w);
    rf_environment_map_lookup(w, rgb, map);
    worst = fmax(worst, error(w, rgb, expected));
  }
  return worst;
}

/* The largest channel's distance to the colour `expected` (double[3]), or where that is NULL
 * to the direction itself. */
static double channel_error(const double w[3], const double rgb[3], const void* expected)
{
  const double* target = expected ? (const double*)expected : w;
  double worst = 0.0;
  int c;
  for (c = 0; c < 3; ++c)
  {
    worst = fmax(worst, fabs(rgb[c] - target[c]));
  }
  return worst;
}

static void test_constant(void)
{
  static float latlong[3 * LATLONG_W * LATLONG_H];
  static float face[3 * CUBE_SIDE * CUBE_SIDE];
  float* const image[1] = { latlong };
  float* const faces[6] = { face, face, face, face, face, face };
  const float colour[3] = { 0.25f, 1.5f, 3.0f };
  const double expected[3] = { colour[0], colour[1], colour[2] };
  const double up[3] = { 0.3, 0.2, 0.9 };
  const double right[3] = { 1.0, -0.4, 0.0 };
  rf_environment_map map;
  double worst = 0.0;
  int k;
  fill_constant(latlong, LATLONG_W * LATLONG_H, colour);
  fill_constant(face, CUBE_SIDE * CUBE_SIDE, colour);
  /* Every layout, filter and wrap: k = cube + 2 linear + 4 repeat. */
  for (k = 0; k < 8; ++k)
  {
    const int linear = (k / 2) % 2;
    const int repeat = k / 4;
    map = k % 2 ? make_map(RF_ENVIRONMENT_CUBE, CUBE_SIDE, CUBE_SIDE, faces, linear, repeat)
                : make_map(RF_ENVIRONMENT_LATLONG, LATLONG_W, LATLONG_H, image, linear, repeat);
    CHECK(rf_environment_map_frame(up, right, map.frame) == RF_OK);
    CHECK(rf_environment_map_validate(&map) == RF_OK);
    worst = fmax(worst, worst_lookup_error(&map, channel_error, expected));
  }
  CHECK_NEAR(worst, 0.0, 1e-6);
}

static void up_and_longitude(const double d[3], float rgb[3])
{
  rgb[0] = (float)d[1];
  rgb[1] = (float)cos(atan2(d[2], d[0]));
  rgb[2] = (float)sin(atan2(d[2], d[0]));
}

/* Channel 0 against the direction's z (the frame's "up"), counted only where
 * |w.z| < *(const double*)limit. */
static double error_up(const double w[3], const double rgb[3], const void* limit)
{
  return fabs(w[2]) < *(const double*)limit ? fabs(rgb[0] - w[2]) : 0.0;
}

/* Channels 1 and 2 against cos and sin of the longitude atan2(-w.y, w.x), away from the
 * poles. */
static double error_longitude(const double w[3], const double rgb[3], const void* expected)
{
  const double longitude = atan2(-w[1], w[0]);
  (void)expected;
  if (fabs(w[2]) >= 0.9)
  {
    return 0.0;
  }
  return fmax(fabs(rgb[1] - cos(longitude)), fabs(rgb[2] - sin(longitude)));
}

/* Texels hold (the direction's y, cos of its longitude, sin of its longitude), all smooth
 * away from the poles. The frame up = +z, right = +x makes the lookup direction
 * (w.x, w.z, -w.y): the map must read w.z as "up" and atan2(-w.y, w.x) as longitude. */
static void test_latlong_frame(void)
{
  static float latlong[3 * LATLONG_W * LATLONG_H];
  float* const image[1] = { latlong };
  const double up[3] = { 0.0, 0.0, 1.0 };
  const double right[3] = { 1.0, 0.0, 0.0 };
  /* GL_REPEAT: the seam at longitude pi blends across, the poles too */
  rf_environment_map map = make_map(RF_ENVIRONMENT_LATLONG, LATLONG_W, LATLONG_H, image, 1, 1);
  /* Bilinear interpolation of sin(latitude) across rows errs by (pi / H)^2 / 8 at most, away
   * from the last half row at either pole (which repeat blends with the other pole). */
  const double off_the_poles = 0.999;
  const double anywhere = INFINITY;
  double worst_up;
  double worst_longitude;
  double worst_identity;
  fill_latlong(latlong, up_and_longitude);
  CHECK(rf_environment_map_frame(up, right, map.frame) == RF_OK);
  CHECK(rf_environment_map_validate(&map) == RF_OK);
  worst_up = worst_lookup_error(&map, error_up, &off_the_poles);
  worst_longitude = worst_lookup_error(&map, error_longitude, NULL);
  CHECK(worst_up < 1e-3);
  CHECK(worst_longitude < 2e-3);
  /* Without the frame the same image reads w.y: the frame must matter. */
  identity_frame(&map);
  worst_identity = worst_lookup_error(&map, error_up, &anywhere);
  CHECK(worst_identity > 0.5);
  printf("lat-long through a frame: worst |up| error %.2e, longitude %.2e (identity frame "
         "misses by %.2f)\n",
    worst_up, worst_longitude, worst_identity);
}

static void test_cube_faces(void)
{
  static float faces[6][3 * CUBE_SIDE * CUBE_SIDE];
  float* const face_pointers[6] = { faces[0], faces[1], faces[2], faces[3], faces[4], faces[5] };
  rf_environment_map map =
    make_map(RF_ENVIRONMENT_CUBE, CUBE_SIDE, CUBE_SIDE, face_pointers, 1, 0);
  double worst;
  int face;
  int a;
  int b;
  for (face = 0; face < 6; ++face)
  {
    for (b = 0; b < CUBE_SIDE; ++b)
    {
      for (a = 0; a < CUBE_SIDE; ++a)
      {
        double d[3];
        int c;
        cube_texel_direction(face, (a + 0.5) / CUBE_SIDE, (b + 0.5) / CUBE_SIDE, d);
        for (c = 0; c < 3; ++c)
        {
          faces[face][3 * (b * CUBE_SIDE + a) + c] = (float)d[c];
        }
      }
    }
  }
  identity_frame(&map);
  CHECK(rf_environment_map_validate(&map) == RF_OK);
  worst = worst_lookup_error(&map, channel_error, NULL);
  /* Inside a face the bilinear error is tiny; along a face's border the clamped half texel
   * reads the centre of the border texels, about 1 / CUBE_SIDE away in angle. */
  CHECK(worst < 1.5 / CUBE_SIDE);
  printf("cube faces: worst direction error %.2e (texel %.2e)\n", worst, 2.0 / CUBE_SIDE);
}

static void half_plus_half_direction(const double d[3], float rgb[3])
{
  int c;
  for (c = 0; c < 3; ++c)
  {
    rgb[c] = (float)(0.5 + 0.5 * d[c]);
  }
}

/* The cube VTK's filter makes of a lat-long image reads what the image reads (up to the
 * two resamplings), and the nearest-filtered map reads texel values exactly. */
static void test_cube_from_latlong(void)
{
  static float latlong[3 * LATLONG_W * LATLONG_H];
  static float faces[6][3 * CUBE_SIDE * CUBE_SIDE];
  float* const image[1] = { latlong };
  float* const face_pointers[6] = { faces[0], faces[1], faces[2], faces[3], faces[4], faces[5] };
  rf_environment_map source =
    make_map(RF_ENVIRONMENT_LATLONG, LATLONG_W, LATLONG_H, image, 1, 1);
  rf_environment_map cube =
    make_map(RF_ENVIRONMENT_CUBE, CUBE_SIDE, CUBE_SIDE, face_pointers, 1, 0);
  double worst = 0.0;
  int n;
  fill_latlong(latlong, half_plus_half_direction);
  identity_frame(&source);
  CHECK(rf_environment_cube_from_latlong(&source, CUBE_SIDE, face_pointers) == RF_OK);
  identity_frame(&cube);
  for (n = 0; n < DIRECTIONS; ++n)
  {
    double w[3];
    double a[3];
    double b[3];
    int c;
    direction(n, w);
    if (fabs(w[1]) > 0.99)
    {
      continue; /* the poles' top and bottom rows wrap under GL_REPEAT */
    }
    rf_environment_map_lookup(w, a, &source);
    rf_environment_map_lookup(w, b, &cube);
    for (c = 0; c < 3; ++c)
    {
      worst = fmax(worst, fabs(a[c] - b[c]));
      /* Both read 0.5 + 0.5 w. */
      CHECK(fabs(b[c] - (0.5 + 0.5 * w[c])) < 1.5 / CUBE_SIDE);
    }
  }
  CHECK(worst < 1.5 / CUBE_SIDE);
  printf("cube from lat-long: worst difference to the lat-long image %.2e\n", worst);

  /* Errors. */
  CHECK(rf_environment_cube_from_latlong(NULL, CUBE_SIDE, face_pointers) == RF_ERR_NULL_ARGUMENT);
  CHECK(rf_environment_cube_from_latlong(&source, 0, face_pointers) == RF_REF_ERR_BAD_OPTION);
  CHECK(rf_environment_cube_from_latlong(&cube, CUBE_SIDE, face_pointers) == RF_REF_ERR_BAD_OPTION);
}

static void test_rejected(void)
{
  const double up[3] = { 0.0, 1.0, 0.0 };
  const double parallel[3] = { 0.0, -2.0, 0.0 };
  const double broken[3] = { NAN, 0.0, 0.0 };
  double frame[9];
  float texel[3] = { 1.0f, 1.0f, 1.0f };
  float* const image[1] = { texel };
  rf_environment_map map = make_map(RF_ENVIRONMENT_LATLONG, 1, 1, image, 1, 1);
  CHECK(rf_environment_map_frame(up, parallel, frame) == RF_REF_ERR_BAD_OPTION);
  CHECK(rf_environment_map_frame(up, broken, frame) == RF_ERR_NOT_FINITE);
  CHECK(rf_environment_map_frame(NULL, up, frame) == RF_ERR_NULL_ARGUMENT);
  CHECK(rf_environment_map_validate(NULL) == RF_ERR_NULL_ARGUMENT);
  identity_frame(&map);
  CHECK(rf_environment_map_validate(&map) == RF_OK);
  map.width = 0;
  CHECK(rf_environment_map_validate(&map) == RF_REF_ERR_BAD_OPTION);
  map.width = 1;
  map.layout = RF_ENVIRONMENT_CUBE; /* five faces missing */
  map.texels[1] = NULL;
  CHECK(rf_environment_map_validate(&map) == RF_ERR_NULL_ARGUMENT);
  map.layout = RF_ENVIRONMENT_LATLONG;
  map.frame[4] = INFINITY;
  CHECK(rf_environment_map_validate(&map) == RF_ERR_NOT_FINITE);
}

int main(void)
{
  test_constant();
  test_latlong_frame();
  test_cube_faces();
  test_cube_from_latlong();
  test_rejected();
  return RF_TEST_SUMMARY();
}
