#include "vtkRefractionReference.h"

#include "rf_environment_map.h"
#include "rf_tracer.h"
#include "vtkRefractionPass.h"

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkEquirectangularToCubeMapTexture.h>
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
#include <vtkPropCollection.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkTexture.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
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

// One opaque actor in world space with what colours it (rf_opaque_mesh points into it).
struct OpaqueWorldMesh
{
  WorldMesh Geometry;
  std::vector<float> Colours; // scalar colours per vertex or per triangle, or none
  rf_colour_binding Binding = RF_COLOUR_MATERIAL;
  rf_opaque_material Material = {};
};

// An actor's polydata as triangles in world space (the GPU sees the mapper's input through
// the actor's matrix; normals go through the inverse transpose, as VTK's normal matrix), or
// false with a message. The triangulated polydata is kept in `triangulated` (its cell data
// follows the triangles).
bool TriangulateToWorld(vtkActor* actor, vtkPolyData* input, bool useNormals, WorldMesh& world,
  vtkSmartPointer<vtkPolyData>& triangulated, std::string& error)
{
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputData(input);
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  triangulate->Update();
  triangulated = triangulate->GetOutput();
  vtkPoints* points = triangulated->GetPoints();
  const vtkIdType nPoints = points ? points->GetNumberOfPoints() : 0;
  if (nPoints == 0 || triangulated->GetNumberOfPolys() == 0)
  {
    error = "has no triangles after triangulation";
    return false;
  }
  vtkDataArray* normals = useNormals ? triangulated->GetPointData()->GetNormals() : nullptr;
  if (normals && normals->GetNumberOfComponents() != 3)
  {
    normals = nullptr;
  }
  vtkMatrix4x4* matrix = actor->GetMatrix();
  vtkNew<vtkMatrix4x4> normalMatrix;
  vtkMatrix4x4::Invert(matrix, normalMatrix);
  normalMatrix->Transpose();
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
        error = "has a non-finite point (id " + std::to_string(p) + ")";
        return false;
      }
      world.WorldPositions[3 * p + c] = value;
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
  vtkCellArray* polys = triangulated->GetPolys();
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
  return true;
}

// Why an actor cannot be traced as an opaque surface, or "" when it can.
std::string OpaqueUnsupported(vtkRenderer* renderer, vtkActor* actor)
{
  if (!renderer->GetViewProps()->IsItemPresent(actor))
  {
    return "is part of an assembly (its matrix is not its own; e.g. vtkAxesActor)";
  }
  vtkMapper* mapper = actor->GetMapper();
  if (!mapper)
  {
    return "has no mapper";
  }
  mapper->Update();
  if (!vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0)))
  {
    return "has no vtkPolyData input";
  }
  if (actor->GetProperty()->GetOpacity() < 1.0 || actor->HasTranslucentPolygonalGeometry())
  {
    return "is translucent";
  }
  if (actor->GetProperty()->GetRepresentation() != VTK_SURFACE)
  {
    return "is drawn as points or wireframe";
  }
  return "";
}

// The opaque actor's colours: its property's shading parameters, and the mapper's scalar
// colours (unsigned char RGBA from MapScalars, as VTK hands them to GL) per vertex or per
// triangle of the triangulated polydata.
void OpaqueColours(vtkActor* actor, vtkPolyData* triangulated, OpaqueWorldMesh& opaque)
{
  vtkProperty* property = actor->GetProperty();
  rf_opaque_material& m = opaque.Material;
  m.lighting = property->GetLighting() ? 1 : 0;
  m.ambient = property->GetAmbient();
  m.diffuse = property->GetDiffuse();
  m.specular = property->GetSpecular();
  m.specular_power = property->GetSpecularPower();
  property->GetAmbientColor(m.ambient_colour);
  property->GetDiffuseColor(m.diffuse_colour);
  property->GetSpecularColor(m.specular_colour);
  vtkMapper* mapper = actor->GetMapper();
  if (!mapper->GetScalarVisibility())
  {
    return;
  }
  int cellFlag = 0;
  vtkUnsignedCharArray* colours = mapper->MapScalars(triangulated, 1.0, cellFlag);
  if (!colours || colours->GetNumberOfComponents() < 3 || cellFlag > 1)
  {
    return; // no scalars (or field data colours, which VTK draws per cell id: not modelled)
  }
  const vtkIdType expected =
    cellFlag == 1 ? triangulated->GetNumberOfCells() : triangulated->GetNumberOfPoints();
  if (colours->GetNumberOfTuples() != expected)
  {
    return;
  }
  opaque.Binding = cellFlag == 1 ? RF_COLOUR_PER_TRIANGLE : RF_COLOUR_PER_VERTEX;
  const int components = colours->GetNumberOfComponents();
  opaque.Colours.resize(3 * static_cast<size_t>(expected));
  for (vtkIdType i = 0; i < expected; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      opaque.Colours[3 * i + c] = colours->GetValue(components * i + c) / 255.f;
    }
  }
}

