/* rf_composite.c: see rf_composite.h. */
#include "rf_composite.h"

#include "rf_peel.h"

#include <math.h>
#include <string.h>

static int incoming_wins(rf_composite_rule rule, float kept, float incoming)
{
  if (isnan(incoming))
  {
    return 0;
  }
  if (isnan(kept))
  {
    return 1;
  }
  switch (rule)
  {
    case RF_COMPOSITE_NEAREST:
      return incoming < kept;
    case RF_COMPOSITE_FURTHEST_PRESENT:
      return incoming > 0.0f && incoming > kept;
    case RF_COMPOSITE_NEAREST_PRESENT:
      return incoming > 0.0f && (kept <= 0.0f || incoming < kept);
  }
  return 0;
}

rf_status rf_composite_select(size_t count, rf_composite_rule rule, float* kept_key,
  const float* incoming_key, size_t stride, unsigned char* take)
{
  size_t i;
  if (!kept_key || !incoming_key || !take)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  if (stride < 1 ||
    (rule != RF_COMPOSITE_NEAREST && rule != RF_COMPOSITE_FURTHEST_PRESENT &&
      rule != RF_COMPOSITE_NEAREST_PRESENT))
  {
    return RF_ERR_EMPTY_RANGE;
  }
  for (i = 0; i < count; ++i)
  {
    const float incoming = incoming_key[i * stride];
    take[i] = (unsigned char)incoming_wins(rule, kept_key[i * stride], incoming);
    if (take[i])
    {
      kept_key[i * stride] = incoming;
    }
  }
  return RF_OK;
}

rf_status rf_composite_copy(size_t count, size_t pixel_bytes, const unsigned char* take,
  const void* incoming, void* kept)
{
  size_t i;
  const unsigned char* from = (const unsigned char*)incoming;
  unsigned char* to = (unsigned char*)kept;
  if (!take || !incoming || !kept)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  for (i = 0; i < count; ++i)
  {
    if (take[i])
    {
      memcpy(to + i * pixel_bytes, from + i * pixel_bytes, pixel_bytes);
    }
  }
  return RF_OK;
}

/* A layer holds a surface when its z is positive (0: cleared, no surface). */
static int layer_present(const float* layer)
{
  return layer[2] > 0.0f;
}

rf_status rf_composite_layers(size_t count, int layers, float* kept, const float* incoming)
{
  size_t i;
  const size_t plane = count * 4;
  if (!kept || !incoming)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  if (layers < 1 || layers > 8)
  {
    return RF_ERR_EMPTY_RANGE;
  }
  for (i = 0; i < count; ++i)
  {
    float merged[16][4];
    float own[8][4];
    int a = 0;
    int b = 0;
    int total = 0;
    int l;
    for (l = 0; l < layers; ++l)
    {
      memcpy(own[l], kept + (size_t)l * plane + i * 4, sizeof own[l]);
    }
    for (;;)
    {
      const int haveA = a < layers && layer_present(own[a]);
      const float* fromB = incoming + (size_t)b * plane + i * 4;
      const int haveB = b < layers && layer_present(fromB);
      if (haveA && (!haveB || own[a][2] <= fromB[2]))
      {
        memcpy(merged[total++], own[a++], sizeof merged[0]);
      }
      else if (haveB)
      {
        memcpy(merged[total++], fromB, sizeof merged[0]);
        ++b;
      }
      else
      {
        break;
      }
    }
    /* Where the last layer holds the furthest surface (rf_peel_last_is_furthest), the
     * union's furthest is one side's last, so the merge is exact. */
    if (rf_peel_last_is_furthest(layers) && total > layers)
    {
      memcpy(merged[layers - 1], merged[total - 1], sizeof merged[0]);
    }
    total = total < layers ? total : layers;
    for (l = 0; l < layers; ++l)
    {
      if (l < total)
      {
        memcpy(kept + (size_t)l * plane + i * 4, merged[l], sizeof merged[l]);
      }
      else
      {
        memset(kept + (size_t)l * plane + i * 4, 0, sizeof merged[l]);
      }
    }
  }
  return RF_OK;
}

rf_status rf_composite_ssp_mask(size_t count, const float* front_depth, const float* scene_depth,
  unsigned char* scene_rgba8)
{
  size_t i;
  if (!front_depth || !scene_depth || !scene_rgba8)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  for (i = 0; i < count; ++i)
  {
    if (front_depth[i] < 1.0f && front_depth[i] <= scene_depth[i])
    {
      /* The blend's arithmetic on bytes: 0.25 * 255 + 0.5 a, rounded as a unorm write. */
      const float a = (float)scene_rgba8[i * 4 + 3] / 255.0f;
      const float masked = 0.25f + 0.5f * a;
      scene_rgba8[i * 4 + 3] = (unsigned char)(masked * 255.0f + 0.5f);
    }
  }
  return RF_OK;
}
