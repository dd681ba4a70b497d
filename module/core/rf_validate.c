/* rf_validate.c: parameter checks and status messages. */
#include "rf_validate.h"

#include <math.h>
#include <stddef.h>

/* Spell RF_CBS_MAX_STEPS into the message so the two cannot disagree. */
#define RF_STRINGIFY_VALUE(x) RF_STRINGIFY(x)
#define RF_STRINGIFY(x) #x

rf_status rf_validate_ior(double ior)
{
  if (!isfinite(ior))
  {
    return RF_ERR_NOT_FINITE;
  }
  /* Snell's law divides by the IOR; zero or negative has no physical meaning. */
  if (!(ior > 0.0))
  {
    return RF_ERR_IOR_NOT_POSITIVE;
  }
  return RF_OK;
}

rf_status rf_validate_cbs_steps(int steps)
{
  if (steps < 0 || steps > RF_CBS_MAX_STEPS)
  {
    return RF_ERR_STEPS_OUT_OF_RANGE;
  }
  return RF_OK;
}

rf_status rf_validate_absorption(const double rgb[3])
{
  int channel;
  if (rgb == NULL)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  for (channel = 0; channel < 3; ++channel)
  {
    if (!isfinite(rgb[channel]))
    {
      return RF_ERR_NOT_FINITE;
    }
    /* A negative coefficient would amplify light with distance. */
    if (rgb[channel] < 0.0)
    {
      return RF_ERR_ABSORPTION_NEGATIVE;
    }
  }
  return RF_OK;
}

rf_status rf_validate_depth_range(double z_min, double z_max)
{
  if (!isfinite(z_min) || !isfinite(z_max))
  {
    return RF_ERR_NOT_FINITE;
  }
  /* eq. 9 divides by the depth of points in the range: it must stay in front
   * of the camera (> 0), and S (z_min) must come before E (z_max). */
  if (!(z_min > 0.0) || !(z_min <= z_max))
  {
    return RF_ERR_EMPTY_RANGE;
  }
  return RF_OK;
}

const char* rf_status_message(rf_status s)
{
  switch (s)
  {
    case RF_OK:
      return "success";
    case RF_TIR:
      return "total internal reflection: no transmitted ray (not an error)";
    case RF_ERR_NULL_ARGUMENT:
      return "a required pointer argument is NULL";
    case RF_ERR_NOT_FINITE:
      return "an input value is NaN or infinite";
    case RF_ERR_IOR_NOT_POSITIVE:
      return "the index of refraction must be greater than zero";
    case RF_ERR_STEPS_OUT_OF_RANGE:
      return "the number of conservative binary search steps must be between 0 and "
             RF_STRINGIFY_VALUE(RF_CBS_MAX_STEPS);
    case RF_ERR_ABSORPTION_NEGATIVE:
      return "absorption coefficients must not be negative";
    case RF_ERR_DEGENERATE_DIRECTION:
      return "the direction is zero, parallel to the image plane, or points toward the camera";
    case RF_ERR_EMPTY_RANGE:
      return "the depth range is empty or not in front of the camera"
             " (need 0 < depth_min <= depth_max, and depth_min < depth_max to search)";
    case RF_ERR_BAD_MESH:
      return "a count is negative, or a polygon names a point (or a point a class) that does"
             " not exist";
  }
  return "unknown status";
}
