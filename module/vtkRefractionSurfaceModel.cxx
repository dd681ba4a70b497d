#include "vtkRefractionSurfaceModel.h"

#include "vtkCellArray.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkRefractionMeshes.h"

#include "rf_pieces.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

vtkStandardNewMacro(vtkRefractionSurfaceModel);

namespace
{
// Sheet pieces whose measures the warning quotes.
const size_t kQuotedPieces = 4;

// The squared length of a polygon's area vector (twice its area; a fan from the first point).
double TwiceArea2(vtkPolyData* poly, vtkIdType count, const vtkIdType* ids)
{
  double a[3];
  double b[3];
  double c[3];
  poly->GetPoint(ids[0], a);
  double normal[3] = { 0.0, 0.0, 0.0 };
  for (vtkIdType j = 1; j + 1 < count; ++j)
  {
    poly->GetPoint(ids[j], b);
    poly->GetPoint(ids[j + 1], c);
    const double ab[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const double ac[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    double cross[3];
    vtkMath::Cross(ab, ac, cross);
    for (int k = 0; k < 3; ++k)
    {
      normal[k] += cross[k];
    }
  }
  return vtkMath::Dot(normal, normal);
}

// The largest side of the bounds (not 0).
double Extent(const double bounds[6])
{
  return std::max(
    { bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4], 1e-300 });
}

// Twice the squared area below which a polygon covers nothing (GetMesh).
double MinimumArea2(double extent)
{
  return 1e-24 * extent * extent * extent * extent;
}

// Two pseudo-random 64-bit keys per point from its position quantized to 2^-20 of the
// bounds, so that the duplicated points of a seam share them (GetMesh).
void PositionKeys(vtkPolyData* poly, const double bounds[6], std::vector<std::uint64_t> keys[2])
{
  const double extent = Extent(bounds);
  const vtkIdType numberOfPoints = poly->GetNumberOfPoints();
  keys[0].resize(numberOfPoints);
  keys[1].resize(numberOfPoints);
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    double p[3];
    poly->GetPoint(i, p);
    std::uint64_t key = 0;
    for (int k = 0; k < 3; ++k)
    {
      const double unit = std::min(std::max((p[k] - bounds[2 * k]) / extent, 0.0), 1.0);
      key = (key << 21) | static_cast<std::uint64_t>(std::llround(unit * 1048576.0));
    }
    for (int salt = 0; salt < 2; ++salt)
    {
      std::uint64_t x = key * 0x9E3779B97F4A7C15ULL + static_cast<std::uint64_t>(salt + 1);
      x ^= x >> 31;
      x *= 0xBF58476D1CE4E5B9ULL;
      x ^= x >> 29;
      keys[salt][i] = x;
    }
  }
}

// A mesh's polygons and their connected pieces (points keyed by position, as the closedness
// test keys them; polygons of no area left out and joining nothing).
struct PieceLabels
{
  std::vector<std::int64_t> Offsets{ 0 };
  std::vector<std::int64_t> Connectivity;
  std::vector<unsigned char> Keep; ///< per polygon: 0 for one of no area
  std::vector<double> Areas;       ///< per polygon
  std::vector<std::int64_t> Piece; ///< per point, -1 where no kept polygon uses it
  std::int64_t Pieces = 0;
};

bool LabelPieces(vtkPolyData* poly, const std::vector<std::uint64_t>& keys,
  double minimumArea2, PieceLabels& labels)
{
  const vtkIdType numberOfPoints = poly->GetNumberOfPoints();
  std::vector<std::int64_t> classes(numberOfPoints);
  {
    std::unordered_map<std::uint64_t, std::int64_t> first;
    first.reserve(static_cast<size_t>(numberOfPoints));
    for (vtkIdType i = 0; i < numberOfPoints; ++i)
    {
      classes[i] = first.emplace(keys[i], i).first->second;
    }
  }
  vtkCellArray* polys = poly->GetPolys();
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
  {
    const double area2 = count >= 3 ? TwiceArea2(poly, count, ids) : 0.0;
    labels.Keep.push_back(area2 > minimumArea2 ? 1 : 0);
    labels.Areas.push_back(labels.Keep.back() ? 0.5 * std::sqrt(area2) : 0.0);
    labels.Connectivity.insert(labels.Connectivity.end(), ids, ids + count);
    labels.Offsets.push_back(static_cast<std::int64_t>(labels.Connectivity.size()));
  }
  labels.Piece.resize(numberOfPoints);
  // The validation refuses meshes that fail here before they are drawn.
  return rf_pieces_label(numberOfPoints, classes.data(),
           static_cast<std::int64_t>(labels.Keep.size()), labels.Offsets.data(),
           labels.Connectivity.data(), labels.Keep.data(), labels.Piece.data(),
           &labels.Pieces) == RF_OK &&
    labels.Pieces > 0;
}

// The connected pieces of a mesh with boundary edges, each piece's boundary length (the
// edges used by one polygon) and area, and which pieces are open as a whole.
void MeasurePieces(vtkPolyData* poly, const std::vector<std::uint64_t>& keys,
  double minimumArea2, vtkRefractionSurfaceModel::Mesh& surface)
{
  PieceLabels labels;
  if (!LabelPieces(poly, keys, minimumArea2, labels))
  {
    return;
  }
  const vtkIdType numberOfPoints = poly->GetNumberOfPoints();
  const std::vector<std::int64_t>& offsets = labels.Offsets;
  const std::vector<std::int64_t>& connectivity = labels.Connectivity;
  const std::vector<unsigned char>& keep = labels.Keep;
  const std::vector<double>& areas = labels.Areas;
  const std::vector<std::int64_t>& piece = labels.Piece;
  const std::int64_t pieces = labels.Pieces;
  std::vector<double> length(pieces, 0.0);
  std::vector<double> area(pieces, 0.0);
  struct Edge
  {
    int Uses = 0;
    double Length = 0.0;
    std::int64_t Piece = 0;
  };
  std::unordered_map<std::uint64_t, Edge> edges;
  double b[3];
  double c[3];
  for (size_t p = 0; p < keep.size(); ++p)
  {
    if (!keep[p])
    {
      continue;
    }
    const std::int64_t* cell = connectivity.data() + offsets[p];
    const std::int64_t n = offsets[p + 1] - offsets[p];
    area[piece[cell[0]]] += areas[p];
    for (std::int64_t j = 0; j < n; ++j)
    {
      const std::int64_t from = cell[j];
      const std::int64_t to = cell[(j + 1) % n];
      const std::uint64_t lo = std::min(keys[from], keys[to]);
      const std::uint64_t hi = std::max(keys[from], keys[to]);
      Edge& edge = edges[lo * 0x9E3779B97F4A7C15ULL ^ (hi + 0x632BE59BD9B4E019ULL)];
      ++edge.Uses;
      poly->GetPoint(from, b);
      poly->GetPoint(to, c);
      edge.Length = std::sqrt(vtkMath::Distance2BetweenPoints(b, c));
      edge.Piece = piece[from];
    }
  }
  for (const auto& edge : edges)
  {
    length[edge.second.Piece] += edge.second.Uses == 1 ? edge.second.Length : 0.0;
  }
  std::vector<unsigned char> sheet(pieces, 0);
  surface.Pieces = static_cast<int>(pieces);
  for (std::int64_t k = 0; k < pieces; ++k)
  {
    int open = 0;
    rf_pieces_open_as_a_whole(length[k], area[k], RF_OPEN_AS_A_WHOLE, &open);
    sheet[k] = open ? 1 : 0;
    surface.SmallHoles = surface.SmallHoles || (!open && length[k] > 0.0);
    if (open)
    {
      ++surface.SheetPieces;
      if (surface.SheetMeasures.size() < kQuotedPieces)
      {
        surface.SheetMeasures.emplace_back(length[k], std::sqrt(area[k]));
      }
    }
  }
  if (!surface.Mixed())
  {
    return;
  }
  surface.PointSheet.assign(static_cast<size_t>(numberOfPoints), 0);
  bool first = true;
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    if (piece[i] < 0 || !sheet[piece[i]])
    {
      continue;
    }
    surface.PointSheet[i] = 1;
    poly->GetPoint(i, b);
    for (int k = 0; k < 3; ++k)
    {
      double* range = surface.SheetBounds + 2 * k;
      range[0] = first ? b[k] : std::min(range[0], b[k]);
      range[1] = first ? b[k] : std::max(range[1], b[k]);
    }
    first = false;
  }
}

