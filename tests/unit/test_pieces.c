/* Unit tests of rf_pieces: connected pieces by shared points (and by position classes), and
 * the open-as-a-whole measure against hand-computed shapes. */
#include "rf_pieces.h"

#include "rf_test.h"

#include <math.h>
#include <stddef.h>

/* C99 has no PI. */
#define PI 3.14159265358979323846

/* Two triangles sharing an edge (points 0-3), a lone triangle (4-6), a point in no polygon (7)
 * and a triangle (8-10) that touches the lone one only through a duplicate of point 4 (10). */
static const int64_t kOffsets[] = { 0, 3, 6, 9, 12 };
static const int64_t kConnectivity[] = { 0, 1, 2, 2, 1, 3, 4, 5, 6, 8, 9, 10 };

static void test_labels_by_ids(void)
{
  int64_t piece[11];
  int64_t count = -1;
  CHECK(rf_pieces_label(11, NULL, 4, kOffsets, kConnectivity, NULL, piece, &count) == RF_OK);
  /* By ids alone the duplicate does not join: three pieces, numbered by smallest point. */
  CHECK(count == 3);
  CHECK(piece[0] == 0 && piece[1] == 0 && piece[2] == 0 && piece[3] == 0);
  CHECK(piece[4] == 1 && piece[5] == 1 && piece[6] == 1);
  CHECK(piece[7] == -1);
  CHECK(piece[8] == 2 && piece[9] == 2 && piece[10] == 2);
}

static void test_labels_by_position(void)
{
  /* Point 10 lies where point 4 does: the last triangle joins the lone one. */
  const int64_t classes[] = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 4 };
  int64_t piece[11];
  int64_t count = -1;
  CHECK(rf_pieces_label(11, classes, 4, kOffsets, kConnectivity, NULL, piece, &count) == RF_OK);
  CHECK(count == 2);
  CHECK(piece[0] == 0 && piece[3] == 0);
  CHECK(piece[4] == 1 && piece[6] == 1 && piece[8] == 1 && piece[9] == 1 && piece[10] == 1);
  CHECK(piece[7] == -1);
}

static void test_keep(void)
{
  /* Leaving out the second triangle leaves point 3 in no piece; the first still holds 0-2. */
  const unsigned char keep[] = { 1, 0, 1, 1 };
  int64_t piece[11];
  int64_t count = -1;
  CHECK(rf_pieces_label(11, NULL, 4, kOffsets, kConnectivity, keep, piece, &count) == RF_OK);
  CHECK(count == 3);
  CHECK(piece[0] == 0 && piece[2] == 0 && piece[3] == -1);
}

static void test_chain(void)
{
  /* A strip of 1000 triangles given from its far end: one piece, labelled 0 everywhere (the
   * union-find joins roots in any order). */
  enum { N = 1000 };
  static int64_t offsets[N + 1];
  static int64_t connectivity[3 * N];
  static int64_t piece[N + 2];
  int64_t count = -1;
  int k;
  int all = 1;
  for (k = 0; k < N; ++k)
  {
    const int t = N - 1 - k;
    offsets[k] = 3 * k;
    connectivity[3 * k] = t;
    connectivity[3 * k + 1] = t + 2;
    connectivity[3 * k + 2] = t + 1;
  }
  offsets[N] = 3 * N;
  CHECK(rf_pieces_label(N + 2, NULL, N, offsets, connectivity, NULL, piece, &count) == RF_OK);
  CHECK(count == 1);
  for (k = 0; k < N + 2; ++k)
  {
    all = all && piece[k] == 0;
  }
  CHECK(all);
}

