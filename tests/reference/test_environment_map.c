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

static void identity_frame(rf_environment_map* map)
{
  const double up[3] = { 0.0, 1.0, 0.0 };
  const double right[3] = { 1.0, 0.0, 0.0 };
  CHECK(rf_environment_map_frame(up, right, map->frame) == RF_OK);
}

static void test_constant(void)
{
  static float latlong[3 * LATLONG_W * LATLONG_H];
  static float face[3 * CUBE_SIDE * CUBE_SIDE];
  const float colour[3] = { 0.25f, 1.5f, 3.0f };
  const double up[3] = { 0.3, 0.2, 0.9 };
  const double right[3] = { 1.0, -0.4, 0.0 };
  rf_environment_map map;
  double worst = 0.0;
  int k;
  int c;
  for (k = 0; k < LATLONG_W * LATLONG_H; ++k)
  {
    for (c = 0; c < 3; ++c)
    {
      latlong[3 * k + c] = colour[c];
    }
  }
  for (k = 0; k < CUBE_SIDE * CUBE_SIDE; ++k)
  {
    for (c = 0; c < 3; ++c)
    {
      face[3 * k + c] = colour[c];
    }
  }
  for (k = 0; k < 8; ++k)
  {
    int f;
    double d[3];
    double rgb[3];
    int n;
    map.layout = k % 2 ? RF_ENVIRONMENT_CUBE : RF_ENVIRONMENT_LATLONG;
    map.width = k % 2 ? CUBE_SIDE : LATLONG_W;
    map.height = k % 2 ? CUBE_SIDE : LATLONG_H;
    for (f = 0; f < 6; ++f)
    {
      map.texels[f] = k % 2 ? face : latlong;
    }
    map.linear = (k / 2) % 2;
    map.repeat = k / 4;
    CHECK(rf_environment_map_frame(up, right, map.frame) == RF_OK);
    CHECK(rf_environment_map_validate(&map) == RF_OK);
    for (n = 0; n < DIRECTIONS; ++n)
    {
      direction(n, d);
      rf_environment_map_lookup(d, rgb, &map);
      for (c = 0; c < 3; ++c)
      {
        worst = fmax(worst, fabs(rgb[c] - colour[c]));
      }
    }
  }
  CHECK_NEAR(worst, 0.0, 1e-6);
}

/* Texels hold (the direction's y, cos of its longitude, sin of its longitude), all smooth
 * away from the poles. The frame up = +z, right = +x makes the lookup direction
 * (w.x, w.z, -w.y): the map must read w.z as "up" and atan2(-w.y, w.x) as longitude. */
static void test_latlong_frame(void)
{
  static float latlong[3 * LATLONG_W * LATLONG_H];
  const double up[3] = { 0.0, 0.0, 1.0 };
  const double right[3] = { 1.0, 0.0, 0.0 };
  rf_environment_map map;
  double worst_up = 0.0;
  double worst_longitude = 0.0;
  double worst_identity = 0.0;
  int i;
  int j;
  int n;
  for (j = 0; j < LATLONG_H; ++j)
  {
    for (i = 0; i < LATLONG_W; ++i)
    {
      double d[3];
      float* texel = latlong + 3 * (j * LATLONG_W + i);
      latlong_texel_direction(i, j, d);
      texel[0] = (float)d[1];
      texel[1] = (float)cos(atan2(d[2], d[0]));
      texel[2] = (float)sin(atan2(d[2], d[0]));
    }
  }
  map.layout = RF_ENVIRONMENT_LATLONG;
  map.width = LATLONG_W;
  map.height = LATLONG_H;
  map.texels[0] = latlong;
  map.linear = 1;
  map.repeat = 1; /* GL_REPEAT: the seam at longitude pi blends across, the poles too */
  CHECK(rf_environment_map_frame(up, right, map.frame) == RF_OK);
  CHECK(rf_environment_map_validate(&map) == RF_OK);
  for (n = 0; n < DIRECTIONS; ++n)
  {
    double w[3];
    double rgb[3];
    double longitude;
    direction(n, w);
    rf_environment_map_lookup(w, rgb, &map);
    /* Bilinear interpolation of sin(latitude) across rows: (pi / H)^2 / 8 at most, away
     * from the last half row at either pole (which repeat blends with the other pole). */
    if (fabs(w[2]) < 0.999)
    {
      worst_up = fmax(worst_up, fabs(rgb[0] - w[2]));
    }
    if (fabs(w[2]) < 0.9)
    {
      longitude = atan2(-w[1], w[0]);
      worst_longitude = fmax(worst_longitude,
        fmax(fabs(rgb[1] - cos(longitude)), fabs(rgb[2] - sin(longitude))));
    }
  }
  CHECK(worst_up < 1e-3);
  CHECK(worst_longitude < 2e-3);
  /* Without the frame the same image reads w.y: the frame must matter. */
  identity_frame(&map);
  for (n = 0; n < DIRECTIONS; ++n)
  {
    double w[3];
    double rgb[3];
    direction(n, w);
    rf_environment_map_lookup(w, rgb, &map);
    worst_identity = fmax(worst_identity, fabs(rgb[0] - w[2]));
  }
  CHECK(worst_identity > 0.5);
  printf("lat-long through a frame: worst |up| error %.2e, longitude %.2e (identity frame "
         "misses by %.2f)\n",
    worst_up, worst_longitude, worst_identity);
}

