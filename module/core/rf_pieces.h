/* rf_pieces.h: the connected pieces of a polygon mesh, and whether a piece is open as a whole
 * (issue 23: the surface model is decided per connected piece). Polygons that share a point are
 * one piece; the caller says which points are one (the same position: a seam's duplicated
 * points join the pieces they border). No VTK or GL types: the ids are 64-bit, as vtkIdType. */
#ifndef RF_PIECES_H
#define RF_PIECES_H

#include "rf_validate.h"

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* A piece is open as a whole (a thin sheet: a height field, a cut plane, a bowl) when the
 * length of its boundary (edges used by one polygon) is at least this many times the square
 * root of its area; below, it is a solid with small holes (a scan, a contour touching the
 * domain at a few cells). 4 for a square sheet, 2.5 for a hemisphere, 0.18 for a sphere with a
 * cap of a tenth of its radius cut. */
#define RF_OPEN_AS_A_WHOLE 1.0

/* Labels the connected pieces of `polygon_count` polygons over `point_count` points: polygon p
 * has the points connectivity[offsets[p]] .. connectivity[offsets[p + 1] - 1] (offsets has
 * polygon_count + 1 entries, non-decreasing, from 0). point_class (NULL: every point its own)
 * maps each point to the point that stands for it (the first point at its position), an id
 * in [0, point_count) whose own class is itself. keep (NULL: all) leaves out polygon p where keep[p] is 0 (polygons of
 * no area, which join nothing). Writes piece_of_point[i] in [0, *piece_count) for every point
 * i whose class a kept polygon uses, -1 for the others; pieces are numbered in the order of
 * their smallest point class. Runs in about linear time (union-find with path halving).
 * Errors: RF_ERR_NULL_ARGUMENT (offsets, connectivity, piece_of_point or piece_count NULL
 * where needed), RF_ERR_BAD_MESH (a negative count, offsets not non-decreasing from 0, a point
 * id or class outside [0, point_count), a class that is not its own class). On error the outputs are unspecified. */
rf_status rf_pieces_label(int64_t point_count, const int64_t* point_class, int64_t polygon_count,
  const int64_t* offsets, const int64_t* connectivity, const unsigned char* keep,
  int64_t* piece_of_point, int64_t* piece_count);

/* Whether a piece with this boundary length and area is open as a whole:
 * boundary_length >= ratio * sqrt(area) (RF_OPEN_AS_A_WHOLE is the pass's ratio). A piece
 * with no boundary is never open, one with a boundary and no area always is.
 * Errors: RF_ERR_NULL_ARGUMENT, RF_ERR_NOT_FINITE, RF_ERR_BAD_MESH (a negative length,
 * area or ratio). On error *open is left unchanged. */
rf_status rf_pieces_open_as_a_whole(double boundary_length, double area, double ratio, int* open);

#ifdef __cplusplus
}
#endif

#endif /* RF_PIECES_H */
