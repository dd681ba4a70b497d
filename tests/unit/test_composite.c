/* Unit tests of rf_composite: the per-pixel rules that merge two ranks' G-buffers (issue 25),
 * against hand-made pixels, and the property the reduction tree relies on: merging pieces in
 * any grouping gives the G-buffer of the whole. */
#include "rf_composite.h"

#include "rf_test.h"

#include <math.h>
#include <string.h>

static void test_select_nearest(void)
{
  float kept[4] = { 0.5f, 0.5f, 1.0f, NAN };
  const float incoming[4] = { 0.4f, 0.5f, NAN, 0.9f };
  unsigned char take[4];
  CHECK(rf_composite_select(4, RF_COMPOSITE_NEAREST, kept, incoming, 1, take) == RF_OK);
  CHECK(take[0] == 1 && kept[0] == 0.4f);
  CHECK(take[1] == 0); /* a tie keeps the kept (lower) rank's */
  CHECK(take[2] == 0 && kept[2] == 1.0f); /* a NaN never wins */
  CHECK(take[3] == 1 && kept[3] == 0.9f); /* a kept NaN always loses */
}

static void test_select_back(void)
{
  /* RGBA pixels, the key in alpha: -z_view, 0 where no back surface. */
  float kept[12] = { 0, 0, 0, 3.0f, 0, 0, 0, 0.0f, 0, 0, 0, 5.0f };
  const float incoming[12] = { 0, 0, 0, 4.0f, 0, 0, 0, 2.0f, 0, 0, 0, 0.0f };
  float nearest[12];
  unsigned char take[3];
  memcpy(nearest, kept, sizeof kept);
  CHECK(rf_composite_select(3, RF_COMPOSITE_FURTHEST_PRESENT, kept + 3, incoming + 3, 4, take) ==
    RF_OK);
  CHECK(take[0] == 1 && kept[3] == 4.0f);
  CHECK(take[1] == 1 && kept[7] == 2.0f);
  CHECK(take[2] == 0 && kept[11] == 5.0f); /* nothing there never wins */
  CHECK(rf_composite_select(3, RF_COMPOSITE_NEAREST_PRESENT, nearest + 3, incoming + 3, 4, take) ==
    RF_OK);
  CHECK(take[0] == 0 && nearest[3] == 3.0f);
  CHECK(take[1] == 1 && nearest[7] == 2.0f); /* anything beats nothing */
  CHECK(take[2] == 0 && nearest[11] == 5.0f);
}

static void test_copy(void)
{
  const unsigned char take[3] = { 1, 0, 1 };
  const unsigned short incoming[3] = { 7, 8, 9 };
  unsigned short kept[3] = { 1, 2, 3 };
  CHECK(rf_composite_copy(3, sizeof kept[0], take, incoming, kept) == RF_OK);
  CHECK(kept[0] == 7 && kept[1] == 2 && kept[2] == 9);
}

/* One pixel's layers as planes of RGBA (count 1): z in component 2, w the material. */
static void set_layers(float* layers, int count, const float* z, int n)
{
  int l;
  memset(layers, 0, sizeof(float) * 4 * (size_t)count);
  for (l = 0; l < n; ++l)
  {
    layers[4 * l + 2] = z[l];
    layers[4 * l + 3] = (float)(l + 1);
  }
}

static void test_layers(void)
{
  float kept[16];
  float incoming[16];
  const float a[3] = { 1.0f, 3.0f, 6.0f };
  const float b[2] = { 2.0f, 4.0f };
  set_layers(kept, 4, a, 3);
  set_layers(incoming, 4, b, 2);
  CHECK(rf_composite_layers(1, 4, kept, incoming) == RF_OK);
  /* The four nearest of 1 3 6 and 2 4, in order; 6 dropped. */
  CHECK(kept[2] == 1.0f && kept[6] == 2.0f && kept[10] == 3.0f && kept[14] == 4.0f);
  CHECK(kept[7] == 1.0f && kept[15] == 2.0f); /* the incoming layers keep their material */
  {
    /* Two layers are the front and the furthest surface: of 1 (furthest 6) and 2 (furthest
     * 4), 1 and 6, as a capture of all four surfaces on one rank would hold. */
    float two[8];
    float other[8];
    const float c[2] = { 1.0f, 6.0f };
    const float d[2] = { 2.0f, 4.0f };
    set_layers(two, 2, c, 2);
    set_layers(other, 2, d, 2);
    CHECK(rf_composite_layers(1, 2, two, other) == RF_OK);
    CHECK(two[2] == 1.0f && two[6] == 6.0f && two[7] == 2.0f);
    set_layers(two, 2, d, 2);
    set_layers(other, 2, c, 2);
    CHECK(rf_composite_layers(1, 2, two, other) == RF_OK);
    CHECK(two[2] == 1.0f && two[6] == 6.0f && two[3] == 1.0f && two[7] == 2.0f);
  }
  {
    float few[8];
    float none[8];
    const float one[1] = { 5.0f };
    set_layers(few, 2, one, 1);
    set_layers(none, 2, one, 0);
    CHECK(rf_composite_layers(1, 2, few, none) == RF_OK);
    CHECK(few[2] == 5.0f && few[6] == 0.0f && few[7] == 0.0f); /* padded with nothing */
  }
  CHECK(rf_composite_layers(1, 0, kept, incoming) == RF_ERR_EMPTY_RANGE);
  CHECK(rf_composite_layers(1, 9, kept, incoming) == RF_ERR_EMPTY_RANGE);
}