// Whether the connected pieces of a closed, consistently wound mesh alternate along every
// sight line (vtkRefractionSurfaceModel::Alternates): each piece bounds a solid, so a line
// enters and leaves it by turns; pieces that do not nest bound disjoint solids, so the turns
// hold across them too. A piece inside another (its bounds inside the other's), or wound the
// other way (its signed volume), breaks them.
bool PiecesAlternate(vtkPolyData* poly)
{
  double bounds[6];
  poly->GetBounds(bounds);
  std::vector<std::uint64_t> keys[2];
  PositionKeys(poly, bounds, keys);
  PieceLabels labels;
  if (!LabelPieces(poly, keys[0], MinimumArea2(Extent(bounds)), labels) ||
    labels.Pieces > vtkRefractionSurfaceModel::MaximumAlternatingPieces)
  {
    return false;
  }
  const double centre[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  const size_t pieces = static_cast<size_t>(labels.Pieces);
  std::vector<double> volume(pieces, 0.0);
  for (size_t p = 0; p + 1 < labels.Offsets.size(); ++p)
  {
    const std::int64_t* cell = labels.Connectivity.data() + labels.Offsets[p];
    const std::int64_t n = labels.Offsets[p + 1] - labels.Offsets[p];
    if (!labels.Keep[p] || n < 3)
    {
      continue;
    }
    double a[3];
    double b[3];
    double c[3];
    poly->GetPoint(cell[0], a);
    for (int k = 0; k < 3; ++k)
    {
      a[k] -= centre[k];
    }
    for (std::int64_t j = 1; j + 1 < n; ++j)
    {
      poly->GetPoint(cell[j], b);
      poly->GetPoint(cell[j + 1], c);
      for (int k = 0; k < 3; ++k)
      {
        b[k] -= centre[k];
        c[k] -= centre[k];
      }
      double cross[3];
      vtkMath::Cross(b, c, cross);
      volume[static_cast<size_t>(labels.Piece[cell[0]])] += vtkMath::Dot(a, cross);
    }
  }
  std::vector<double> pieceBounds(6 * pieces);
  std::vector<unsigned char> seen(pieces, 0);
  for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i)
  {
    if (labels.Piece[i] < 0)
    {
      continue;
    }
    const size_t piece = static_cast<size_t>(labels.Piece[i]);
    double* range = pieceBounds.data() + 6 * piece;
    double x[3];
    poly->GetPoint(i, x);
    for (int k = 0; k < 3; ++k)
    {
      range[2 * k] = seen[piece] ? std::min(range[2 * k], x[k]) : x[k];
      range[2 * k + 1] = seen[piece] ? std::max(range[2 * k + 1], x[k]) : x[k];
    }
    seen[piece] = 1;
  }
  for (size_t i = 0; i < pieces; ++i)
  {
    if (!(volume[i] * volume[0] > 0.0))
    {
      return false;
    }
    for (size_t j = 0; j < pieces; ++j)
    {
      const double* inner = pieceBounds.data() + 6 * i;
      const double* outer = pieceBounds.data() + 6 * j;
      bool inside = i != j;
      for (int k = 0; k < 3 && inside; ++k)
      {
        inside = inner[2 * k] >= outer[2 * k] && inner[2 * k + 1] <= outer[2 * k + 1];
      }
      if (inside)
      {
        return false;
      }
    }
  }
  return true;
}
}

