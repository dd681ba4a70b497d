/* Unit tests of rf_dir_search (paper sections 3.2-3.3) against numbers
 * worked out by hand: the segment and the paper's search (rf_dir_segment_init, rf_dir_cbs),
 * and the whole search as the shader runs it (rf_dir_search, the same kernel source). */
#include "rf_dir_search.h"

#include "rf_test.h"

#include <math.h>
#include <string.h>

/* OpenGL perspective projection, fovy 90 degrees, aspect 1, near 1, far 100,
 * row-major. f = 1 / tan(45 deg) = 1:
 *   [ f/aspect 0  0                0               ]   [ 1 0  0        0       ]
 *   [ 0        f  0                0               ] = [ 0 1  0        0       ]
 *   [ 0        0  (far+near)/(near-far) 2 far near/(near-far) ]  [ 0 0 -101/99 -200/99 ]
 *   [ 0        0  -1               0               ]   [ 0 0 -1        0       ]
 * so a view point p projects to t' = (0.5 p.x / -p.z + 0.5, 0.5 p.y / -p.z + 0.5). */
static void make_projection(double m[16])
{
  const double values[16] = { 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, -101.0 / 99.0,
    -200.0 / 99.0, 0.0, 0.0, -1.0, 0.0 };
  memcpy(m, values, sizeof(values));
}

/* The projection above, written directly (independent of the code under test). */
static void hand_texcoord(rf_vec3 p, double tc[2])
{
  tc[0] = 0.5 * p.x / -p.z + 0.5;
  tc[1] = 0.5 * p.y / -p.z + 0.5;
}

/* The hand-worked ray used throughout:
 *   P1 = (0.1, -0.2, -2), T1 = (0.48, 0.36, -0.8) (unit: 0.2304 + 0.1296 + 0.64 = 1),
 *   depth_min = 4, depth_max = 6, so Zmin = -4, Zmax = -6.
 *   T1 / T1.z = (-0.6, -0.45, 1).
 *   S = P1 + (-4 + 2)(-0.6, -0.45, 1) = P1 + (1.2, 0.9, -2) = (1.3, 0.7, -4)   (eq. 3)
 *   E = P1 + (-6 + 2)(-0.6, -0.45, 1) = P1 + (2.4, 1.8, -4) = (2.5, 1.6, -6)   (eq. 4)
 *   k1 = 1 / S.z = -0.25;  k2 = S.z E.z / (S.z - E.z) = 24 / 2 = 12           (eq. 9)
 *   t'_s = (0.5 * 1.3/4 + 0.5, 0.5 * 0.7/4 + 0.5) = (0.6625, 0.5875)
 *   t'_e = (0.5 * 2.5/6 + 0.5, 0.5 * 1.6/6 + 0.5) = (0.708333..., 0.633333...) (eq. 10)
 * Along it -P.z = 4 + 2 beta (eq. 5), so a back plane at depth d is crossed at
 * beta_true = (d - 4) / 2. */
static const rf_vec3 hand_P1 = { 0.1, -0.2, -2.0 };
static const rf_vec3 hand_T1 = { 0.48, 0.36, -0.8 };
static const double hand_depth_min = 4.0;
static const double hand_depth_max = 6.0;

static rf_dir_segment hand_segment(void)
{
  double projection[16];
  rf_dir_segment seg;
  memset(&seg, 0, sizeof(seg));
  make_projection(projection);
  CHECK(rf_dir_segment_init(hand_P1, hand_T1, hand_depth_min, hand_depth_max, projection, &seg) ==
    RF_OK);
  return seg;
}

