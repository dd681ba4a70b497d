// libFuzzer target over meshes, through the pass's CPU-side code: what a user's vtkPolyData
// (or composite data) meets before anything is drawn. The bytes make a mesh: points from a
// table of values that break numerics (NaN, infinities, zeros of both signs, subnormals, the
// largest and smallest floats) or from a small grid (so that closed and open surfaces, shared
// edges and folds happen), and cells of every kind (vertices, lines, polygons, strips, of
// sizes 0 to 6) whose ids may name points that do not exist. The mesh goes, as glass, through
//  - vtkRefractionGlassChecker::SplitProps (validation: ids in range, cell sizes, finite
//    coordinates within float range, empty data, no polygons), alone and across ranks;
//  - vtkRefractionSurfaceModel (boundary edges, connected pieces, winding, open as a whole);
//  - the reference module's filters a user runs on glass before rendering: vtkISRDistanceFilter
//    (ISR's d_N) and vtkSHTransferFilter (the SH method's transfer), which must refuse what
//    the checker refuses.
// Contracts checked (a violation aborts; a crash is a finding): a prop the checker keeps as
// glass is well formed (fuzz_contract.h: ids in range, polygons and strips of 3 points or
// more, coordinates within float range); a prop it refuses got a message; the surface
// model's figures are sane (pieces >= sheet pieces >= 0, winding +-1, finite volume).
// libFuzzer sees the branches of the module and the reference filters when the build
// instruments all its code (scripts/test.sh's build-asan: clang, -fsanitize=fuzzer-no-link),
// where this target is built with -fsanitize=fuzzer (tests/fuzz/CMakeLists.txt); without
// libFuzzer, fuzz_replay.c replays the kept corpus (corpus-mesh/) through the same function.
#include "fuzz_contract.h"
#include "vtkISRDistanceFilter.h"
#include "vtkRefractionGlassChecker.h"
#include "vtkRefractionPass.h"
#include "vtkRefractionSurfaceModel.h"
#include "vtkSHTransferFilter.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCompositePolyDataMapper2.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProp.h>
#include <vtkRenderState.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <vector>

namespace
{
void Require(bool condition, const char* what)
{
  rfFuzzRequire(condition, "fuzz_mesh", what);
}

struct Bytes
{
  const uint8_t* Data;
  size_t Size;
  uint8_t Take()
  {
    if (this->Size == 0)
    {
      return 0;
    }
    --this->Size;
    return *this->Data++;
  }
};

double Coordinate(Bytes& in)
{
  static const double special[] = { std::numeric_limits<double>::quiet_NaN(),
    std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(), 0.0, -0.0,
    std::numeric_limits<double>::denorm_min(), FLT_MIN, 1e-30, 1e30, FLT_MAX, -FLT_MAX, DBL_MAX,
    1.0 + DBL_EPSILON, 1e-7, 1e7, -1e-12 };
  const uint8_t b = in.Take();
  if (b < sizeof(special) / sizeof(special[0]))
  {
    return special[b];
  }
  // A small grid: points repeat exactly, so surfaces close and edges are shared.
  return (static_cast<double>(in.Take()) - 128.0) / 16.0;
}

vtkIdType PointId(Bytes& in, vtkIdType points)
{
  const uint8_t b = in.Take();
  switch (b)
  {
    case 0:
      return -1;
    case 1:
      return points; // one past the end
    case 2:
      return points + 1000;
    case 3:
      return std::numeric_limits<int>::max();
    case 4:
      return std::numeric_limits<vtkIdType>::min();
    default:
      return points > 0 ? static_cast<vtkIdType>(b % points) : 0;
  }
}

vtkSmartPointer<vtkPolyData> MakeMesh(Bytes& in, bool doublePoints, bool normals)
{
  const vtkIdType pointCount = in.Take() % 65;
  vtkNew<vtkPoints> points;
  points->SetDataType(doublePoints ? VTK_DOUBLE : VTK_FLOAT);
  points->SetNumberOfPoints(pointCount);
  for (vtkIdType i = 0; i < pointCount; ++i)
  {
    const double p[3] = { Coordinate(in), Coordinate(in), Coordinate(in) };
    points->SetPoint(i, p);
  }
  vtkNew<vtkCellArray> kinds[4];
  const int cellCount = in.Take() % 48;
  for (int c = 0; c < cellCount; ++c)
  {
    const uint8_t b = in.Take();
    const int size = (b >> 2) % 7;
    std::vector<vtkIdType> ids(static_cast<size_t>(size));
    for (auto& id : ids)
    {
      id = PointId(in, pointCount);
    }
    kinds[b & 3]->InsertNextCell(size, ids.data());
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetVerts(kinds[0]);
  mesh->SetLines(kinds[1]);
  mesh->SetPolys(kinds[2]);
  mesh->SetStrips(kinds[3]);
  if (normals && pointCount > 0)
  {
    vtkNew<vtkFloatArray> n;
    n->SetNumberOfComponents(3);
    n->SetNumberOfTuples(pointCount);
    for (vtkIdType i = 0; i < pointCount; ++i)
    {
      n->SetTuple3(i, Coordinate(in), Coordinate(in), Coordinate(in));
    }
    mesh->GetPointData()->SetNormals(n);
  }
  return mesh;
}

}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  rfCountingOutputWindow* messages = rfFuzzMessages();
  Bytes in{ data, size };
  const uint8_t flags = in.Take();
  const bool composite = flags & 1;
  const bool acrossRanks = flags & 2;
  const int surfaceModel = ((flags >> 2) & 3) % 3 - 1; // auto, solid, thin sheet
  const bool doublePoints = flags & 16;
  const bool normals = flags & 32;
  const bool filters = flags & 64;

