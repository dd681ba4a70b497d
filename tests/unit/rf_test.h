/* rf_test.h: a minimal test harness for the C core's unit tests.
 * Each test program includes it once; the failure counters are file-scope
 * statics so every program has its own. */
#ifndef RF_TEST_H
#define RF_TEST_H

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

#endif /* RF_TEST_H */