static void test_errors(void)
{
  const int64_t bad_ids[] = { 0, 1, 11, 2, 1, 3, 4, 5, 6, 8, 9, 10 };
  const int64_t bad_offsets[] = { 0, 3, 2, 9, 12 };
  const int64_t own_classes[] = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10 };
  const int64_t chained_class[] = { 0, 0, 1, 3, 4, 5, 6, 7, 8, 9, 10 };
  int64_t piece[11];
  int64_t count = -1;
  CHECK(rf_pieces_label(11, NULL, 4, kOffsets, kConnectivity, NULL, NULL, &count) ==
    RF_ERR_NULL_ARGUMENT);
  CHECK(rf_pieces_label(11, NULL, 4, kOffsets, kConnectivity, NULL, piece, NULL) ==
    RF_ERR_NULL_ARGUMENT);
  CHECK(rf_pieces_label(11, NULL, 4, NULL, kConnectivity, NULL, piece, &count) ==
    RF_ERR_NULL_ARGUMENT);
  CHECK(rf_pieces_label(11, NULL, 4, kOffsets, bad_ids, NULL, piece, &count) == RF_ERR_BAD_MESH);
  CHECK(rf_pieces_label(11, NULL, 4, bad_offsets, kConnectivity, NULL, piece, &count) ==
    RF_ERR_BAD_MESH);
  CHECK(rf_pieces_label(-1, NULL, 0, kOffsets, kConnectivity, NULL, piece, &count) ==
    RF_ERR_BAD_MESH);
  /* Every point its own class: fine; class 1 of point 2 is point 1, whose class is 0: not a
   * class. */
  CHECK(rf_pieces_label(11, own_classes, 4, kOffsets, kConnectivity, NULL, piece, &count) ==
    RF_OK);
  CHECK(rf_pieces_label(11, chained_class, 4, kOffsets, kConnectivity, NULL, piece, &count) ==
    RF_ERR_BAD_MESH);
  /* Nothing at all: no pieces. */
  CHECK(rf_pieces_label(0, NULL, 0, NULL, NULL, NULL, NULL, &count) == RF_OK);
  CHECK(count == 0);
}

static void test_open_as_a_whole(void)
{
  int open = -1;
  /* A unit square sheet: boundary 4, area 1: open. */
  CHECK(rf_pieces_open_as_a_whole(4.0, 1.0, RF_OPEN_AS_A_WHOLE, &open) == RF_OK);
  CHECK(open == 1);
  /* A hemisphere of radius 1: boundary 2 pi, area 2 pi: 2.5 sqrt(area): open. */
  CHECK(rf_pieces_open_as_a_whole(2.0 * PI, 2.0 * PI, RF_OPEN_AS_A_WHOLE, &open) == RF_OK);
  CHECK(open == 1);
  /* A unit sphere with a cap of 10 degrees cut: boundary 2 pi sin(10 deg), area about 4 pi:
   * 0.31 sqrt(area): a solid with a hole. */
  CHECK(rf_pieces_open_as_a_whole(2.0 * PI * sin(PI / 18.0), 4.0 * PI, RF_OPEN_AS_A_WHOLE,
          &open) == RF_OK);
  CHECK(open == 0);
  /* Exactly at the ratio: open; no boundary: closed, whatever the area; a boundary around no
   * area: open. */
  CHECK(rf_pieces_open_as_a_whole(2.0, 4.0, 1.0, &open) == RF_OK && open == 1);
  CHECK(rf_pieces_open_as_a_whole(0.0, 4.0, 1.0, &open) == RF_OK && open == 0);
  CHECK(rf_pieces_open_as_a_whole(0.0, 0.0, 1.0, &open) == RF_OK && open == 0);
  CHECK(rf_pieces_open_as_a_whole(1e-9, 0.0, 1.0, &open) == RF_OK && open == 1);
  open = 7;
  CHECK(rf_pieces_open_as_a_whole(NAN, 1.0, 1.0, &open) == RF_ERR_NOT_FINITE && open == 7);
  CHECK(rf_pieces_open_as_a_whole(1.0, INFINITY, 1.0, &open) == RF_ERR_NOT_FINITE && open == 7);
  CHECK(rf_pieces_open_as_a_whole(-1.0, 1.0, 1.0, &open) == RF_ERR_BAD_MESH && open == 7);
  CHECK(rf_pieces_open_as_a_whole(1.0, 1.0, 1.0, NULL) == RF_ERR_NULL_ARGUMENT);
}

int main(void)
{
  test_labels_by_ids();
  test_labels_by_position();
  test_keep();
  test_chain();
  test_errors();
  test_open_as_a_whole();
  return RF_TEST_SUMMARY();
}