static void test_segment_constants(void)
{
  const rf_dir_segment seg = hand_segment();
  CHECK_NEAR(seg.S.x, 1.3, 1e-14);
  CHECK_NEAR(seg.S.y, 0.7, 1e-14);
  CHECK_NEAR(seg.S.z, -4.0, 1e-14);
  CHECK_NEAR(seg.E.x, 2.5, 1e-14);
  CHECK_NEAR(seg.E.y, 1.6, 1e-14);
  CHECK_NEAR(seg.E.z, -6.0, 1e-14);
  CHECK_NEAR(seg.k1, -0.25, 1e-15);
  CHECK_NEAR(seg.k2, 12.0, 1e-14);
  CHECK_NEAR(seg.ts[0], 0.6625, 1e-14);
  CHECK_NEAR(seg.ts[1], 0.5875, 1e-14);
  CHECK_NEAR(seg.te[0], 0.5 * 2.5 / 6.0 + 0.5, 1e-14);
  CHECK_NEAR(seg.te[1], 0.5 * 1.6 / 6.0 + 0.5, 1e-14);

  /* eq. 3-4 only use T1 / T1.z: a non-unit direction gives the same segment. */
  {
    double projection[16];
    rf_dir_segment scaled;
    make_projection(projection);
    CHECK(rf_dir_segment_init(hand_P1, rf_vec3_scale(hand_T1, 3.0), hand_depth_min,
            hand_depth_max, projection, &scaled) == RF_OK);
    CHECK_NEAR(scaled.E.x, 2.5, 1e-14);
    CHECK_NEAR(scaled.k2, 12.0, 1e-14);
  }
}

static void test_alpha_and_texcoords(void)
{
  const rf_dir_segment seg = hand_segment();
  const double betas[] = { 0.0, 0.1, 0.25, 0.5, 0.75, 0.9, 1.0 };
  double tc[2];
  int i;
  /* eq. 9 is 0 at S and 1 at E, exactly. */
  CHECK(rf_dir_alpha(&seg, -4.0) == 0.0);
  CHECK(rf_dir_alpha(&seg, -6.0) == 1.0);
  CHECK(isnan(rf_dir_alpha(NULL, -5.0)));
  /* eq. 10 at alpha = 0 and 1 gives t'_s and t'_e. */
  rf_dir_texcoord(&seg, 0.0, tc);
  CHECK_NEAR(tc[0], 0.6625, 1e-15);
  CHECK_NEAR(tc[1], 0.5875, 1e-15);
  rf_dir_texcoord(&seg, 1.0, tc);
  CHECK_NEAR(tc[0], 0.5 * 2.5 / 6.0 + 0.5, 1e-15);
  CHECK_NEAR(tc[1], 0.5 * 1.6 / 6.0 + 0.5, 1e-15);

  /* The 3D midpoint (beta = 0.5) is P = (1.9, 1.15, -5):
   * alpha = (1/-5 + 0.25) * 12 = 0.6, not 0.5 (perspective), and it projects
   * to (0.5 * 1.9/5 + 0.5, 0.5 * 1.15/5 + 0.5) = (0.69, 0.615). */
  CHECK_NEAR(rf_dir_alpha(&seg, -5.0), 0.6, 1e-14);
  rf_dir_texcoord(&seg, rf_dir_alpha(&seg, -5.0), tc);
  CHECK_NEAR(tc[0], 0.69, 1e-14);
  CHECK_NEAR(tc[1], 0.615, 1e-14);

  /* For any beta, texcoord(alpha(P.z)) is the projection of P itself. */
  for (i = 0; i < (int)(sizeof(betas) / sizeof(betas[0])); ++i)
  {
    const rf_vec3 S = { 1.3, 0.7, -4.0 };
    const rf_vec3 E = { 2.5, 1.6, -6.0 };
    const rf_vec3 P = rf_vec3_add(rf_vec3_scale(S, 1.0 - betas[i]), rf_vec3_scale(E, betas[i]));
    double direct[2];
    hand_texcoord(P, direct);
    rf_dir_texcoord(&seg, rf_dir_alpha(&seg, P.z), tc);
    CHECK_NEAR(tc[0], direct[0], 1e-14);
    CHECK_NEAR(tc[1], direct[1], 1e-14);
  }
}

/* A synthetic depth map: a back plane at `depth` inside a disc of the
 * texture, empty (0) outside, as the first pass would store it. It records
 * the last coordinate it was asked for, and how many times. */
typedef struct disc_depth_map
{
  double center[2];
  double radius;
  double depth;
  int calls;
  double last_tc[2];
} disc_depth_map;

static int inside_disc(const disc_depth_map* map, const double tc[2])
{
  const double dx = tc[0] - map->center[0];
  const double dy = tc[1] - map->center[1];
  return dx * dx + dy * dy <= map->radius * map->radius;
}