/* Four ranks' single-layer fronts merged ((0,1),(2,3)) then together, against one pass over
 * all four: the tree gives the same nearest front wherever the pieces are. */
static void test_grouping(void)
{
  enum
  {
    PIXELS = 64,
    RANKS = 4
  };
  float depth[RANKS][PIXELS];
  float normal[RANKS][PIXELS];
  unsigned char take[PIXELS];
  int r;
  int i;
  unsigned int seed = 12345u;
  for (r = 0; r < RANKS; ++r)
  {
    for (i = 0; i < PIXELS; ++i)
    {
      seed = seed * 1103515245u + 12345u;
      depth[r][i] = (seed >> 16) % 5 == 0 ? 1.0f : (float)((seed >> 8) % 1000) / 1000.0f;
      normal[r][i] = (float)(r * 1000 + i);
    }
  }
  {
    float flatDepth[PIXELS];
    float flatNormal[PIXELS];
    float treeDepth[RANKS][PIXELS];
    float treeNormal[RANKS][PIXELS];
    memcpy(flatDepth, depth[0], sizeof flatDepth);
    memcpy(flatNormal, normal[0], sizeof flatNormal);
    for (r = 1; r < RANKS; ++r)
    {
      rf_composite_select(PIXELS, RF_COMPOSITE_NEAREST, flatDepth, depth[r], 1, take);
      rf_composite_copy(PIXELS, sizeof(float), take, normal[r], flatNormal);
    }
    memcpy(treeDepth, depth, sizeof treeDepth);
    memcpy(treeNormal, normal, sizeof treeNormal);
    for (r = 0; r < RANKS; r += 2)
    {
      rf_composite_select(PIXELS, RF_COMPOSITE_NEAREST, treeDepth[r], treeDepth[r + 1], 1, take);
      rf_composite_copy(PIXELS, sizeof(float), take, treeNormal[r + 1], treeNormal[r]);
    }
    rf_composite_select(PIXELS, RF_COMPOSITE_NEAREST, treeDepth[0], treeDepth[2], 1, take);
    rf_composite_copy(PIXELS, sizeof(float), take, treeNormal[2], treeNormal[0]);
    CHECK(memcmp(flatDepth, treeDepth[0], sizeof flatDepth) == 0);
    CHECK(memcmp(flatNormal, treeNormal[0], sizeof flatNormal) == 0);
  }
}

static void test_ssp_mask(void)
{
  const float front[3] = { 0.3f, 0.8f, 1.0f };
  const float scene[3] = { 0.5f, 0.5f, 1.0f };
  unsigned char rgba[12] = { 0, 0, 0, 255, 0, 0, 0, 255, 0, 0, 0, 0 };
  CHECK(rf_composite_ssp_mask(3, front, scene, rgba) == RF_OK);
  CHECK(rgba[3] == 191); /* glass in front of an object: 0.25 + 0.5 = 0.75 */
  CHECK(rgba[7] == 255); /* glass behind the object: unchanged */
  CHECK(rgba[11] == 0);  /* no glass: unchanged */
}

static void test_errors(void)
{
  float key[1] = { 0.0f };
  unsigned char take[1];
  CHECK(rf_composite_select(1, RF_COMPOSITE_NEAREST, NULL, key, 1, take) == RF_ERR_NULL_ARGUMENT);
  CHECK(rf_composite_select(1, RF_COMPOSITE_NEAREST, key, key, 0, take) == RF_ERR_EMPTY_RANGE);
  CHECK(rf_composite_select(1, (rf_composite_rule)7, key, key, 1, take) == RF_ERR_EMPTY_RANGE);
  CHECK(rf_composite_copy(1, 4, NULL, key, key) == RF_ERR_NULL_ARGUMENT);
  CHECK(rf_composite_ssp_mask(1, key, key, NULL) == RF_ERR_NULL_ARGUMENT);
}

int main(void)
{
  test_select_nearest();
  test_select_back();
  test_copy();
  test_layers();
  test_grouping();
  test_ssp_mask();
  test_errors();
  return RF_TEST_SUMMARY();
}
