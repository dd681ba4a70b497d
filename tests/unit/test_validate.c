/* Unit tests of rf_validate: parameter checks and status messages. */
#include "rf_validate.h"

#include "rf_test.h"

#include <math.h>
#include <string.h>

static void test_ior(void)
{
  /* IOR < 1 is legal (a bubble); zero, negative and non-finite are not. */
  CHECK(rf_validate_ior(1.0) == RF_OK);
  CHECK(rf_validate_ior(1.5) == RF_OK);
  CHECK(rf_validate_ior(0.75) == RF_OK);
  CHECK(rf_validate_ior(0.0) == RF_ERR_IOR_NOT_POSITIVE);
  CHECK(rf_validate_ior(-1.0) == RF_ERR_IOR_NOT_POSITIVE);
  CHECK(rf_validate_ior(NAN) == RF_ERR_NOT_FINITE);
  CHECK(rf_validate_ior(INFINITY) == RF_ERR_NOT_FINITE);
  CHECK(rf_validate_ior(-INFINITY) == RF_ERR_NOT_FINITE);
}

static void test_cbs_steps(void)
{
  CHECK(RF_CBS_MAX_STEPS == 16);
  CHECK(rf_validate_cbs_steps(0) == RF_OK);
  CHECK(rf_validate_cbs_steps(5) == RF_OK);
  CHECK(rf_validate_cbs_steps(16) == RF_OK);
  CHECK(rf_validate_cbs_steps(-1) == RF_ERR_STEPS_OUT_OF_RANGE);
  CHECK(rf_validate_cbs_steps(17) == RF_ERR_STEPS_OUT_OF_RANGE);
}

static void test_absorption(void)
{
  const double zero[3] = { 0.0, 0.0, 0.0 };
  const double tinted[3] = { 0.1, 0.5, 2.0 };
  const double negative[3] = { 0.1, -0.01, 0.0 };
  const double not_a_number[3] = { 0.0, 0.0, NAN };
  const double infinite[3] = { INFINITY, 0.0, 0.0 };
  CHECK(rf_validate_absorption(zero) == RF_OK);
  CHECK(rf_validate_absorption(tinted) == RF_OK);
  CHECK(rf_validate_absorption(negative) == RF_ERR_ABSORPTION_NEGATIVE);
  CHECK(rf_validate_absorption(not_a_number) == RF_ERR_NOT_FINITE);
  CHECK(rf_validate_absorption(infinite) == RF_ERR_NOT_FINITE);
  CHECK(rf_validate_absorption(NULL) == RF_ERR_NULL_ARGUMENT);
}

static void test_depth_range(void)
{
  CHECK(rf_validate_depth_range(1.0, 2.0) == RF_OK);
  CHECK(rf_validate_depth_range(3.0, 3.0) == RF_OK);
  CHECK(rf_validate_depth_range(2.0, 1.0) == RF_ERR_EMPTY_RANGE);
  CHECK(rf_validate_depth_range(0.0, 1.0) == RF_ERR_EMPTY_RANGE);
  CHECK(rf_validate_depth_range(-1.0, 1.0) == RF_ERR_EMPTY_RANGE);
  CHECK(rf_validate_depth_range(NAN, 1.0) == RF_ERR_NOT_FINITE);
  CHECK(rf_validate_depth_range(1.0, INFINITY) == RF_ERR_NOT_FINITE);
}

static void test_messages(void)
{
  const rf_status all[] = { RF_OK, RF_TIR, RF_ERR_NULL_ARGUMENT, RF_ERR_NOT_FINITE,
    RF_ERR_IOR_NOT_POSITIVE, RF_ERR_STEPS_OUT_OF_RANGE, RF_ERR_ABSORPTION_NEGATIVE,
    RF_ERR_DEGENERATE_DIRECTION, RF_ERR_EMPTY_RANGE, RF_ERR_BAD_MESH };
  const int count = (int)(sizeof(all) / sizeof(all[0]));
  const char* unknown = rf_status_message((rf_status)99);
  int i;
  int j;
  CHECK(unknown != NULL && strcmp(unknown, "unknown status") == 0);
  CHECK(strcmp(rf_status_message((rf_status)-1), "unknown status") == 0);
  CHECK(RF_OK == 0 && RF_TIR == 1);
  for (i = 0; i < count; ++i)
  {
    const char* message = rf_status_message(all[i]);
    CHECK(message != NULL && strlen(message) > 0);
    CHECK(message != NULL && strcmp(message, "unknown status") != 0);
    /* Distinct codes deserve distinct sentences. */
    for (j = 0; j < i; ++j)
    {
      CHECK(message != NULL && strcmp(message, rf_status_message(all[j])) != 0);
    }
  }
  /* The message spells the limit from the macro. */
  CHECK(strstr(rf_status_message(RF_ERR_STEPS_OUT_OF_RANGE), "16") != NULL);
}

int main(void)
{
  test_ior();
  test_cbs_steps();
  test_absorption();
  test_depth_range();
  test_messages();
  return RF_TEST_SUMMARY();
}