static double sample_disc(void* context, const double tc[2])
{
  disc_depth_map* map = (disc_depth_map*)context;
  ++map->calls;
  map->last_tc[0] = tc[0];
  map->last_tc[1] = tc[1];
  return inside_disc(map, tc) ? map->depth : 0.0;
}

static void test_cbs_error_bound(void)
{
  const rf_dir_segment seg = hand_segment();
  const double plane_depths[] = { 4.3, 5.0, 5.3, 5.9 };
  double expected_bound = 1.0;
  int c;
  int p;
  CHECK(rf_cbs_error_bound(5) == 0.03125); /* the paper's 3.125% after 5 steps */
  for (c = 0; c <= 10; ++c)
  {
    CHECK(rf_cbs_error_bound(c) == expected_bound);
    for (p = 0; p < (int)(sizeof(plane_depths) / sizeof(plane_depths[0])); ++p)
    {
      /* The disc (radius 0.4 about the centre) holds the whole segment
       * (t'_s and t'_e are within 0.25 of the centre). */
      disc_depth_map map = { { 0.5, 0.5 }, 0.4, 0.0, 0, { 0.0, 0.0 } };
      const double beta_true = (plane_depths[p] - 4.0) / 2.0;
      rf_vec3 P2;
      double tc[2];
      double direct[2];
      double beta = -1.0;
      map.depth = plane_depths[p];
      CHECK(rf_dir_cbs(&seg, c, sample_disc, &map, &P2, tc, &beta) == RF_OK);
      CHECK(map.calls == c);
      CHECK(fabs(beta - beta_true) <= expected_bound + 1e-12);
      /* Conservative: never past the surface. */
      CHECK(beta <= beta_true + 1e-12);
      /* P2 is the eq. 5 point of beta, and tc its projection. */
      CHECK_NEAR(P2.x, 1.3 + beta * 1.2, 1e-12);
      CHECK_NEAR(P2.y, 0.7 + beta * 0.9, 1e-12);
      CHECK_NEAR(P2.z, -4.0 - beta * 2.0, 1e-12);
      hand_texcoord(P2, direct);
      CHECK_NEAR(tc[0], direct[0], 1e-12);
      CHECK_NEAR(tc[1], direct[1], 1e-12);
    }
    expected_bound *= 0.5;
  }
  /* With 16 steps and the plane at 5 (beta_true = 0.5 exactly, never
   * strictly in front), beta = 0.5 - 2^-16 exactly. */
  {
    disc_depth_map map = { { 0.5, 0.5 }, 0.4, 5.0, 0, { 0.0, 0.0 } };
    rf_vec3 P2;
    double tc[2];
    double beta;
    CHECK(rf_dir_cbs(&seg, 16, sample_disc, &map, &P2, tc, &beta) == RF_OK);
    CHECK(beta == 0.5 - 1.0 / 65536.0);
  }
}

static void test_cbs_is_conservative(void)
{
  /* The disc of radius 0.22 about (0.5, 0.5) contains t'_s (distance
   * sqrt(0.1625^2 + 0.0875^2) = 0.1846) but not t'_e (0.2474): the ray
   * leaves the silhouette before reaching the plane at depth 5.9. */
  const rf_dir_segment seg = hand_segment();
  int c;
  int last_sample_outside = 0;
  for (c = 0; c <= 10; ++c)
  {
    disc_depth_map map = { { 0.5, 0.5 }, 0.22, 5.9, 0, { 0.0, 0.0 } };
    rf_vec3 P2;
    double tc[2];
    double beta;
    CHECK(inside_disc(&map, seg.ts) && !inside_disc(&map, seg.te));
    CHECK(rf_dir_cbs(&seg, c, sample_disc, &map, &P2, tc, &beta) == RF_OK);
    if (c > 0 && !inside_disc(&map, map.last_tc))
    {
      ++last_sample_outside;
    }
    CHECK(inside_disc(&map, tc));
    CHECK(sample_disc(&map, tc) > 0.0);
  }
  /* The scenario does exercise the silhouette: the last sampled candidate
   * (what a plain binary search would return, Figure 6) was often outside. */
  CHECK(last_sample_outside > 0);
}

