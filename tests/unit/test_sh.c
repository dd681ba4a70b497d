/* Unit tests of rf_sh (real spherical harmonics, kernel/rf_kernel_sh.h) against closed forms:
 * the basis of orders 0-2 written out, orthonormality by quadrature, a function that is
 * exactly of order 3 projected and reproduced, the one-sweep evaluation against the basis
 * function by function, and bad input. */
#include "rf_sh.h"

#include "rf_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define N_QUADRATURE 40000

/* The k-th of n points of a Fibonacci sphere (nearly even; the quadrature of the tests). */
static void fibonacci(int k, int n, double d[3])
{
  const double golden = 3.14159265358979323846 * (3.0 - sqrt(5.0));
  const double z = 1.0 - (2.0 * k + 1.0) / n;
  const double r = sqrt(1.0 - z * z);
  d[0] = r * cos(golden * k);
  d[1] = r * sin(golden * k);
  d[2] = z;
}

static void test_closed_forms(void)
{
  double basis[9];
  int k;
  for (k = 0; k < 50; ++k)
  {
    double d[3];
    double x;
    double y;
    double z;
    fibonacci(k, 50, d);
    x = d[0];
    y = d[1];
    z = d[2];
    CHECK(rf_sh_basis(2, d, basis) == RF_OK);
    CHECK_NEAR(basis[0], 0.28209479177387814, 1e-14);
    CHECK_NEAR(basis[1], 0.4886025119029199 * y, 1e-14);
    CHECK_NEAR(basis[2], 0.4886025119029199 * z, 1e-14);
    CHECK_NEAR(basis[3], 0.4886025119029199 * x, 1e-14);
    CHECK_NEAR(basis[4], 1.0925484305920792 * x * y, 1e-14);
    CHECK_NEAR(basis[5], 1.0925484305920792 * y * z, 1e-14);
    CHECK_NEAR(basis[6], 0.31539156525252005 * (3.0 * z * z - 1.0), 1e-14);
    CHECK_NEAR(basis[7], 1.0925484305920792 * x * z, 1e-14);
    CHECK_NEAR(basis[8], 0.5462742152960396 * (x * x - y * y), 1e-14);
  }
}

static void test_orthonormal(void)
{
  enum
  {
    order = 6,
    count = (order + 1) * (order + 1)
  };
  static double gram[count][count];
  double basis[count];
  double worst = 0.0;
  int k;
  int i;
  int j;
  memset(gram, 0, sizeof(gram));
  for (k = 0; k < N_QUADRATURE; ++k)
  {
    double d[3];
    fibonacci(k, N_QUADRATURE, d);
    CHECK(rf_sh_basis(order, d, basis) == RF_OK);
    for (i = 0; i < count; ++i)
    {
      for (j = 0; j < count; ++j)
      {
        gram[i][j] += basis[i] * basis[j] * 4.0 * 3.14159265358979323846 / N_QUADRATURE;
      }
    }
  }
  for (i = 0; i < count; ++i)
  {
    for (j = 0; j < count; ++j)
    {
      worst = fmax(worst, fabs(gram[i][j] - (i == j ? 1.0 : 0.0)));
    }
  }
  printf("orthonormality of order %d over %d directions: largest error %.2e\n", order,
    N_QUADRATURE, worst);
  /* Measured: 4.7e-6. */
  CHECK(worst < 1e-4);
}

static void test_projection_reproduces(void)
{
  enum
  {
    order = 3,
    count = (order + 1) * (order + 1)
  };
  double truth[count];
  double projected[count] = { 0.0 };
  double worst = 0.0;
  int i;
  int k;
  srand(7);
  for (i = 0; i < count; ++i)
  {
    truth[i] = (double)rand() / RAND_MAX * 2.0 - 1.0;
  }
  for (k = 0; k < N_QUADRATURE; ++k)
  {
    double d[3];
    double f = 0.0;
    fibonacci(k, N_QUADRATURE, d);
    CHECK(rf_sh_evaluate(order, truth, d, &f) == RF_OK);
    CHECK(rf_sh_accumulate(order, d, f, 4.0 * 3.14159265358979323846 / N_QUADRATURE, projected) ==
      RF_OK);
  }
  for (i = 0; i < count; ++i)
  {
    worst = fmax(worst, fabs(projected[i] - truth[i]));
  }
  printf("an order-3 function projected back: largest coefficient error %.2e\n", worst);
  /* Measured: 1.3e-6. */
  CHECK(worst < 1e-4);
}

static void test_evaluate_matches_basis(void)
{
  enum
  {
    order = RF_SH_ORDER_MAX,
    count = (order + 1) * (order + 1)
  };
  double basis[count];
  double one_hot[count];
  double worst = 0.0;
  int i;
  int k;
  for (k = 0; k < 20; ++k)
  {
    double d[3];
    fibonacci(k, 20, d);
    d[0] *= 3.0; /* not unit: normalized by the API */
    d[1] *= 3.0;
    d[2] *= 3.0;
    CHECK(rf_sh_basis(order, d, basis) == RF_OK);
    for (i = 0; i < count; ++i)
    {
      double value = 0.0;
      memset(one_hot, 0, sizeof(one_hot));
      one_hot[i] = 1.0;
      CHECK(rf_sh_evaluate(order, one_hot, d, &value) == RF_OK);
      worst = fmax(worst, fabs(value - basis[i]));
    }
  }
  CHECK(worst < 1e-12);
  /* At the poles (sin theta = 0) the terms with m != 0 vanish and nothing divides by zero. */
  {
    const double pole[3] = { 0.0, 0.0, -1.0 };
    CHECK(rf_sh_basis(order, pole, basis) == RF_OK);
    for (i = 0; i < count; ++i)
    {
      CHECK(isfinite(basis[i]));
    }
    CHECK(basis[3] == 0.0 && basis[1] == 0.0);
  }
}

static void test_bad_input(void)
{
  double basis[81];
  double value = 0.0;
  const double zero[3] = { 0.0, 0.0, 0.0 };
  const double nan_direction[3] = { NAN, 0.0, 1.0 };
  const double up[3] = { 0.0, 0.0, 1.0 };
  CHECK(rf_sh_coefficient_count(8) == 81 && rf_sh_coefficient_count(9) == 0 &&
    rf_sh_coefficient_count(-1) == 0);
  CHECK(rf_sh_basis(9, up, basis) == RF_ERR_STEPS_OUT_OF_RANGE);
  CHECK(rf_sh_basis(2, zero, basis) == RF_ERR_DEGENERATE_DIRECTION);
  CHECK(rf_sh_basis(2, nan_direction, basis) == RF_ERR_NOT_FINITE);
  CHECK(rf_sh_basis(2, up, NULL) == RF_ERR_NULL_ARGUMENT);
  CHECK(rf_sh_evaluate(2, NULL, up, &value) == RF_ERR_NULL_ARGUMENT);
  CHECK(rf_sh_accumulate(2, up, NAN, 1.0, basis) == RF_ERR_NOT_FINITE);
}

int main(void)
{
  test_closed_forms();
  test_orthonormal();
  test_projection_reproduces();
  test_evaluate_matches_basis();
  test_bad_input();
  return RF_TEST_SUMMARY();
}
