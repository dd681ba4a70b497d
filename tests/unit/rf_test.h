/* rf_test.h: a minimal test harness for the C core's unit tests, and the closed forms that
 * both they and the reference tracer's tests use.
 * Each test program includes it once; the failure counters are file-scope
 * statics so every program has its own. */
#ifndef RF_TEST_H
#define RF_TEST_H

#include "rf_vec3.h"

#include <math.h>
#include <stdio.h>

static int rf_test_checks = 0;
static int rf_test_failures = 0;

/* Records one check; prints where and what on failure. */
static inline void rf_test_record(int passed, const char* file, int line, const char* what)
{
  ++rf_test_checks;
  if (!passed)
  {
    ++rf_test_failures;
    fprintf(stderr, "%s:%d: CHECK failed: %s\n", file, line, what);
  }
}

/* |a - b| <= tol, false for NaNs so a NaN result cannot pass. */
static inline void rf_test_record_near(
  double a, double b, double tol, const char* file, int line, const char* a_text, const char* b_text)
{
  const int passed = fabs(a - b) <= tol;
  ++rf_test_checks;
  if (!passed)
  {
    ++rf_test_failures;
    fprintf(stderr, "%s:%d: CHECK_NEAR failed: %s = %.17g, %s = %.17g, |diff| = %.3g > tol %.3g\n",
      file, line, a_text, a, b_text, b, fabs(a - b), tol);
  }
}

#define CHECK(cond) rf_test_record((cond) ? 1 : 0, __FILE__, __LINE__, #cond)
#define CHECK_NEAR(a, b, tol) rf_test_record_near((a), (b), (tol), __FILE__, __LINE__, #a, #b)

/* Prints the summary line; use as `return RF_TEST_SUMMARY();` in main. */
static inline int rf_test_summary(const char* program)
{
  printf("%s: %d checks, %d failed\n", program, rf_test_checks, rf_test_failures);
  return rf_test_failures == 0 ? 0 : 1;
}
#define RF_TEST_SUMMARY() rf_test_summary(__FILE__)

/* Snell's law written out here, independently of rf_optics.c (the code under test uses that),
 * so that a shared mistake cannot make a test pass. I and N unit, N against I, eta = n1 / n2.
 * Gives the refracted direction, normalized; under total internal reflection returns 0 and
 * gives the mirror direction. */
static inline int rf_test_snell(rf_vec3 I, rf_vec3 N, double eta, rf_vec3* out)
{
  const double c = -rf_vec3_dot(I, N);
  const double k = 1.0 - eta * eta * (1.0 - c * c);
  if (k < 0.0)
  {
    *out = rf_vec3_add(I, rf_vec3_scale(N, 2.0 * c));
    return 0;
  }
  *out =
    rf_vec3_normalize(rf_vec3_add(rf_vec3_scale(I, eta), rf_vec3_scale(N, eta * c - sqrt(k))));
  return 1;
}

#endif /* RF_TEST_H */