static void test_zero_steps(void)
{
  const rf_dir_segment seg = hand_segment();
  disc_depth_map map = { { 0.5, 0.5 }, 0.4, 5.0, 0, { 0.0, 0.0 } };
  rf_vec3 P2;
  double tc[2];
  double beta = -1.0;
  CHECK(rf_dir_cbs(&seg, 0, sample_disc, &map, &P2, tc, &beta) == RF_OK);
  CHECK(beta == 0.0);
  CHECK(P2.x == seg.S.x && P2.y == seg.S.y && P2.z == seg.S.z);
  CHECK_NEAR(tc[0], 0.6625, 1e-15);
  CHECK_NEAR(tc[1], 0.5875, 1e-15);
}

static void test_degenerate_inputs(void)
{
  double projection[16];
  rf_dir_segment seg;
  rf_dir_segment untouched;
  const rf_vec3 nan_vector = { NAN, 0.0, -1.0 };
  /* T1 parallel to the image plane (S and E at infinity), zero, or toward the camera. */
  const rf_vec3 degenerate_T1[] = { { 1.0, 0.0, 0.0 }, { 1.0, 0.0, 1e-13 }, { 0.0, 0.0, 0.0 },
    { 0.0, 0.6, 0.8 } };
  size_t d;
  make_projection(projection);
  memset(&seg, 0, sizeof(seg));
  seg.k1 = 123.0; /* sentinel: errors must leave *seg alone */
  for (d = 0; d < sizeof(degenerate_T1) / sizeof(degenerate_T1[0]); ++d)
  {
    CHECK(rf_dir_segment_init(hand_P1, degenerate_T1[d], 4.0, 6.0, projection, &seg) ==
      RF_ERR_DEGENERATE_DIRECTION);
  }
  /* Empty and invalid ranges. */
  CHECK(rf_dir_segment_init(hand_P1, hand_T1, 5.0, 5.0, projection, &seg) == RF_ERR_EMPTY_RANGE);
  CHECK(rf_dir_segment_init(hand_P1, hand_T1, 6.0, 4.0, projection, &seg) == RF_ERR_EMPTY_RANGE);
  CHECK(rf_dir_segment_init(hand_P1, hand_T1, 0.0, 4.0, projection, &seg) == RF_ERR_EMPTY_RANGE);
  /* NaN and infinite inputs. */
  CHECK(rf_dir_segment_init(nan_vector, hand_T1, 4.0, 6.0, projection, &seg) == RF_ERR_NOT_FINITE);
  CHECK(rf_dir_segment_init(hand_P1, nan_vector, 4.0, 6.0, projection, &seg) == RF_ERR_NOT_FINITE);
  CHECK(rf_dir_segment_init(hand_P1, hand_T1, NAN, 6.0, projection, &seg) == RF_ERR_NOT_FINITE);
  CHECK(rf_dir_segment_init(hand_P1, hand_T1, 4.0, INFINITY, projection, &seg) ==
    RF_ERR_NOT_FINITE);
  projection[5] = NAN;
  CHECK(rf_dir_segment_init(hand_P1, hand_T1, 4.0, 6.0, projection, &seg) == RF_ERR_NOT_FINITE);
  make_projection(projection);
  /* A projection whose w = +z puts the range behind the camera plane. */
  projection[14] = 1.0;
  CHECK(rf_dir_segment_init(hand_P1, hand_T1, 4.0, 6.0, projection, &seg) ==
    RF_ERR_DEGENERATE_DIRECTION);
  make_projection(projection);
  /* NULL pointers. */
  CHECK(rf_dir_segment_init(hand_P1, hand_T1, 4.0, 6.0, NULL, &seg) == RF_ERR_NULL_ARGUMENT);
  CHECK(rf_dir_segment_init(hand_P1, hand_T1, 4.0, 6.0, projection, NULL) == RF_ERR_NULL_ARGUMENT);
  CHECK(seg.k1 == 123.0);

  untouched = hand_segment();
  {
    disc_depth_map map = { { 0.5, 0.5 }, 0.4, 5.0, 0, { 0.0, 0.0 } };
    rf_vec3 P2;
    double tc[2];
    double beta;
    CHECK(rf_dir_cbs(NULL, 5, sample_disc, &map, &P2, tc, &beta) == RF_ERR_NULL_ARGUMENT);
    CHECK(rf_dir_cbs(&untouched, 5, NULL, &map, &P2, tc, &beta) == RF_ERR_NULL_ARGUMENT);
    CHECK(rf_dir_cbs(&untouched, 5, sample_disc, &map, NULL, tc, &beta) == RF_ERR_NULL_ARGUMENT);
    CHECK(rf_dir_cbs(&untouched, 5, sample_disc, &map, &P2, NULL, &beta) == RF_ERR_NULL_ARGUMENT);
    CHECK(rf_dir_cbs(&untouched, 5, sample_disc, &map, &P2, tc, NULL) == RF_ERR_NULL_ARGUMENT);
    CHECK(rf_dir_cbs(&untouched, -1, sample_disc, &map, &P2, tc, &beta) ==
      RF_ERR_STEPS_OUT_OF_RANGE);
    CHECK(rf_dir_cbs(&untouched, 17, sample_disc, &map, &P2, tc, &beta) ==
      RF_ERR_STEPS_OUT_OF_RANGE);
    CHECK(map.calls == 0);
  }
}

