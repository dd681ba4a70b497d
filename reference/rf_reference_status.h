/* rf_reference_status.h: the status codes the reference tracer and the metrics need beyond
 * those of module/core/rf_validate.h.
 *
 * They extend rf_status without editing the core (another owner): the values continue the
 * enum above its last member and stay below 16, so that a C++ caller may also hold them in
 * an rf_status (the enum's value range covers 0..15). They belong in rf_validate.h; when
 * they move there, delete this file's macros and keep the names. */
#ifndef RF_REFERENCE_STATUS_H
#define RF_REFERENCE_STATUS_H

#include "rf_validate.h"

#include "rf_reference_export.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A buffer could not be allocated (the image, the per-thread state or a copy of a mesh). */
#define RF_REF_ERR_OUT_OF_MEMORY ((rf_status)11)
/* Embree refused the device, the scene or a geometry (its own message goes to stderr). */
#define RF_REF_ERR_EMBREE ((rf_status)12)
/* A triangle names a vertex beyond the mesh's vertex_count. */
#define RF_REF_ERR_INDEX_OUT_OF_RANGE ((rf_status)13)
/* An option or size is out of range: image size <= 0, max_depth outside 1..64, an output
 * image whose size differs from the camera's, a singular camera matrix, ... */
#define RF_REF_ERR_BAD_OPTION ((rf_status)14)
/* A metric was asked of zero pixels (empty mask, or no pixel with valid data). */
#define RF_REF_ERR_NO_SAMPLES ((rf_status)15)

/* A sentence describing s, the codes above included; never NULL. */
RF_REFERENCE_EXPORT const char* rf_reference_status_message(rf_status s);

#ifdef __cplusplus
}
#endif

#endif /* RF_REFERENCE_STATUS_H */