// Owns an rf_trace_image for the duration of a trace.
struct ImageHolder
{
  rf_trace_image Image = {};
  ~ImageHolder() { rf_trace_image_free(&this->Image); }
};

// The environment the tracer samples, with the texels it points into.
struct EnvironmentHolder
{
  std::vector<float> Texels[6];
  rf_environment_map Map = {};
  bool Use = false; // false: the built-in environment
};

double SrgbToLinear(double c)
{
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// A 2D image's scalars as linear RGB floats, as a texture with direct scalars hands them to
// GL: floats raw, unsigned 8 and 16 bit normalized (8 bit decoded from sRGB when asked).
bool ImageToRgb(vtkImageData* image, bool srgb, std::vector<float>& rgb, int size[2],
  std::string& error)
{
  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  if (!scalars)
  {
    error = "has no image or no point scalars";
    return false;
  }
  int dims[3];
  image->GetDimensions(dims);
  const int components = scalars->GetNumberOfComponents();
  if (dims[0] < 1 || dims[1] < 1 || dims[2] != 1)
  {
    error = "is not a 2D image";
    return false;
  }
  if (components < 1 || components > 4)
  {
    error = "has " + std::to_string(components) + " components (1 to 4 expected)";
    return false;
  }
  double scale = 1.0;
  switch (scalars->GetDataType())
  {
    case VTK_FLOAT:
    case VTK_DOUBLE:
      srgb = false;
      break;
    case VTK_UNSIGNED_CHAR:
      scale = 1.0 / 255.0;
      break;
    case VTK_UNSIGNED_SHORT:
      scale = 1.0 / 65535.0;
      srgb = false;
      break;
    default:
      error = std::string("has scalars of type ") + scalars->GetDataTypeAsString() +
        " (float, double, unsigned char or unsigned short expected)";
      return false;
  }
  const vtkIdType count = static_cast<vtkIdType>(dims[0]) * dims[1];
  rgb.resize(3 * static_cast<size_t>(count));
  for (vtkIdType i = 0; i < count; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      // Grey images (1 or 2 components) give the same value in every channel.
      double value = scalars->GetComponent(i, components < 3 ? 0 : c) * scale;
      if (!std::isfinite(value))
      {
        error = "has a non-finite texel (id " + std::to_string(i) + ")";
        return false;
      }
      rgb[3 * i + c] = static_cast<float>(srgb ? SrgbToLinear(value) : value);
    }
  }
  size[0] = dims[0];
  size[1] = dims[1];
  return true;
}

// The image on a texture's input port k (a cube map has one port per face), up to date.
vtkImageData* TextureInput(vtkTexture* texture, int k)
{
  if (texture->GetNumberOfInputPorts() <= k || texture->GetNumberOfInputConnections(k) < 1)
  {
    return nullptr;
  }
  if (vtkAlgorithm* producer = texture->GetInputAlgorithm(k, 0))
  {
    producer->Update();
  }
  return vtkImageData::SafeDownCast(texture->GetInputDataObject(k, 0));
}