/* The secant step after the search: exact for a back plane of constant depth (the gap to
 * the stored depth is linear along the ray), from any number of steps >= 1 that leaves a
 * bracket across the plane; unchanged where the far end of the bracket is an empty texel. */
static void test_secant_refinement(void)
{
  const rf_dir_segment seg = hand_segment();
  const double plane_depths[] = { 4.3, 5.3, 5.9 };
  int c;
  int p;
  for (c = 1; c <= 8; ++c)
  {
    for (p = 0; p < (int)(sizeof(plane_depths) / sizeof(plane_depths[0])); ++p)
    {
      disc_depth_map map = { { 0.5, 0.5 }, 0.4, 0.0, 0, { 0.0, 0.0 } };
      const double beta_true = (plane_depths[p] - 4.0) / 2.0;
      rf_vec3 P2;
      double tc[2];
      double beta = -1.0;
      double searched;
      map.depth = plane_depths[p];
      CHECK(rf_dir_cbs(&seg, c, sample_disc, &map, &P2, tc, &beta) == RF_OK);
      searched = beta;
      CHECK(rf_dir_secant_refine(&seg, c, sample_disc, &map, &P2, tc, &beta) == RF_OK);
      if (searched + ldexp(1.0, -c) <= 1.0)
      {
        CHECK_NEAR(beta, beta_true, 1e-9);
        CHECK_NEAR(P2.z, -plane_depths[p], 1e-9);
      }
      else
      {
        CHECK(beta == searched);
      }
    }
  }
  /* The far end of the bracket outside the silhouette: no slope to use, no change. */
  {
    disc_depth_map map = { { 0.5, 0.5 }, 0.22, 5.9, 0, { 0.0, 0.0 } };
    rf_vec3 P2;
    double tc[2];
    double beta;
    double searched;
    CHECK(rf_dir_cbs(&seg, 3, sample_disc, &map, &P2, tc, &beta) == RF_OK);
    searched = beta;
    CHECK(rf_dir_secant_refine(&seg, 3, sample_disc, &map, &P2, tc, &beta) == RF_OK);
    CHECK(beta == searched);
  }
  CHECK(rf_dir_secant_refine(NULL, 3, sample_disc, NULL, NULL, NULL, NULL) == RF_ERR_NULL_ARGUMENT);
}


/* ---- rf_dir_search: the whole exit search the shader runs (rfk_dir_search) ---- */

/* The hand-worked ray on a 64 x 64 map; the options not named (adaptive, secant, parallel)
 * off. */
static rf_dir_search_input hand_search_input(int steps)
{
  rf_dir_search_input in = { .P1 = hand_P1, .T1 = hand_T1, .depth_min = hand_depth_min,
    .depth_max = hand_depth_max, .viewport = { 64, 64 }, .steps = steps };
  make_projection(in.projection);
  return in;
}

