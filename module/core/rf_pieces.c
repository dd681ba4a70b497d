/* rf_pieces.c: connected pieces by union-find (see rf_pieces.h). */
#include "rf_pieces.h"

#include <math.h>
#include <stddef.h>

/* The root of x's set; halves the path on the way (every entry points to a smaller id, so the
 * roots are the smallest ids of their sets). */
static int64_t rf_pieces_find(int64_t* parent, int64_t x)
{
  while (parent[x] != x)
  {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

rf_status rf_pieces_label(int64_t point_count, const int64_t* point_class, int64_t polygon_count,
  const int64_t* offsets, const int64_t* connectivity, const unsigned char* keep,
  int64_t* piece_of_point, int64_t* piece_count)
{
  int64_t p;
  int64_t i;
  int64_t pieces = 0;
  if (piece_count == NULL || (point_count > 0 && piece_of_point == NULL) ||
    (polygon_count > 0 && (offsets == NULL || connectivity == NULL)))
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  if (point_count < 0 || polygon_count < 0 || (polygon_count > 0 && offsets[0] != 0))
  {
    return RF_ERR_BAD_MESH;
  }
  /* piece_of_point holds the union-find parents over the classes first: -1 for a class no
   * kept polygon uses. */
  for (i = 0; i < point_count; ++i)
  {
    piece_of_point[i] = -1;
    if (point_class != NULL && (point_class[i] < 0 || point_class[i] >= point_count ||
                                 point_class[point_class[i]] != point_class[i]))
    {
      return RF_ERR_BAD_MESH;
    }
  }
  for (p = 0; p < polygon_count; ++p)
  {
    int64_t first = -1;
    int64_t j;
    if (offsets[p + 1] < offsets[p])
    {
      return RF_ERR_BAD_MESH;
    }
    for (j = offsets[p]; j < offsets[p + 1]; ++j)
    {
      if (connectivity[j] < 0 || connectivity[j] >= point_count)
      {
        return RF_ERR_BAD_MESH;
      }
    }
    if (keep != NULL && !keep[p])
    {
      continue;
    }
    for (j = offsets[p]; j < offsets[p + 1]; ++j)
    {
      const int64_t c = point_class != NULL ? point_class[connectivity[j]] : connectivity[j];
      int64_t a;
      int64_t b;
      if (piece_of_point[c] < 0)
      {
        piece_of_point[c] = c;
      }
      if (first < 0)
      {
        first = c;
        continue;
      }
      a = rf_pieces_find(piece_of_point, first);
      b = rf_pieces_find(piece_of_point, c);
      /* The larger root joins the smaller: parents stay below their children. */
      if (a < b)
      {
        piece_of_point[b] = a;
      }
      else if (b < a)
      {
        piece_of_point[a] = b;
      }
    }
  }
  /* Ascending, every parent is final before its children: a root takes the next label,
   * stored as -(label + 2) so that it reads apart from the ids and from -1; a child copies
   * its parent's (already its root's) entry. */
  for (i = 0; i < point_count; ++i)
  {
    const int64_t parent = piece_of_point[i];
    if (parent == i)
    {
      piece_of_point[i] = -(pieces + 2);
      ++pieces;
    }
    else if (parent >= 0)
    {
      piece_of_point[i] = piece_of_point[parent];
    }
  }
  for (i = 0; i < point_count; ++i)
  {
    piece_of_point[i] = piece_of_point[i] <= -2 ? -piece_of_point[i] - 2 : -1;
  }
  /* From classes to points: a point takes its class's piece (a class is its own class, so
   * its entry is never overwritten here). */
  if (point_class != NULL)
  {
    for (i = 0; i < point_count; ++i)
    {
      if (point_class[i] != i)
      {
        piece_of_point[i] = piece_of_point[point_class[i]];
      }
    }
  }
  *piece_count = pieces;
  return RF_OK;
}

rf_status rf_pieces_open_as_a_whole(double boundary_length, double area, double ratio, int* open)
{
  if (open == NULL)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  if (!isfinite(boundary_length) || !isfinite(area) || !isfinite(ratio))
  {
    return RF_ERR_NOT_FINITE;
  }
  if (boundary_length < 0.0 || area < 0.0 || ratio < 0.0)
  {
    return RF_ERR_BAD_MESH;
  }
  *open = boundary_length > 0.0 && boundary_length >= ratio * sqrt(area);
  return RF_OK;
}
