/* rf_peel.c: the PEEL method's trace through depth-peeled layers (Chi, Wang & Hu, seed 004):
 * validation around kernel/rf_kernel_peel.h. */
#include "rf_peel.h"

#include "kernel/rf_kernel_peel.h"

#include <math.h>
#include <stddef.h>

#if RF_PEEL_MAX_LAYERS != RF_PEEL_LAYERS_MAX
#error "the kernel's layer cap and the validated layer range disagree"
#endif

typedef struct peel_context
{
  rf_layer_sampler sample;
  void* context;
} peel_context;

static rf_float4 sample_layer(void* context, const double tc[2], int layer)
{
  const peel_context* c = (const peel_context*)context;
  double rgba[4] = { 0.0, 0.0, 0.0, 0.0 };
  c->sample(c->context, tc, layer, rgba);
  /* A NaN depth counts as empty. */
  return rf_make4(rgba[0], rgba[1], isfinite(rgba[2]) ? rgba[2] : 0.0, rgba[3]);
}

rf_status rf_peel_trace(const rf_peel_input* input, rf_layer_sampler sample, void* context,
  rf_peel_result* result)
{
  rf_mat4 projection;
  rf_vec3 direction;
  rf_vec3 P2;
  rf_vec3 T2;
  double inside = 0.0;
  int i;
  int flags;
  peel_context wrapped;
  rf_layer_stack layers;
  rf_material_table materials;
  rfk_camera camera;
  if (input == NULL || sample == NULL || result == NULL || input->ior == NULL)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  for (i = 0; i < 16; ++i)
  {
    if (!isfinite(input->projection[i]))
    {
      return RF_ERR_NOT_FINITE;
    }
    projection.m[i] = input->projection[i];
  }
  if (!rf_vec3_is_finite(input->P1) || !rf_vec3_is_finite(input->T1) ||
    !isfinite(input->extent) || !isfinite(input->depth_range[0]) ||
    !isfinite(input->depth_range[1]))
  {
    return RF_ERR_NOT_FINITE;
  }
  if (input->layers < 1 || input->layers > RF_PEEL_LAYERS_MAX || input->interfaces < 0 ||
    input->interfaces > RF_PEEL_INTERFACES_MAX || input->bounces < 0 ||
    input->bounces > RF_PEEL_BOUNCES_MAX || input->materials < 1 || input->material < 0 ||
    input->material >= input->materials)
  {
    return RF_ERR_STEPS_OUT_OF_RANGE;
  }
  for (i = 0; i < input->materials; ++i)
  {
    if (rf_validate_ior(input->ior[i]) != RF_OK)
    {
      return RF_ERR_IOR_NOT_POSITIVE;
    }
  }
  if (input->viewport[0] < 1 || input->viewport[1] < 1 || !(input->extent > 0.0) ||
    !(input->depth_range[0] >= 0.0 && input->depth_range[0] <= input->depth_range[1]))
  {
    return RF_ERR_EMPTY_RANGE;
  }
  direction = rf_vec3_normalize(input->T1);
  if (!(rf_vec3_length(direction) > 0.0))
  {
    return RF_ERR_DEGENERATE_DIRECTION;
  }
  wrapped.sample = sample;
  wrapped.context = context;
  layers.texel = sample_layer;
  layers.context = &wrapped;
  materials.ior = input->ior;
  materials.sheet = input->sheet;
  materials.count = input->materials;
  camera = rfk_make_camera(projection,
    rf_make2((double)input->viewport[0], (double)input->viewport[1]), input->parallel != 0);
  flags = rfk_peel_trace(layers, input->layers, materials, camera, input->P1, direction,
    input->material, input->interfaces, input->bounces,
    input->tir_clamp ? RF_TIR_POLICY_CLAMP : RF_TIR_POLICY_REFLECT, input->extent,
    rf_make2(input->depth_range[0], input->depth_range[1]), RF_ADDR(P2), RF_ADDR(T2),
    RF_ADDR(inside));
  if (!rf_vec3_is_finite(P2) || !rf_vec3_is_finite(T2) || !isfinite(inside))
  {
    return RF_ERR_NOT_FINITE;
  }
  result->P2 = P2;
  result->T2 = T2;
  result->inside_length = inside;
  result->bounces = flags % 16;
  result->tir_ended = flags >= 16 ? 1 : 0;
  return RF_OK;
}

int rf_peel_interfaces(int layers, int bounces)
{
  return rfk_peel_interfaces(layers, bounces);
}

int rf_peel_last_is_furthest(int layers)
{
  /* From three layers on the last as the furthest cost the nested contours 0.1-0.4 dB with
   * four (a ray through two balls left the first through the second's back;
   * docs/benchmark.md). */
  return layers == 2;
}