//------------------------------------------------------------------------------
bool vtkRefractionSurfaceModel::Alternates(vtkProp* prop)
{
  if (this->AcrossRanks)
  {
    return false; // the ranks' pieces are cut open, and may nest across ranks
  }
  // One mesh: a plain vtkPolyData, or composite data with one visible block that holds
  // polygons (ParaView hands every dataset to its mapper as composite data). Several blocks
  // may nest: not decided.
  const auto blocks = vtkRefractionMeshes::GetBlocks(prop);
  if (blocks.size() != 1 || !blocks[0].Mesh)
  {
    return false;
  }
  vtkPolyData* poly = blocks[0].Mesh;
  this->GetMesh(poly); // brought up to date
  Mesh& surface = this->Meshes[poly];
  if (surface.Alternating < 0)
  {
    if (!surface.AskedBefore)
    {
      // A mesh that changes every frame (re-contoured data) would pay the pieces' labelling
      // (about 0.35 us a point on this project's 2-core machine) at every frame, more than
      // culling saves on a GPU: decided from the second frame the mesh stays the same.
      surface.AskedBefore = true;
      return false;
    }
    surface.Alternating = surface.Closed && PiecesAlternate(poly) ? 1 : 0;
  }
  return surface.Alternating == 1;
}

//------------------------------------------------------------------------------
void vtkRefractionSurfaceModel::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Meshes: " << this->Meshes.size() << "\n";
}

