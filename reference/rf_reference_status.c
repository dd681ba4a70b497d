/* rf_reference_status.c: messages of the reference's extra status codes. */
#include "rf_reference_status.h"

const char* rf_reference_status_message(rf_status s)
{
  /* Compared as ints: the extra codes are not members of the enum (see the header). */
  switch ((int)s)
  {
    case (int)RF_REF_ERR_OUT_OF_MEMORY:
      return "out of memory";
    case (int)RF_REF_ERR_EMBREE:
      return "Embree failed to build the scene (its message went to stderr)";
    case (int)RF_REF_ERR_INDEX_OUT_OF_RANGE:
      return "a triangle refers to a vertex beyond the mesh's vertex count";
    case (int)RF_REF_ERR_BAD_OPTION:
      return "an option, size or camera matrix is out of range or singular";
    case (int)RF_REF_ERR_NO_SAMPLES:
      return "no pixel to measure (empty mask or no valid data)";
    default:
      return rf_status_message(s);
  }
}