  std::vector<vtkSmartPointer<vtkPolyData>> meshes;
  vtkNew<vtkActor> actor;
  if (composite)
  {
    vtkNew<vtkMultiBlockDataSet> blocks;
    const unsigned int count = 1 + in.Take() % 3;
    blocks->SetNumberOfBlocks(count);
    for (unsigned int b = 0; b < count; ++b)
    {
      meshes.push_back(MakeMesh(in, doublePoints, normals));
      blocks->SetBlock(b, meshes.back());
    }
    vtkNew<vtkCompositePolyDataMapper2> mapper;
    mapper->SetInputDataObject(blocks);
    actor->SetMapper(mapper);
  }
  else
  {
    meshes.push_back(MakeMesh(in, doublePoints, normals));
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(meshes.back());
    actor->SetMapper(mapper);
  }
  Require(vtkRefractionPass::MakeGlass(actor, 1.5), "MakeGlass(1.5) accepted");
  if (surfaceModel != vtkRefractionPass::SURFACE_AUTO)
  {
    vtkRefractionPass::SetSurfaceModel(actor, surfaceModel);
  }

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkProp* props[1] = { actor };
  vtkRenderState state(renderer);
  state.SetPropArrayAndCount(props, 1);
  vtkNew<vtkRefractionGlassChecker> checker;
  std::vector<vtkProp*> glass;
  std::vector<vtkProp*> others;
  const long before = messages->Messages;
  checker->SplitProps(&state, glass, &others, acrossRanks);
  bool allWellFormed = true;
  bool anyPolygons = false;
  vtkIdType cellsTotal = 0;
  for (const auto& mesh : meshes)
  {
    allWellFormed = allWellFormed && rfFuzzWellFormed(mesh);
    anyPolygons = anyPolygons || mesh->GetNumberOfPolys() + mesh->GetNumberOfStrips() > 0;
    cellsTotal += mesh->GetNumberOfCells();
  }
  const bool kept = glass.size() == 1;
  if (kept)
  {
    Require(allWellFormed, "a mesh kept as glass has ids in range and finite points");
  }
  if (!allWellFormed)
  {
    Require(!kept, "a malformed mesh is not kept as glass");
    Require(messages->Messages > before, "a malformed mesh is refused with a message");
  }
  if (!kept && !acrossRanks)
  {
    Require(messages->Messages > before, "glass that is not drawn as glass gets a message");
  }

  if (kept && anyPolygons && cellsTotal > 0)
  {
    vtkNew<vtkRefractionSurfaceModel> model;
    model->SetAcrossRanks(acrossRanks);
    const vtkRefractionSurfaceModel::Prop prop = model->GetProp(actor);
    Require(prop.WindingSign == 1 || prop.WindingSign == -1, "prop winding is +-1");
    Require(prop.OpenBlocks <= prop.Blocks && prop.MixedBlocks <= prop.Blocks,
      "open and mixed blocks are counted among the blocks");
    for (const auto& mesh : meshes)
    {
      const vtkRefractionSurfaceModel::Mesh& m = model->GetMesh(mesh);
      Require(m.WindingSign == 1 || m.WindingSign == -1, "mesh winding is +-1");
      Require(std::isfinite(m.Volume), "signed volume is finite");
      Require(m.SheetPieces >= 0 && m.SheetPieces <= m.Pieces, "0 <= sheet pieces <= pieces");
      Require(m.PointSheet.empty() ||
          m.PointSheet.size() == static_cast<size_t>(mesh->GetNumberOfPoints()),
        "the per-point sheet flags cover the points");
    }
  }

  if (filters)
  {
    // The user's preprocessing of glass: refuses what the checker refuses, never crashes.
    for (const auto& mesh : meshes)
    {
      const long beforeFilter = messages->Messages;
      vtkNew<vtkISRDistanceFilter> distances;
      distances->SetInputData(mesh);
      distances->Update();
      if (!rfFuzzWellFormed(mesh))
      {
        Require(messages->Messages > beforeFilter, "ISR distances refuse a malformed mesh");
      }
      vtkNew<vtkSHTransferFilter> transfer;
      transfer->SetInputData(mesh);
      transfer->SetOrder(2);
      transfer->SetDirections(16);
      transfer->SetMaxBounces(2);
      transfer->SetThreads(1);
      transfer->SetCacheDirectory("");
      const long beforeTransfer = messages->Messages;
      transfer->Update();
      if (!rfFuzzWellFormed(mesh))
      {
        Require(messages->Messages > beforeTransfer, "the SH transfer refuses a malformed mesh");
      }
    }
  }
  return 0;
}