//------------------------------------------------------------------------------
void vtkRefractionSurfaceModel::Prune(size_t keep)
{
  if (this->Meshes.size() > keep)
  {
    this->Meshes.clear();
  }
}

//------------------------------------------------------------------------------
vtkRefractionSurfaceModel::Prop vtkRefractionSurfaceModel::GetProp(vtkProp* prop)
{
  // Composite data: the blocks together. The winding follows their total signed volume; the
  // faces are culled only when every block is closed; the prop is open (a thin sheet) only
  // when every block is (vtkRefractionMaterials says which blocks disagree). A plain mesh
  // whose pieces disagree is decided per piece (PerPiece); a block of composite data whose
  // pieces disagree stays a solid block.
  Prop total;
  double volume = 0.0;
  const bool composite = vtkRefractionMeshes::IsComposite(prop);
  for (const auto& block : vtkRefractionMeshes::GetBlocks(prop))
  {
    const Mesh& surface = this->GetMesh(block.Mesh);
    if (!surface.Polygons)
    {
      continue;
    }
    volume += surface.Volume;
    total.Closed = total.Blocks == 0 ? surface.Closed : total.Closed && surface.Closed;
    total.OpenBlocks += surface.Boundary ? 1 : 0;
    total.MixedBlocks += surface.Mixed() ? 1 : 0;
    if (!composite && surface.Mixed())
    {
      total.PerPiece = block.Mesh;
    }
    ++total.Blocks;
    total.Polygons = true;
  }
  total.WindingSign = volume < 0.0 ? -1 : 1;
  total.Boundary = total.Blocks > 0 && total.OpenBlocks == total.Blocks;
  if (this->AcrossRanks)
  {
    total.Boundary = false;
    total.OpenBlocks = 0;
    total.MixedBlocks = 0;
    total.PerPiece = nullptr;
  }
  return total;
}