/* The paper's search (rf_dir_cbs on the hand segment) and the shader's (rf_dir_search of the
 * hand ray), each `steps` steps over the same depth map. */
typedef struct paper_and_shader
{
  rf_vec3 paper_P2;
  double paper_tc[2];
  double paper_beta;
  rf_dir_search_result shader;
} paper_and_shader;

static paper_and_shader search_both_ways(const rf_dir_segment* seg, int steps,
  disc_depth_map* map)
{
  const rf_dir_search_input in = hand_search_input(steps);
  paper_and_shader both;
  CHECK(rf_dir_cbs(seg, steps, sample_disc, map, &both.paper_P2, both.paper_tc,
          &both.paper_beta) == RF_OK);
  CHECK(rf_dir_search(&in, sample_disc, map, &both.shader) == RF_OK);
  return both;
}

static double sample_constant(void* context, const double tc[2])
{
  (void)tc;
  return *(const double*)context;
}

/* Where S lies on the silhouette and P1 before Zmin, the shader's search is the paper's:
 * the same P2 as rf_dir_cbs on the eq. 3-4 segment, for every step count. */
static void test_search_matches_the_paper_inside(void)
{
  const rf_dir_segment seg = hand_segment();
  int c;
  for (c = 0; c <= 10; ++c)
  {
    disc_depth_map map = { { 0.5, 0.5 }, 0.4, 5.3, 0, { 0.0, 0.0 } };
    const paper_and_shader both = search_both_ways(&seg, c, &map);
    CHECK(both.shader.found == 1);
    CHECK_NEAR(both.shader.P2.x, both.paper_P2.x, 1e-12);
    CHECK_NEAR(both.shader.P2.y, both.paper_P2.y, 1e-12);
    CHECK_NEAR(both.shader.P2.z, both.paper_P2.z, 1e-12);
    CHECK_NEAR(both.shader.tc[0], both.paper_tc[0], 1e-12);
    CHECK_NEAR(both.shader.tc[1], both.paper_tc[1], 1e-12);
  }
}

/* T1 toward the camera: rf_dir_segment_init has no segment (S and E lie behind P1), the shader
 * searches sideways from P1 up to the frustum. P1 = (0, 0, -2), T1 = (0.6, 0, 0.8): the side
 * plane x = -z is reached at 0.6 t = 2 - 0.8 t, t = 1.4286, the near plane -z = 1 first, at
 * t = 1.25, E = (0.75, 0, -1). Behind a back surface at depth 10 everywhere every candidate
 * advances: after c steps P2 = P1 + (1 - 2^-c) 1.25 T1. */
static void test_search_toward_the_camera(void)
{
  double depth = 10.0;
  double projection[16];
  rf_dir_segment seg;
  int c;
  make_projection(projection);
  CHECK(rf_dir_segment_init(rf_vec3_make(0.0, 0.0, -2.0), rf_vec3_make(0.6, 0.0, 0.8), 4.0, 6.0,
          projection, &seg) == RF_ERR_DEGENERATE_DIRECTION);
  for (c = 0; c <= 8; ++c)
  {
    rf_dir_search_input in = hand_search_input(c);
    rf_dir_search_result out;
    const double t = (1.0 - ldexp(1.0, -c)) * 1.25;
    in.P1 = rf_vec3_make(0.0, 0.0, -2.0);
    in.T1 = rf_vec3_make(0.6, 0.0, 0.8);
    in.secant = 1; /* no effect here: the far end of the bracket is never behind the surface */
    CHECK(rf_dir_search(&in, sample_constant, &depth, &out) == RF_OK);
    CHECK(out.found == 1);
    CHECK_NEAR(out.P2.x, 0.6 * t, 1e-12);
    CHECK_NEAR(out.P2.y, 0.0, 1e-12);
    CHECK_NEAR(out.P2.z, -2.0 + 0.8 * t, 1e-12);
  }
}

/* Zmin = Zmax (a flat back facing the camera): rf_dir_segment_init refuses the empty range.
 * The shader's segment shrinks to the point S = (1.9, 1.15, -5) on the plane (hand ray at depth
 * 5), which is no start "before" E, so the search runs from P1 to that point instead: after 5
 * steps P2 = P1 + (31/32)(S - P1) = (1.84375, 1.1078125, -4.90625), in front of the plane. */
