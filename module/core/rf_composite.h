/* rf_composite.h: the per-pixel rules by which the G-buffers that several processes drew of
 * one glass object (each its piece of the data) become the G-buffers one process would have
 * drawn of the whole (issue 25: sort-last glass across MPI ranks). DIR needs at each pixel the
 * nearest front surface and the furthest (or nearest) back surface of the whole object, PEEL
 * its K nearest layers, scene refraction the nearest opaque surface: each is a depth test
 * between two processes' buffers, applied pairwise up a reduction tree. The buffers are
 * "kept" (the receiving process's, updated in place) and "incoming"; on equal keys the kept
 * one stays, so a tree that keeps the lower rank's is deterministic. No VTK or GL types. */
#ifndef RF_COMPOSITE_H
#define RF_COMPOSITE_H

#include "rf_validate.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Which of two keys wins a pixel. */
typedef enum rf_composite_rule
{
  /* The smaller key: depths in window coordinates (front surface, opaque scene). */
  RF_COMPOSITE_NEAREST = 0,
  /* The larger positive key, 0 meaning nothing there: the furthest back surface by its
   * -z_view (BACK_SURFACE's alpha). */
  RF_COMPOSITE_FURTHEST_PRESENT,
  /* The smaller positive key, 0 meaning nothing there: the nearest back surface. */
  RF_COMPOSITE_NEAREST_PRESENT
} rf_composite_rule;

/* For each of `count` pixels, whether the incoming key wins under `rule`: take[i] = 1 and
 * kept_key[i] becomes incoming_key[i], else take[i] = 0. Keys are read with a stride (in
 * floats; 1 for a depth plane, 4 for the alpha of an RGBA plane) and written back with it. A
 * NaN key never wins and a kept NaN is always replaced. Errors: RF_ERR_NULL_ARGUMENT, or
 * RF_ERR_EMPTY_RANGE for a stride below 1 or an unknown rule. */
rf_status rf_composite_select(size_t count, rf_composite_rule rule, float* kept_key,
  const float* incoming_key, size_t stride, unsigned char* take);

/* Copies, for each pixel where take[i] is set, its `pixel_bytes` bytes from incoming to kept:
 * the planes that follow a key (normal, material, colour, ...). */
rf_status rf_composite_copy(size_t count, size_t pixel_bytes, const unsigned char* take,
  const void* incoming, void* kept);

/* Depth-peeled layers: `layers` planes of RGBA floats per buffer (plane l at
 * buffer + l * count * 4), each pixel's layers ordered nearest first by their z component
 * (-z_view, > 0) and ending at the first z of 0 (no surface). Each pixel's kept layers become
 * the `layers` nearest of both lists, in order, padded with zeros, except with two layers
 * (PEEL's capture then: the front and the furthest surface behind it) the nearest and the
 * furthest; on equal z the kept layer comes first. Errors: RF_ERR_NULL_ARGUMENT,
 * RF_ERR_EMPTY_RANGE for layers outside 1..8. */
rf_status rf_composite_layers(size_t count, int layers, float* kept, const float* incoming);

/* The screen-space perturbation method's refraction mask (vtkRefractionGeometryStage::
 * DrawMask, computed here once the front surface and scene are composited): where the glass is
 * the visible surface (front_depth <= scene_depth, and front_depth < 1), the scene's alpha a
 * (RGBA8, byte 3 of each pixel) becomes 0.25 + 0.5 a, as the blend 0.5 * 0.5 + (1 - 0.5) a
 * makes it; elsewhere it stays. Depths are window coordinates. */
rf_status rf_composite_ssp_mask(size_t count, const float* front_depth, const float* scene_depth,
  unsigned char* scene_rgba8);

#ifdef __cplusplus
}
#endif

#endif
