/* Unit tests of rf_isr (Wyman 2005a, eq. 1-2 of the DIR paper: the estimate the ISR shader
 * runs) against closed forms worked out here with Snell's law directly. */
#include "rf_isr.h"

#include "rf_test.h"

#include <math.h>

static void test_view_distance(void)
{
  double d = -1.0;
  /* Straight down the axis from z = -3 to the back at depth 5: 2. */
  CHECK(rf_isr_view_distance(5.0, rf_vec3_make(0.0, 0.0, -3.0), rf_vec3_make(0.0, 0.0, -1.0), &d) ==
    RF_OK);
  CHECK_NEAR(d, 2.0, 1e-15);
  /* Slanted by V = (0.6, 0, -0.8) (need not be unit: scaled by 5): 2 / 0.8 = 2.5. */
  CHECK(rf_isr_view_distance(5.0, rf_vec3_make(0.0, 0.0, -3.0), rf_vec3_make(3.0, 0.0, -4.0), &d) ==
    RF_OK);
  CHECK_NEAR(d, 2.5, 1e-15);
  /* An empty texel gives 0, a back depth in front of the entry point too. */
  CHECK(rf_isr_view_distance(0.0, rf_vec3_make(0.0, 0.0, -3.0), rf_vec3_make(0.0, 0.0, -1.0), &d) ==
    RF_OK);
  CHECK(d == 0.0);
  CHECK(rf_isr_view_distance(2.0, rf_vec3_make(0.0, 0.0, -3.0), rf_vec3_make(0.0, 0.0, -1.0), &d) ==
    RF_OK);
  CHECK(d == 0.0);
}

static void test_estimate(void)
{
  const double eta = 1.0 / 1.5;
  const double dV = 2.0;
  const double dN = 1.2;
  const rf_vec3 N1 = rf_vec3_make(0.0, 0.0, 1.0);
  double d = -1.0;
  int k;
  /* Normal incidence: theta_t / theta_i tends to eta, so d = eta dV + (1 - eta) dN. */
  CHECK(rf_isr_distance(dV, dN, rf_vec3_make(0.0, 0.0, -1.0), N1, rf_vec3_make(0.0, 0.0, -1.0),
          eta, &d) == RF_OK);
  CHECK_NEAR(d, eta * dV + (1.0 - eta) * dN, 1e-15);
  /* Oblique: theta_t = asin(eta sin(theta_i)) by Snell, the ratio of the two angles weighs
   * d_V against d_N. */
  for (k = 1; k <= 8; ++k)
  {
    const double theta_i = k * 0.19;
    const double theta_t = asin(eta * sin(theta_i));
    const double ratio = theta_t / theta_i;
    const rf_vec3 V = rf_vec3_make(sin(theta_i), 0.0, -cos(theta_i));
    const rf_vec3 T1 = rf_vec3_make(sin(theta_t), 0.0, -cos(theta_t));
    CHECK(rf_isr_distance(dV, dN, V, N1, T1, eta, &d) == RF_OK);
    CHECK_NEAR(d, ratio * dV + (1.0 - ratio) * dN, 1e-12);
    /* the normal's orientation does not matter (turned against V) */
    CHECK(rf_isr_distance(dV, dN, V, rf_vec3_scale(N1, -2.0), T1, eta, &d) == RF_OK);
    CHECK_NEAR(d, ratio * dV + (1.0 - ratio) * dN, 1e-12);
  }
  /* Near normal incidence the angles are small and their ratio still eta-like: 1e-3 rad. */
  {
    const double theta_i = 1e-3;
    const double theta_t = asin(eta * sin(theta_i));
    const double ratio = theta_t / theta_i;
    CHECK(rf_isr_distance(dV, dN, rf_vec3_make(sin(theta_i), 0.0, -cos(theta_i)), N1,
            rf_vec3_make(sin(theta_t), 0.0, -cos(theta_t)), eta, &d) == RF_OK);
    CHECK_NEAR(d, ratio * dV + (1.0 - ratio) * dN, 1e-9);
  }
}

static void test_errors(void)
{
  const rf_vec3 V = rf_vec3_make(0.0, 0.0, -1.0);
  const rf_vec3 zero = rf_vec3_make(0.0, 0.0, 0.0);
  double d = 7.0;
  CHECK(rf_isr_distance(1.0, 1.0, V, V, V, 1.5, NULL) == RF_ERR_NULL_ARGUMENT);
  CHECK(rf_isr_distance(NAN, 1.0, V, V, V, 1.5, &d) == RF_ERR_NOT_FINITE);
  CHECK(rf_isr_distance(1.0, INFINITY, V, V, V, 1.5, &d) == RF_ERR_NOT_FINITE);
  CHECK(rf_isr_distance(1.0, 1.0, rf_vec3_make(NAN, 0.0, 1.0), V, V, 1.5, &d) == RF_ERR_NOT_FINITE);
  CHECK(rf_isr_distance(1.0, 1.0, V, V, V, 0.0, &d) == RF_ERR_IOR_NOT_POSITIVE);
  CHECK(rf_isr_distance(1.0, 1.0, V, zero, V, 1.5, &d) == RF_ERR_DEGENERATE_DIRECTION);
  CHECK(rf_isr_view_distance(1.0, V, zero, &d) == RF_ERR_DEGENERATE_DIRECTION);
  CHECK(rf_isr_view_distance(NAN, V, V, &d) == RF_ERR_NOT_FINITE);
  CHECK(rf_isr_view_distance(1.0, V, V, NULL) == RF_ERR_NULL_ARGUMENT);
  CHECK(d == 7.0);
}

int main(void)
{
  test_view_distance();
  test_estimate();
  test_errors();
  return RF_TEST_SUMMARY();
}
