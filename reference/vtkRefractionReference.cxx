#include "vtkRefractionReference.h"

#include "rf_tracer.h"
#include "vtkRefractionPass.h"

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkMapper.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkRefractionReference);

namespace
{
// One glass actor in world space, in the layout rf_mesh points into.
struct WorldMesh
{
  std::vector<double> WorldPositions; // before recentring
  std::vector<float> Positions;       // world space minus the glass's centre
  std::vector<float> Normals;
  std::vector<unsigned> Triangles;
};

// Owns an rf_trace_image for the duration of a trace.
struct ImageHolder
{
  rf_trace_image Image = {};
  ~ImageHolder() { rf_trace_image_free(&this->Image); }
};

vtkSmartPointer<vtkFloatArray> MakeArray(const char* name, int components, vtkIdType tuples)
{
  auto array = vtkSmartPointer<vtkFloatArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  return array;
}
}

//------------------------------------------------------------------------------
vtkRefractionReference::vtkRefractionReference() = default;
vtkRefractionReference::~vtkRefractionReference() = default;

//------------------------------------------------------------------------------
vtkImageData* vtkRefractionReference::GetOutput()
{
  return this->Output;
}

//------------------------------------------------------------------------------
bool vtkRefractionReference::Trace(vtkRenderer* renderer, int width, int height)
{
  if (!renderer)
  {
    vtkErrorMacro("No renderer.");
    return false;
  }
  if (width <= 0 || height <= 0)
  {
    const int* size = renderer->GetSize();
    width = size[0];
    height = size[1];
  }
  if (width <= 0 || height <= 0)
  {
    vtkErrorMacro("Image size " << width << " x " << height
                                << " is empty (no size given and the renderer has none).");
    return false;
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  if (!camera)
  {
    vtkErrorMacro("The renderer has no camera.");
    return false;
  }

  // The glass, moved to world space (the GPU sees the mapper's input through the actor's
  // matrix; normals go through the inverse transpose, as VTK's normal matrix).
  std::vector<WorldMesh> worldMeshes;
  std::vector<double> iors;
  double lo[3] = { std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
    std::numeric_limits<double>::max() };
  double hi[3] = { -lo[0], -lo[1], -lo[2] };
  vtkIdType triangles = 0;
  vtkActorCollection* actors = renderer->GetActors();
  vtkCollectionSimpleIterator it;
  actors->InitTraversal(it);
  while (vtkActor* actor = actors->GetNextActor(it))
  {
    if (!vtkRefractionPass::IsGlass(actor) || !actor->GetVisibility())
    {
      continue;
    }
    vtkMapper* mapper = actor->GetMapper();
    if (!mapper)
    {
      vtkErrorMacro("A glass actor has no mapper.");
      return false;
    }
    mapper->Update();
    vtkPolyData* input = vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0));
    if (!input)
    {
      vtkErrorMacro("A glass actor's mapper has no vtkPolyData input.");
      return false;
    }
    if (input->GetNumberOfPoints() == 0 ||
      input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
    {
      vtkErrorMacro("A glass actor's polydata is empty (no points or no polygons).");
      return false;
    }
    vtkNew<vtkTriangleFilter> triangulate;
    triangulate->SetInputData(input);
    triangulate->PassVertsOff();
    triangulate->PassLinesOff();
    triangulate->Update();
    vtkPolyData* mesh = triangulate->GetOutput();
    vtkPoints* points = mesh->GetPoints();
    const vtkIdType nPoints = points ? points->GetNumberOfPoints() : 0;
    if (nPoints == 0 || mesh->GetNumberOfPolys() == 0)
    {
      vtkErrorMacro("A glass actor's polydata has no triangles after triangulation.");
      return false;
    }
    vtkDataArray* normals = mesh->GetPointData()->GetNormals();
    if (normals && normals->GetNumberOfComponents() != 3)
    {
      normals = nullptr;
    }

    vtkMatrix4x4* matrix = actor->GetMatrix();
    vtkNew<vtkMatrix4x4> normalMatrix;
    vtkMatrix4x4::Invert(matrix, normalMatrix);
    normalMatrix->Transpose();

    WorldMesh world;
    world.WorldPositions.resize(3 * nPoints);
    if (normals)
    {
      world.Normals.resize(3 * nPoints);
    }
    for (vtkIdType p = 0; p < nPoints; ++p)
    {
      double x[4] = { 0.0, 0.0, 0.0, 1.0 };
      points->GetPoint(p, x);
      double w[4];
      matrix->MultiplyPoint(x, w);
      for (int c = 0; c < 3; ++c)
      {
        const double value = w[c] / w[3];
        if (!std::isfinite(value))
        {
          vtkErrorMacro("A glass actor has a non-finite point (id " << p << ").");
          return false;
        }
        world.WorldPositions[3 * p + c] = value;
        lo[c] = std::min(lo[c], value);
        hi[c] = std::max(hi[c], value);
      }
      if (normals)
      {
        double n[4] = { 0.0, 0.0, 0.0, 0.0 };
        normals->GetTuple(p, n);
        double m[4];
        normalMatrix->MultiplyPoint(n, m);
        const double length = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
        for (int c = 0; c < 3; ++c)
        {
          // A zero or broken normal is stored as zero: the tracer then falls back to the
          // triangle's geometric normal.
          const double value = length > 0.0 ? m[c] / length : 0.0;
          world.Normals[3 * p + c] = std::isfinite(value) ? static_cast<float>(value) : 0.f;
        }
      }
    }
    vtkCellArray* polys = mesh->GetPolys();
    world.Triangles.reserve(3 * polys->GetNumberOfCells());
    vtkIdType cellSize = 0;
    const vtkIdType* cell = nullptr;
    for (polys->InitTraversal(); polys->GetNextCell(cellSize, cell);)
    {
      if (cellSize != 3)
      {
        continue;
      }
      for (int k = 0; k < 3; ++k)
      {
        world.Triangles.push_back(static_cast<unsigned>(cell[k]));
      }
    }
    triangles += static_cast<vtkIdType>(world.Triangles.size() / 3);
    worldMeshes.push_back(std::move(world));
    iors.push_back(vtkRefractionPass::GetIndexOfRefraction(actor));
  }
  if (worldMeshes.empty())
  {
    vtkErrorMacro("The renderer has no visible glass actor (vtkRefractionPass::MakeGlass).");
    return false;
  }

  // Embree works in float. Far from the origin (DESIGN.md section 6: coordinates offset by
  // 1e7) float positions would lose the object's shape, while VTK's mappers shift such
  // coordinates before the GPU sees them. So the tracer gets positions relative to the
  // glass's centre, subtracted in double, and a view matrix that adds the centre back.
  double centre[3];
  for (int c = 0; c < 3; ++c)
  {
    centre[c] = 0.5 * (lo[c] + hi[c]);
  }
  for (WorldMesh& world : worldMeshes)
  {
    world.Positions.resize(world.WorldPositions.size());
    for (size_t i = 0; i < world.WorldPositions.size(); ++i)
    {
      world.Positions[i] = static_cast<float>(world.WorldPositions[i] - centre[i % 3]);
    }
    std::vector<double>().swap(world.WorldPositions);
  }

  std::vector<rf_mesh> meshes(worldMeshes.size());
  for (size_t m = 0; m < worldMeshes.size(); ++m)
  {
    const WorldMesh& world = worldMeshes[m];
    meshes[m].positions = world.Positions.data();
    meshes[m].normals = world.Normals.empty() ? nullptr : world.Normals.data();
    meshes[m].vertex_count = world.Positions.size() / 3;
    meshes[m].triangles = world.Triangles.data();
    meshes[m].triangle_count = world.Triangles.size() / 3;
    meshes[m].ior = iors[m];
    for (int c = 0; c < 3; ++c)
    {
      meshes[m].absorption[c] = this->Absorption[c];
    }
  }

  // The matrices vtkOpenGLCamera::GetKeyMatrices starts from (before transposing for GL).
  rf_camera rfCamera;
  rfCamera.width = width;
  rfCamera.height = height;
  vtkMatrix4x4* view = camera->GetViewTransformMatrix();
  vtkMatrix4x4* projection = camera->GetProjectionTransformMatrix(
    static_cast<double>(width) / static_cast<double>(height), -1.0, 1.0);
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      rfCamera.view[4 * r + c] = view->GetElement(r, c);
      rfCamera.projection[4 * r + c] = projection->GetElement(r, c);
    }
    // view * translate(centre): from the recentred positions to view space.
    rfCamera.view[4 * r + 3] += view->GetElement(r, 0) * centre[0] +
      view->GetElement(r, 1) * centre[1] + view->GetElement(r, 2) * centre[2];
  }

  rf_trace_options options;
  rf_trace_options_default(&options);
  options.mode = this->Mode == FULL ? RF_TRACE_FULL : RF_TRACE_TWO_INTERFACE;
  options.tir_clamp = this->TIRClamp ? 1 : 0;
  options.max_depth = this->MaxDepth;
  options.fresnel = this->Fresnel ? 1 : 0;
  options.threads = this->Threads;

  ImageHolder holder;
  rf_status status = rf_trace_image_alloc(&holder.Image, width, height);
  if (status != RF_OK)
  {
    vtkErrorMacro("Cannot allocate the image: " << rf_reference_status_message(status));
    return false;
  }
  const auto start = std::chrono::steady_clock::now();
  status = rf_trace(meshes.data(), meshes.size(), &rfCamera, &options, &holder.Image);
  this->TraceSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (status != RF_OK)
  {
    vtkErrorMacro("Tracing failed: " << rf_reference_status_message(status));
    return false;
  }

  const vtkIdType count = static_cast<vtkIdType>(width) * height;
  const rf_trace_image& img = holder.Image;
  auto colour = MakeArray("Colour", 3, count);
  auto p1 = MakeArray("P1", 3, count);
  auto p2 = MakeArray("P2", 3, count);
  auto t2 = MakeArray("T2", 3, count);
  auto thickness = MakeArray("Thickness", 1, count);
  auto bounces = MakeArray("Bounces", 1, count);
  auto tir = MakeArray("TIR", 1, count);
  auto hit = MakeArray("Hit", 1, count);
  auto flags = MakeArray("Flags", 1, count);
  std::copy(img.colour, img.colour + 3 * count, colour->GetPointer(0));
  std::copy(img.p1, img.p1 + 3 * count, p1->GetPointer(0));
  std::copy(img.p2, img.p2 + 3 * count, p2->GetPointer(0));
  std::copy(img.t2, img.t2 + 3 * count, t2->GetPointer(0));
  std::copy(img.thickness, img.thickness + count, thickness->GetPointer(0));
  for (vtkIdType i = 0; i < count; ++i)
  {
    bounces->SetValue(i, static_cast<float>(img.bounces[i]));
    tir->SetValue(i, img.tir[i]);
    hit->SetValue(i, img.hit[i]);
    flags->SetValue(i, img.hit[i] ? (img.tir[i] ? 2.f : 1.f) : 0.f);
  }
  auto output = vtkSmartPointer<vtkImageData>::New();
  output->SetDimensions(width, height, 1);
  for (vtkFloatArray* array : { colour.Get(), p1.Get(), p2.Get(), t2.Get(), thickness.Get(),
         bounces.Get(), tir.Get(), hit.Get(), flags.Get() })
  {
    output->GetPointData()->AddArray(array);
  }
  this->Output = output;
  this->NumberOfGlassActors = static_cast<int>(worldMeshes.size());
  this->NumberOfTriangles = triangles;
  double diagonal = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    diagonal += (hi[c] - lo[c]) * (hi[c] - lo[c]);
  }
  this->GlassDiagonal = std::sqrt(diagonal);
  return true;
}

//------------------------------------------------------------------------------
void vtkRefractionReference::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mode: " << (this->Mode == FULL ? "FULL" : "TWO_INTERFACE") << "\n";
  os << indent << "TIRClamp: " << this->TIRClamp << "\n";
  os << indent << "MaxDepth: " << this->MaxDepth << "\n";
  os << indent << "Fresnel: " << this->Fresnel << "\n";
  os << indent << "Threads: " << this->Threads << "\n";
  os << indent << "Absorption: " << this->Absorption[0] << " " << this->Absorption[1] << " "
     << this->Absorption[2] << "\n";
  os << indent << "GlassDiagonal: " << this->GlassDiagonal << "\n";
  os << indent << "NumberOfGlassActors: " << this->NumberOfGlassActors << "\n";
  os << indent << "NumberOfTriangles: " << this->NumberOfTriangles << "\n";
  os << indent << "TraceSeconds: " << this->TraceSeconds << "\n";
  os << indent << "Output: " << this->Output.Get() << "\n";
}