static void test_cube_faces(void)
{
  static float faces[6][3 * CUBE_SIDE * CUBE_SIDE];
  rf_environment_map map;
  double worst = 0.0;
  int face;
  int a;
  int b;
  int n;
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
    map.texels[face] = faces[face];
  }
  map.layout = RF_ENVIRONMENT_CUBE;
  map.width = CUBE_SIDE;
  map.height = CUBE_SIDE;
  map.linear = 1;
  map.repeat = 0;
  identity_frame(&map);
  CHECK(rf_environment_map_validate(&map) == RF_OK);
  for (n = 0; n < DIRECTIONS; ++n)
  {
    double w[3];
    double rgb[3];
    int c;
    direction(n, w);
    rf_environment_map_lookup(w, rgb, &map);
    for (c = 0; c < 3; ++c)
    {
      worst = fmax(worst, fabs(rgb[c] - w[c]));
    }
  }
  /* Inside a face the bilinear error is tiny; along a face's border the clamped half texel
   * reads the centre of the border texels, about 1 / CUBE_SIDE away in angle. */
  CHECK(worst < 1.5 / CUBE_SIDE);
  printf("cube faces: worst direction error %.2e (texel %.2e)\n", worst, 2.0 / CUBE_SIDE);
}

/* The cube VTK's filter makes of a lat-long image reads what the image reads (up to the
 * two resamplings), and the nearest-filtered map reads texel values exactly. */
static void test_cube_from_latlong(void)
{
  static float latlong[3 * LATLONG_W * LATLONG_H];
  static float faces[6][3 * CUBE_SIDE * CUBE_SIDE];
  float* face_pointers[6];
  rf_environment_map source;
  rf_environment_map cube;
  double worst = 0.0;
  int i;
  int j;
  int n;
  for (j = 0; j < LATLONG_H; ++j)
  {
    for (i = 0; i < LATLONG_W; ++i)
    {
      double d[3];
      int c;
      latlong_texel_direction(i, j, d);
      for (c = 0; c < 3; ++c)
      {
        latlong[3 * (j * LATLONG_W + i) + c] = (float)(0.5 + 0.5 * d[c]);
      }
    }
  }
  source.layout = RF_ENVIRONMENT_LATLONG;
  source.width = LATLONG_W;
  source.height = LATLONG_H;
  source.texels[0] = latlong;
  source.linear = 1;
  source.repeat = 1;
  identity_frame(&source);
  for (i = 0; i < 6; ++i)
  {
    face_pointers[i] = faces[i];
    cube.texels[i] = faces[i];
  }
  CHECK(rf_environment_cube_from_latlong(&source, CUBE_SIDE, face_pointers) == RF_OK);
  cube.layout = RF_ENVIRONMENT_CUBE;
  cube.width = CUBE_SIDE;
  cube.height = CUBE_SIDE;
  cube.linear = 1;
  cube.repeat = 0;
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
  rf_environment_map map;
  float texel[3] = { 1.0f, 1.0f, 1.0f };
  CHECK(rf_environment_map_frame(up, parallel, frame) == RF_REF_ERR_BAD_OPTION);
  CHECK(rf_environment_map_frame(up, broken, frame) == RF_ERR_NOT_FINITE);
  CHECK(rf_environment_map_frame(NULL, up, frame) == RF_ERR_NULL_ARGUMENT);
  CHECK(rf_environment_map_validate(NULL) == RF_ERR_NULL_ARGUMENT);
  map.layout = RF_ENVIRONMENT_LATLONG;
  map.width = 1;
  map.height = 1;
  map.texels[0] = texel;
  map.linear = 1;
  map.repeat = 1;
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
