/* Unit tests of the octahedral normal encoding of the kernel (rf_kernel_octahedral.h), which
 * the G-buffer stores; its GLSL side is compared with this one by test_kernel_glsl. */
#include "rf_kernel_octahedral.h"

#include "rf_test.h"

#include <math.h>

static void test_axes(void)
{
  /* The six axes land on the octahedron's vertices: +z at the centre, -z at the corners. */
  rf_float2 e = rf_oct_encode(rf_make3(0.0, 0.0, 2.0));
  CHECK(e.x == 0.0 && e.y == 0.0);
  e = rf_oct_encode(rf_make3(3.0, 0.0, 0.0));
  CHECK(e.x == 1.0 && e.y == 0.0);
  e = rf_oct_encode(rf_make3(0.0, -1.0, 0.0));
  CHECK(e.x == 0.0 && e.y == -1.0);
  e = rf_oct_encode(rf_make3(0.0, 0.0, -1.0));
  CHECK(fabs(e.x) == 1.0 && fabs(e.y) == 1.0);
  /* (1, 1, 1) / 3 is (1/3, 1/3) on the upper face; (1, 1, -1) folds to (2/3, 2/3). */
  e = rf_oct_encode(rf_make3(1.0, 1.0, 1.0));
  CHECK_NEAR(e.x, 1.0 / 3.0, 1e-15);
  CHECK_NEAR(e.y, 1.0 / 3.0, 1e-15);
  e = rf_oct_encode(rf_make3(1.0, 1.0, -1.0));
  CHECK_NEAR(e.x, 2.0 / 3.0, 1e-15);
  CHECK_NEAR(e.y, 2.0 / 3.0, 1e-15);
}

static void test_round_trip(void)
{
  int i;
  int j;
  for (j = 0; j < 41; ++j)
  {
    for (i = 0; i < 80; ++i)
    {
      const double z = -1.0 + 2.0 * j / 40.0;
      const double r = sqrt(fmax(1.0 - z * z, 0.0));
      const double phi = 2.0 * 3.14159265358979 * (i + 0.25) / 80.0;
      const rf_float3 n = rf_make3(r * cos(phi), r * sin(phi), z);
      const rf_float2 e = rf_oct_encode(n);
      const rf_float3 d = rf_oct_decode(e);
      CHECK(fabs(e.x) <= 1.0 && fabs(e.y) <= 1.0);
      CHECK_NEAR(d.x, n.x, 1e-12);
      CHECK_NEAR(d.y, n.y, 1e-12);
      CHECK_NEAR(d.z, n.z, 1e-12);
    }
  }
}

static void test_degenerate(void)
{
  /* A zero or non-finite normal encodes to the centre, which decodes to +z (finite). */
  rf_float2 e = rf_oct_encode(rf_make3(0.0, 0.0, 0.0));
  CHECK(e.x == 0.0 && e.y == 0.0);
  e = rf_oct_encode(rf_make3(INFINITY, 0.0, 1.0));
  CHECK(e.x == 0.0 && e.y == 0.0);
  e = rf_oct_encode(rf_make3(NAN, 0.0, 1.0));
  CHECK(e.x == 0.0 && e.y == 0.0);
  CHECK(rf_oct_decode(rf_make2(0.0, 0.0)).z == 1.0);
}

int main(void)
{
  test_axes();
  test_round_trip();
  test_degenerate();
  return RF_TEST_SUMMARY();
}
