/* rf_peel.h: a ray followed through depth-peeled layers of the glass (Chi, Wang & Hu, seed
 * 004), on the CPU: the checks of the public API around kernel/rf_kernel_peel.h, which the
 * PEEL method's shader runs too.
 *
 * View (camera) space, OpenGL convention: the camera at the origin looking down -z. A layer
 * texel is (x, y) the octahedral normal turned toward the viewer, z the depth -z_view (0:
 * empty), w = +-(material + 1), positive where the surface's outward side faces the viewer;
 * layers sorted by depth at each texel, empty ones last. */
#ifndef RF_PEEL_H
#define RF_PEEL_H

#include "rf_validate.h"
#include "rf_vec3.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Most layers a trace reads (K), interfaces it follows, bounces it may reflect. */
#define RF_PEEL_LAYERS_MAX 8
#define RF_PEEL_INTERFACES_MAX 32
#define RF_PEEL_BOUNCES_MAX 8

/* Writes layer `layer` at texture coordinates tc in [0, 1]^2 (the nearest texel's) to rgba. */
typedef void (*rf_layer_sampler)(void* context, const double tc[2], int layer, double rgba[4]);

typedef struct rf_peel_input
{
  rf_vec3 P1;            /* the entry point on layer 0, view space */
  rf_vec3 T1;            /* the refracted direction inside (need not be unit) */
  int material;          /* the glass entered, 0..materials - 1 */
  int layers;            /* K, 1..RF_PEEL_LAYERS_MAX */
  int interfaces;        /* crossings followed after the entry, 0..RF_PEEL_INTERFACES_MAX */
  int bounces;           /* total internal reflections followed, 0..RF_PEEL_BOUNCES_MAX */
  int tir_clamp;         /* non-zero: past the bounces TIR clamps (the paper), else reflects */
  double extent;         /* longest segment searched (the glass's diagonal), > 0 */
  double depth_range[2]; /* the glass's depths (positive, near to far): nothing beyond */
  double projection[16]; /* view to clip, ROW-MAJOR */
  int viewport[2];       /* the layers' size in texels */
  int parallel;          /* non-zero: a parallel projection */
  const double* ior;     /* per material, > 0 */
  const int* sheet;      /* per material, non-zero: a thin sheet (may be NULL) */
  int materials;         /* entries of ior (and sheet), >= 1 */
} rf_peel_input;

typedef struct rf_peel_result
{
  rf_vec3 P2;           /* where the ray leaves the captured glass */
  rf_vec3 T2;           /* its unit direction there */
  double inside_length; /* the length it travelled inside glass after P1 */
  int bounces;          /* total internal reflections followed */
  int tir_ended;        /* 1 when a reflection past the bounces ended the trace */
} rf_peel_result;

/* The PEEL method's trace exactly as the shader runs it (rfk_peel_trace).
 * Errors: RF_ERR_NULL_ARGUMENT; RF_ERR_NOT_FINITE; RF_ERR_DEGENERATE_DIRECTION (T1 zero);
 * RF_ERR_STEPS_OUT_OF_RANGE (layers, interfaces or bounces outside their ranges, or the
 * material outside the table); RF_ERR_IOR_NOT_POSITIVE; RF_ERR_EMPTY_RANGE (a viewport below
 * 1x1, extent <= 0, or a depth range that is not 0 <= near <= far). On error *result is left unchanged. */
rf_status rf_peel_trace(const rf_peel_input* input, rf_layer_sampler sample, void* context,
  rf_peel_result* result);

/* The interfaces the shader follows with `layers` (K) and `bounces` (rfk_peel_interfaces). */
int rf_peel_interfaces(int layers, int bounces);

/* Non-zero when the last of `layers` (K) peeled layers holds the furthest surface behind the
 * others instead of the next nearest: with K = 2, the two-interface model's exit surface, as
 * DIR's back capture holds it. The capture (vtkRefractionGeometryStage::DrawPeel) and the
 * ranks' merge (rf_composite_layers) follow it. */
int rf_peel_last_is_furthest(int layers);

#ifdef __cplusplus
}
#endif

#endif /* RF_PEEL_H */