static void test_search_flat_range(void)
{
  disc_depth_map map = { { 0.5, 0.5 }, 0.4, 5.0, 0, { 0.0, 0.0 } };
  rf_dir_search_input in = hand_search_input(5);
  rf_dir_search_result out;
  double projection[16];
  double tc[2];
  rf_dir_segment seg;
  make_projection(projection);
  CHECK(rf_dir_segment_init(hand_P1, hand_T1, 5.0, 5.0, projection, &seg) == RF_ERR_EMPTY_RANGE);
  in.depth_min = 5.0;
  in.depth_max = 5.0;
  in.secant = 1; /* the far end lies on the plane, not behind it: no secant step */
  CHECK(rf_dir_search(&in, sample_disc, &map, &out) == RF_OK);
  CHECK(out.found == 1);
  CHECK_NEAR(out.P2.x, 1.84375, 1e-12);
  CHECK_NEAR(out.P2.y, 1.1078125, 1e-12);
  CHECK_NEAR(out.P2.z, -4.90625, 1e-12);
  hand_texcoord(out.P2, tc);
  CHECK_NEAR(out.tc[0], tc[0], 1e-12);
  CHECK_NEAR(out.tc[1], tc[1], 1e-12);
}

/* S outside the silhouette: the back surface covers a disc of radius 0.1 about P1's own texel
 * (0.525, 0.45), not S's (0.6625, 0.5875), 0.194 away. The paper's search from S cannot move
 * (every candidate's texel is empty) and ends on an empty texel; the shader's starts at P1 and
 * ends on the silhouette, in front of the back surface. */
static void test_search_from_P1_when_S_is_outside(void)
{
  const rf_dir_segment seg = hand_segment();
  int moved = 0;
  int c;
  for (c = 1; c <= 8; ++c)
  {
    disc_depth_map map = { { 0.525, 0.45 }, 0.1, 5.9, 0, { 0.0, 0.0 } };
    const paper_and_shader both = search_both_ways(&seg, c, &map);
    const rf_vec3 along = rf_vec3_sub(both.shader.P2, hand_P1);
    CHECK(!inside_disc(&map, both.paper_tc));
    CHECK(inside_disc(&map, both.shader.tc));
    CHECK(-both.shader.P2.z < 5.9);
    /* on the ray, ahead of P1, and off it once there are steps to take */
    CHECK_NEAR(rf_vec3_length(rf_vec3_cross(along, hand_T1)), 0.0, 1e-12);
    CHECK(rf_vec3_dot(along, hand_T1) >= 0.0);
    moved += rf_vec3_dot(along, hand_T1) > 0.0 ? 1 : 0;
  }
  /* the first candidates (half and a quarter of the way) lie outside the disc; finer ones
   * find the part of the ray inside it */
  CHECK(moved >= 5);
}

/* 0 steps: the shader takes no secant step (rf_dir_secant_refine neither, now), so P2 = S. */
static void test_search_zero_steps(void)
{
  const rf_dir_segment seg = hand_segment();
  disc_depth_map map = { { 0.5, 0.5 }, 0.4, 5.0, 0, { 0.0, 0.0 } };
  rf_dir_search_input in = hand_search_input(0);
  rf_dir_search_result out;
  rf_vec3 P2 = seg.S;
  double tc[2] = { seg.ts[0], seg.ts[1] };
  double beta = 0.0;
  in.secant = 1;
  CHECK(rf_dir_search(&in, sample_disc, &map, &out) == RF_OK);
  CHECK(out.P2.x == seg.S.x && out.P2.y == seg.S.y && out.P2.z == seg.S.z);
  CHECK(rf_dir_secant_refine(&seg, 0, sample_disc, &map, &P2, tc, &beta) == RF_OK);
  CHECK(beta == 0.0 && P2.z == seg.S.z);
  /* with one step the secant does move it: a plane at depth 4.6 lies between S (4) and the
   * rejected midpoint (5), and the secant finds it exactly */
  in.steps = 1;
  map.depth = 4.6;
  CHECK(rf_dir_search(&in, sample_disc, &map, &out) == RF_OK);
  CHECK_NEAR(out.P2.z, -4.6, 1e-12);
}