//------------------------------------------------------------------------------
const vtkRefractionSurfaceModel::Mesh& vtkRefractionSurfaceModel::GetMesh(vtkPolyData* poly)
{
  auto cached = this->Meshes.find(poly);
  if (cached != this->Meshes.end() && cached->second.Time == poly->GetMTime())
  {
    return cached->second;
  }
  Mesh& surface = this->Meshes[poly];
  surface = Mesh();
  surface.Time = poly->GetMTime();
  // The signed volume of a closed mesh is positive when its polygons wind counter-clockwise
  // seen from outside (the OpenGL front face). Measured about the bounds' centre so that far
  // offset coordinates keep their precision.
  double bounds[6];
  poly->GetBounds(bounds);
  const double centre[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  double volume = 0.0;
  // Closed and consistently oriented: every directed edge a->b has its partner b->a, so a sum
  // of an antisymmetric function of the edges' ends vanishes. The ends are keyed by their
  // position (quantized to 2^-20 of the bounds), not their ids, so that the duplicated points
  // of a seam (a parametric torus, a sphere's poles) pair up as the surface does. Pseudo-random
  // 64-bit values per key and wrapping arithmetic: a boundary edge leaves the sum non-zero
  // (but for a chance of 2^-64); a mesh wound inconsistently counts as open. One pass, no edge
  // table: re-contoured data is checked every time step.
  const double extent = Extent(bounds);
  std::vector<std::uint64_t> keys[2];
  PositionKeys(poly, bounds, keys);
  std::uint64_t edgeSum = 0;
  // Boundary edges, whatever the winding: a symmetric function of the ends, XOR-summed over
  // the edges' uses, vanishes when every edge is used an even number of times.
  std::uint64_t edgeParity = 0;
  vtkCellArray* polys = poly->GetPolys();
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  double a[3];
  double b[3];
  double c[3];
  // Polygons of no area (repeated or collinear points) cover nothing: their edges are left
  // out of both tests, so degenerate slivers do not make a closed surface open (a genuine
  // surface made partly of such slivers would count as open, and be drawn as a thin sheet).
  const double minimumArea2 = MinimumArea2(extent);
  for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
  {
    if (count < 3)
    {
      continue;
    }
    poly->GetPoint(ids[0], a);
    for (int k = 0; k < 3; ++k)
    {
      a[k] -= centre[k];
    }
    double area[3] = { 0.0, 0.0, 0.0 };
    for (vtkIdType j = 1; j + 1 < count; ++j)
    {
      poly->GetPoint(ids[j], b);
      poly->GetPoint(ids[j + 1], c);
      for (int k = 0; k < 3; ++k)
      {
        b[k] -= centre[k];
        c[k] -= centre[k];
      }
      volume += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
        a[2] * (b[0] * c[1] - b[1] * c[0]);
      const double ab[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
      const double ac[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
      area[0] += ab[1] * ac[2] - ab[2] * ac[1];
      area[1] += ab[2] * ac[0] - ab[0] * ac[2];
      area[2] += ab[0] * ac[1] - ab[1] * ac[0];
    }
    double longest2 = 0.0;
    for (vtkIdType j = 0; j < count; ++j)
    {
      poly->GetPoint(ids[j], b);
      poly->GetPoint(ids[(j + 1) % count], c);
      longest2 = std::max(longest2,
        (b[0] - c[0]) * (b[0] - c[0]) + (b[1] - c[1]) * (b[1] - c[1]) + (b[2] - c[2]) * (b[2] - c[2]));
    }
    // Twice the area below 1e-5 of the longest edge squared: a sliver (height under 1e-5 of
    // its base), as collinear points rounded to floats make.
    const double area2 = area[0] * area[0] + area[1] * area[1] + area[2] * area[2];
    if (area2 <= minimumArea2 || area2 <= 1e-10 * longest2 * longest2)
    {
      continue;
    }
    for (vtkIdType j = 0; j < count; ++j)
    {
      const vtkIdType from = ids[j];
      const vtkIdType to = ids[(j + 1) % count];
      edgeSum += keys[0][from] * keys[1][to] - keys[0][to] * keys[1][from];
      edgeParity ^= keys[0][from] * keys[1][to] + keys[0][to] * keys[1][from];
    }
  }
  surface.Volume = volume;
  surface.WindingSign = volume < 0.0 ? -1 : 1;
  surface.Polygons = polys->GetNumberOfCells() > 0 || poly->GetNumberOfStrips() > 0;
  surface.Closed = edgeSum == 0 && poly->GetNumberOfStrips() == 0 && polys->GetNumberOfCells() > 0;
  surface.Boundary = edgeParity != 0 && poly->GetNumberOfStrips() == 0;
  if (surface.Boundary)
  {
    // Open, but how much, and where? A scan with a few small holes, or a contour that touches
    // the domain at a few cells, is a solid with holes; a height field or a bowl is open as a
    // whole. Decided per connected piece, so that a closed piece among open ones stays solid.
    MeasurePieces(poly, keys[0], minimumArea2, surface);
    surface.Boundary = surface.Pieces > 0 && surface.SheetPieces == surface.Pieces;
  }
  return surface;
}