// Fills env with what the pass samples (see the class comment); false with a message in
// error. A warning is for what the reference cannot reproduce.
bool PrepareEnvironment(vtkRenderer* renderer, vtkImageData* explicitImage,
  EnvironmentHolder& env, std::string& description, std::string& error, std::string& warning)
{
  double up[3];
  double right[3];
  renderer->GetEnvironmentUp(up);
  renderer->GetEnvironmentRight(right);
  if (rf_environment_map_frame(up, right, env.Map.frame) != RF_OK)
  {
    std::ostringstream message;
    message << "The renderer's EnvironmentUp (" << up[0] << ", " << up[1] << ", " << up[2]
      << ") and EnvironmentRight (" << right[0] << ", " << right[1] << ", " << right[2]
      << ") do not span a frame.";
    error = message.str();
    return false;
  }
  env.Map.linear = 1;
  env.Map.repeat = 1;
  std::string problem;
  int size[2] = { 0, 0 };
  if (explicitImage)
  {
    if (!ImageToRgb(explicitImage, false, env.Texels[0], size, problem))
    {
      std::ostringstream message;
      message << "The environment image " << problem << ".";
      error = message.str();
      return false;
    }
    env.Map.layout = RF_ENVIRONMENT_LATLONG;
    env.Map.width = size[0];
    env.Map.height = size[1];
    env.Map.texels[0] = env.Texels[0].data();
    env.Use = true;
    description = "lat-long image " + std::to_string(size[0]) + "x" +
      std::to_string(size[1]) + " (bilinear)";
    return true;
  }
  vtkTexture* texture = renderer->GetEnvironmentTexture();
  if (!texture || !texture->GetCubeMap())
  {
    // What the pass falls back to (it warns about a texture that is not a cube map).
    description = "built-in";
    return true;
  }
  auto* equirectangular = vtkEquirectangularToCubeMapTexture::SafeDownCast(texture);
  vtkTexture* source = equirectangular ? equirectangular->GetInputTexture() : texture;
  if (!source)
  {
    std::ostringstream message;
    message << "The renderer's vtkEquirectangularToCubeMapTexture has no input texture.";
    error = message.str();
    return false;
  }
  const bool srgb = source->GetUseSRGBColorSpace();
  const int images = equirectangular ? 1 : 6;
  for (int k = 0; k < images; ++k)
  {
    vtkImageData* image = TextureInput(source, k);
    int faceSize[2] = { 0, 0 };
    if (!ImageToRgb(image, srgb, env.Texels[k], faceSize, problem))
    {
      std::ostringstream message;
      message << "The renderer's environment texture (input " << k << ") " << problem << ".";
      error = message.str();
      return false;
    }
    if (source->GetColorMode() != VTK_COLOR_MODE_DIRECT_SCALARS &&
      image->GetPointData()->GetScalars()->GetDataType() != VTK_UNSIGNED_CHAR)
    {
      warning = "The renderer's environment texture maps its scalars through a lookup table "
                "(SetColorModeToDirectScalars is not set); the reference uses them as they "
                "are: the pass's colours will differ.";
    }
    if (k > 0 && (faceSize[0] != size[0] || faceSize[1] != size[1]))
    {
      std::ostringstream message;
      message << "The renderer's cube map faces differ in size.";
      error = message.str();
      return false;
    }
    size[0] = faceSize[0];
    size[1] = faceSize[1];
  }
  env.Map.linear = source->GetInterpolate() ? 1 : 0;
  env.Map.repeat = source->GetRepeat() && !source->GetEdgeClamp() ? 1 : 0;
  if (equirectangular)
  {
    rf_environment_map latlong = env.Map;
    latlong.layout = RF_ENVIRONMENT_LATLONG;
    latlong.width = size[0];
    latlong.height = size[1];
    latlong.texels[0] = env.Texels[0].data();
    const int side = equirectangular->GetCubeMapSize();
    float* faces[6];
    std::vector<float> latlongTexels;
    latlongTexels.swap(env.Texels[0]);
    latlong.texels[0] = latlongTexels.data();
    for (int k = 0; k < 6; ++k)
    {
      env.Texels[k].assign(3 * static_cast<size_t>(side) * side, 0.f);
      faces[k] = env.Texels[k].data();
    }
    if (rf_environment_cube_from_latlong(&latlong, side, faces) != RF_OK)
    {
      std::ostringstream message;
      message << "Cannot resample the lat-long environment into a " << side << " cube map.";
      error = message.str();
      return false;
    }
    // VTK renders its cube map with linear filtering whatever the input texture says.
    env.Map.linear = 1;
    size[0] = size[1] = side;
    description = "cube map " + std::to_string(side) +
      " from a lat-long image " + std::to_string(latlong.width) + "x" +
      std::to_string(latlong.height) + " (vtkEquirectangularToCubeMapTexture)";
  }
  else
  {
    if (size[0] != size[1])
    {
      std::ostringstream message;
      message << "The renderer's cube map faces are not square.";
      error = message.str();
      return false;
    }
    description = "cube map " + std::to_string(size[0]) + " (six images)";
  }
  env.Map.layout = RF_ENVIRONMENT_CUBE;
  env.Map.width = size[0];
  env.Map.height = size[1];
  for (int k = 0; k < 6; ++k)
  {
    env.Map.texels[k] = env.Texels[k].data();
  }
  env.Use = true;
  return true;
}

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
void vtkRefractionReference::SetEnvironmentImage(vtkImageData* image)
{
  if (this->EnvironmentImage != image)
  {
    this->EnvironmentImage = image;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkImageData* vtkRefractionReference::GetEnvironmentImage()
{
  return this->EnvironmentImage;
}


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
    WorldMesh world;
    vtkSmartPointer<vtkPolyData> triangulated;
    std::string problem;
    if (!TriangulateToWorld(actor, input, true, world, triangulated, problem))
    {
      vtkErrorMacro("A glass actor's polydata " << problem << ".");
      return false;
    }
    for (size_t i = 0; i < world.WorldPositions.size(); ++i)
    {
      lo[i % 3] = std::min(lo[i % 3], world.WorldPositions[i]);
      hi[i % 3] = std::max(hi[i % 3], world.WorldPositions[i]);
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

  // The opaque scene around the glass: what the pass captures before drawing the glass.
  std::vector<OpaqueWorldMesh> opaqueMeshes;
  if (this->OpaqueActors)
  {
    int skipped = 0;
    std::string firstSkipped;
    actors->InitTraversal(it);
    while (vtkActor* actor = actors->GetNextActor(it))
    {
      if (vtkRefractionPass::IsGlass(actor) || !actor->GetVisibility())
      {
        continue;
      }
      std::string problem = OpaqueUnsupported(renderer, actor);
      OpaqueWorldMesh opaque;
      vtkSmartPointer<vtkPolyData> triangulated;
      vtkPolyData* input = problem.empty()
        ? vtkPolyData::SafeDownCast(actor->GetMapper()->GetInputDataObject(0, 0))
        : nullptr;
      if (input && input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
      {
        continue; // points or lines only: nothing a ray can meet
      }
      if (input &&
        !TriangulateToWorld(actor, input,
          actor->GetProperty()->GetInterpolation() != VTK_FLAT, opaque.Geometry, triangulated,
          problem))
      {
        input = nullptr;
      }
      if (!input)
      {
        if (skipped++ == 0)
        {
          firstSkipped = actor->GetClassName() + std::string(" ") + problem;
        }
        continue;
      }
      OpaqueColours(actor, triangulated, opaque);
      opaqueMeshes.push_back(std::move(opaque));
    }
    if (skipped > 0)
    {
      vtkWarningMacro(<< skipped << " opaque actor(s) left out of the reference (the first: a "
                      << firstSkipped
                      << "); only opaque vtkActors with vtkPolyData surfaces are traced.");
    }
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
  for (OpaqueWorldMesh& opaque : opaqueMeshes)
  {
    WorldMesh& world = opaque.Geometry;
    world.Positions.resize(world.WorldPositions.size());
    for (size_t i = 0; i < world.WorldPositions.size(); ++i)
    {
      world.Positions[i] = static_cast<float>(world.WorldPositions[i] - centre[i % 3]);
    }
    std::vector<double>().swap(world.WorldPositions);
  }
  std::vector<rf_opaque_mesh> opaqueScene(opaqueMeshes.size());
  for (size_t m = 0; m < opaqueMeshes.size(); ++m)
  {
    const OpaqueWorldMesh& opaque = opaqueMeshes[m];
    rf_opaque_mesh& mesh = opaqueScene[m];
    mesh.positions = opaque.Geometry.Positions.data();
    mesh.normals = opaque.Geometry.Normals.empty() ? nullptr : opaque.Geometry.Normals.data();
    mesh.vertex_count = opaque.Geometry.Positions.size() / 3;
    mesh.triangles = opaque.Geometry.Triangles.data();
    mesh.triangle_count = opaque.Geometry.Triangles.size() / 3;
    mesh.colour_binding = opaque.Binding;
    mesh.colours = opaque.Colours.empty() ? nullptr : opaque.Colours.data();
    mesh.material = opaque.Material;
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
  options.samples_per_side = this->SamplesPerSide;
  renderer->GetBackground(options.background);

  EnvironmentHolder environment;
  std::string environmentError;
  std::string environmentWarning;
  if (!PrepareEnvironment(renderer, this->EnvironmentImage, environment,
        this->EnvironmentDescription, environmentError, environmentWarning))
  {
    vtkErrorMacro(<< environmentError);
    return false;
  }
  if (!environmentWarning.empty())
  {
    vtkWarningMacro(<< environmentWarning);
  }
  rf_background_environment background = {};
  if (environment.Use)
  {
    options.environment = rf_environment_map_lookup;
    options.environment_user = &environment.Map;
  }
  else if (this->EnvironmentMode == vtkRefractionPass::ENVIRONMENT_RENDERER)
  {
    // No cube map: the pass shows the renderer's background in the ray's direction.
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        background.world_to_view[3 * r + c] = rfCamera.view[4 * r + c];
      }
    }
    std::copy(rfCamera.projection, rfCamera.projection + 16, background.projection);
    renderer->GetBackground(background.bottom);
    if (renderer->GetGradientBackground())
    {
      renderer->GetBackground2(background.top);
    }
    else
    {
      renderer->GetBackground(background.top);
    }
    options.environment = rf_background_environment_lookup;
    options.environment_user = &background;
    this->EnvironmentDescription = renderer->GetGradientBackground()
      ? "the renderer's gradient background"
      : "the renderer's background";
  }
  options.progress = [](double fraction, void* self) {
    static_cast<vtkRefractionReference*>(self)->InvokeEvent(vtkCommand::ProgressEvent, &fraction);
  };
  options.progress_user = this;

  ImageHolder holder;
  rf_status status = rf_trace_image_alloc(&holder.Image, width, height);
  if (status != RF_OK)
  {
    vtkErrorMacro("Cannot allocate the image: " << rf_reference_status_message(status));
    return false;
  }
  double fraction = 0.0;
  this->InvokeEvent(vtkCommand::StartEvent);
  this->InvokeEvent(vtkCommand::ProgressEvent, &fraction);
  const auto start = std::chrono::steady_clock::now();
  status = rf_trace_scene(meshes.data(), meshes.size(), opaqueScene.data(), opaqueScene.size(),
    &rfCamera, &options, &holder.Image);
  this->TraceSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (status == RF_OK)
  {
    fraction = 1.0;
    this->InvokeEvent(vtkCommand::ProgressEvent, &fraction);
  }
  this->InvokeEvent(vtkCommand::EndEvent);
  if (status != RF_OK)
  {
    vtkErrorMacro("Tracing failed: " << rf_reference_status_message(status));
    return false;
  }

  const vtkIdType count = static_cast<vtkIdType>(width) * height;
  const rf_trace_image& img = holder.Image;
  auto colour = MakeArray("Colour", 3, count);
  auto coverage = MakeArray("Coverage", 1, count);
  auto p1 = MakeArray("P1", 3, count);
  auto p2 = MakeArray("P2", 3, count);
  auto t2 = MakeArray("T2", 3, count);
  auto thickness = MakeArray("Thickness", 1, count);
  auto bounces = MakeArray("Bounces", 1, count);
  auto tir = MakeArray("TIR", 1, count);
  auto hit = MakeArray("Hit", 1, count);
  auto flags = MakeArray("Flags", 1, count);
  auto opaque = MakeArray("Opaque", 1, count);
  std::copy(img.colour, img.colour + 3 * count, colour->GetPointer(0));
  std::copy(img.coverage, img.coverage + count, coverage->GetPointer(0));
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
    opaque->SetValue(i, img.opaque[i]);
  }
  auto output = vtkSmartPointer<vtkImageData>::New();
  output->SetDimensions(width, height, 1);
  for (vtkFloatArray* array : { colour.Get(), coverage.Get(), p1.Get(), p2.Get(), t2.Get(), thickness.Get(),
         bounces.Get(), tir.Get(), hit.Get(), flags.Get(), opaque.Get() })
  {
    output->GetPointData()->AddArray(array);
  }
  this->Output = output;
  this->NumberOfGlassActors = static_cast<int>(worldMeshes.size());
  this->NumberOfTriangles = triangles;
  this->NumberOfOpaqueActors = static_cast<int>(opaqueMeshes.size());
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
  os << indent << "SamplesPerSide: " << this->SamplesPerSide << "\n";
  os << indent << "EnvironmentImage: " << this->EnvironmentImage.Get() << "\n";
  os << indent << "EnvironmentMode: "
     << (this->EnvironmentMode == vtkRefractionPass::ENVIRONMENT_RENDERER ? "renderer" : "builtin")
     << "\n";
  os << indent << "OpaqueActors: " << this->OpaqueActors << "\n";
  os << indent << "NumberOfOpaqueActors: " << this->NumberOfOpaqueActors << "\n";
  os << indent << "EnvironmentDescription: " << this->EnvironmentDescription << "\n";
  os << indent << "GlassDiagonal: " << this->GlassDiagonal << "\n";
  os << indent << "NumberOfGlassActors: " << this->NumberOfGlassActors << "\n";
  os << indent << "NumberOfTriangles: " << this->NumberOfTriangles << "\n";
  os << indent << "TraceSeconds: " << this->TraceSeconds << "\n";
  os << indent << "Output: " << this->Output.Get() << "\n";
}