/* The adaptive bound: the hand segment spans t'_e - t'_s = (0.0458, 0.0458), 4.15 texels of a
 * 64 x 64 map, so ceil(log2(2 x 4.15)) = 4 steps bring the bracket under half a texel. */
static void test_search_adaptive_bound(void)
{
  disc_depth_map map = { { 0.5, 0.5 }, 0.4, 5.3, 0, { 0.0, 0.0 } };
  rf_dir_search_input adaptive = hand_search_input(8);
  rf_dir_search_input four = hand_search_input(4);
  rf_dir_search_input eight = hand_search_input(8);
  rf_dir_search_result a;
  rf_dir_search_result b;
  rf_dir_search_result c;
  adaptive.adaptive = 1;
  CHECK(rf_dir_search(&adaptive, sample_disc, &map, &a) == RF_OK);
  CHECK(rf_dir_search(&four, sample_disc, &map, &b) == RF_OK);
  CHECK(rf_dir_search(&eight, sample_disc, &map, &c) == RF_OK);
  CHECK(a.P2.z == b.P2.z);
  CHECK(a.P2.z != c.P2.z);
}

static void test_search_errors(void)
{
  disc_depth_map map = { { 0.5, 0.5 }, 0.4, 5.0, 0, { 0.0, 0.0 } };
  rf_dir_search_input in = hand_search_input(5);
  rf_dir_search_result out;
  rf_dir_search_result untouched;
  memset(&out, 0x5a, sizeof(out));
  untouched = out;
  CHECK(rf_dir_search(NULL, sample_disc, &map, &out) == RF_ERR_NULL_ARGUMENT);
  CHECK(rf_dir_search(&in, NULL, &map, &out) == RF_ERR_NULL_ARGUMENT);
  CHECK(rf_dir_search(&in, sample_disc, &map, NULL) == RF_ERR_NULL_ARGUMENT);
  in.steps = RF_CBS_MAX_STEPS + 1;
  CHECK(rf_dir_search(&in, sample_disc, &map, &out) == RF_ERR_STEPS_OUT_OF_RANGE);
  in = hand_search_input(5);
  in.T1 = rf_vec3_make(0.0, 0.0, 0.0);
  CHECK(rf_dir_search(&in, sample_disc, &map, &out) == RF_ERR_DEGENERATE_DIRECTION);
  in = hand_search_input(5);
  in.depth_max = NAN;
  CHECK(rf_dir_search(&in, sample_disc, &map, &out) == RF_ERR_NOT_FINITE);
  in = hand_search_input(5);
  in.projection[0] = INFINITY;
  CHECK(rf_dir_search(&in, sample_disc, &map, &out) == RF_ERR_NOT_FINITE);
  in = hand_search_input(5);
  in.viewport[1] = 0;
  CHECK(rf_dir_search(&in, sample_disc, &map, &out) == RF_ERR_EMPTY_RANGE);
  CHECK(memcmp(&out, &untouched, sizeof(out)) == 0);
  CHECK(map.calls == 0);
  /* Nothing captured (the reduction's empty answer, Zmin > Zmax): not found, P2 = P1. */
  in = hand_search_input(5);
  in.depth_min = 3e38;
  in.depth_max = 0.0;
  CHECK(rf_dir_search(&in, sample_disc, &map, &out) == RF_OK);
  CHECK(out.found == 0);
  CHECK(out.P2.x == hand_P1.x && out.P2.y == hand_P1.y && out.P2.z == hand_P1.z);
}

int main(void)
{
  test_segment_constants();
  test_alpha_and_texcoords();
  test_cbs_error_bound();
  test_cbs_is_conservative();
  test_secant_refinement();
  test_zero_steps();
  test_degenerate_inputs();
  test_search_matches_the_paper_inside();
  test_search_toward_the_camera();
  test_search_flat_range();
  test_search_from_P1_when_S_is_outside();
  test_search_zero_steps();
  test_search_adaptive_bound();
  test_search_errors();
  return RF_TEST_SUMMARY();
}
