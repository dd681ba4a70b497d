// Composite data as glass (issue 23). Every ParaView surface and every multiblock reader
// hands a vtkCompositeDataSet to a vtkCompositePolyDataMapper2; the glass must not differ
// from the same meshes as single datasets.
//   same_as_actors_M  three spheres (two block colours, one coloured by point scalars through
//                     a lookup table) in front of an opaque wall: one composite actor and three
//                     separate actors give the same picture (>= 40 dB), M = dir sir isr ssp
//                     peel; the spheres' data colours tint the glass (checked on the pixels)
//   partitioned       the same through a vtkPartitionedDataSet
//   nested_blocks     a red block inside a blue one, PEEL: the inner block shows red at the
//                     centre, the rim is blue; the same as two actors (>= 40 dB)
//   open_blocks       two open height-field blocks are drawn as thin sheets as the same two
//                     meshes in separate actors are (>= 40 dB)
//   bad_block         a block with NaN points, and a polydata whose cell names a missing point
//                     (not in a block: VTK 9.1's composite bounds corrupt memory on it):
//                     an error that names the actor (and the block), that glass not drawn, the
//                     opaque wall still drawn, no crash and no GL error
//   hidden_block      a block hidden through the display attributes is left out of the glass
//                     as the mapper leaves it out (the same as the actors without it)
#include "vtkRefractionPass.h"

#include "rfTestRig.h"
#include "rfTestPNG.h"
#include "rfTestScene.h"
#include "rf_metrics.h"
#include "rf_require.h"

#include <vtkActor.h>
#include <vtkCompositeDataDisplayAttributes.h>
#include <vtkCompositePolyDataMapper2.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkLookupTable.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPartitionedDataSet.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace
{
const int kSize = 160;
const double kMinPSNR = 40.0;

struct Part
{
  vtkSmartPointer<vtkPolyData> Mesh;
  double Colour[3];
  bool Scalars;
};

vtkSmartPointer<vtkLookupTable> BlueToRed()
{
  auto lut = vtkSmartPointer<vtkLookupTable>::New();
  lut->SetHueRange(0.66, 0.0);
  lut->SetTableRange(-1.0, 1.0);
  lut->Build();
  return lut;
}

// The sphere's height as point scalars.
void AddHeightScalars(vtkPolyData* poly)
{
  vtkNew<vtkFloatArray> height;
  height->SetName("height");
  for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i)
  {
    height->InsertNextValue(static_cast<float>(poly->GetPoint(i)[1] * 2.0 - 1.6));
  }
  poly->GetPointData()->SetScalars(height);
}

std::vector<Part> ThreeSpheres()
{
  const double a[3] = { -0.9, -0.3, 0.0 };
  const double b[3] = { 0.9, -0.3, 0.0 };
  const double c[3] = { 0.0, 0.8, 0.0 };
  std::vector<Part> parts = { { rftest::SpherePoly(a, 0.6, 48), { 1.0, 0.45, 0.45 }, false },
    { rftest::SpherePoly(b, 0.6, 48), { 0.45, 0.6, 1.0 }, false },
    { rftest::SpherePoly(c, 0.5, 48), { 1.0, 1.0, 1.0 }, true } };
  AddHeightScalars(parts[2].Mesh);
  return parts;
}

// The scene around the glass: an opaque two-colour wall behind, the camera, the pass.
struct Scene
{
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRefractionPass> Pass;
  vtkSmartPointer<vtkRenderWindow> Window;

  explicit Scene(int method)
  {
    const double leftCentre[3] = { -1.25, 0.0, -2.5 };
    const double rightCentre[3] = { 1.25, 0.0, -2.5 };
    const double size[3] = { 2.5, 5.0, 0.1 };
    this->Renderer->AddActor(rftest::FlatActor(rftest::BoxPoly(size, leftCentre), 1.0, 0.55, 0.1));
    this->Renderer->AddActor(rftest::FlatActor(rftest::BoxPoly(size, rightCentre), 0.1, 0.6, 0.55));
    this->Renderer->SetBackground(0.1, 0.1, 0.15);
    this->Pass->SetMethod(method);
    // The tint's distance in world units: the same for one composite actor and its parts.
    this->Pass->SetAbsorptionDistance(1.0);
    this->Renderer->SetPass(this->Pass);
    this->Window = rftest::MakeWindow(this->Renderer, kSize, kSize);
    rftest::LookAtOrigin(this->Renderer, 7.0, 10.0);
  }

  vtkSmartPointer<vtkImageData> Render()
  {
    this->Renderer->ResetCameraClippingRange();
    this->Window->Render();
    return rftest::Grab(this->Window);
  }
};

vtkSmartPointer<vtkActor> CompositeActor(vtkDataObject* data, const std::vector<Part>& parts)
{
  vtkNew<vtkCompositePolyDataMapper2> mapper;
  mapper->SetInputDataObject(data);
  mapper->SetLookupTable(BlueToRed());
  mapper->SetScalarRange(-1.0, 1.0);
  mapper->SetScalarModeToUsePointData();
  mapper->ScalarVisibilityOn();
  vtkNew<vtkCompositeDataDisplayAttributes> attributes;
  mapper->SetCompositeDataDisplayAttributes(attributes);
  for (size_t i = 0; i < parts.size(); ++i)
  {
    if (!parts[i].Scalars)
    {
      mapper->SetBlockColor(static_cast<unsigned int>(i + 1), parts[i].Colour);
    }
  }
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

vtkSmartPointer<vtkActor> PartActor(const Part& part)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(part.Mesh);
  mapper->SetLookupTable(BlueToRed());
  mapper->SetScalarRange(-1.0, 1.0);
  mapper->SetScalarModeToUsePointData();
  mapper->SetScalarVisibility(part.Scalars);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(part.Colour[0], part.Colour[1], part.Colour[2]);
  return actor;
}

vtkSmartPointer<vtkMultiBlockDataSet> Multiblock(const std::vector<Part>& parts)
{
  auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  blocks->SetNumberOfBlocks(static_cast<unsigned int>(parts.size()));
  for (size_t i = 0; i < parts.size(); ++i)
  {
    blocks->SetBlock(static_cast<unsigned int>(i), parts[i].Mesh);
  }
  return blocks;
}


double PSNR(vtkImageData* a, vtkImageData* b)
{
  const std::vector<float> x = rftest::ToColour(a);
  const std::vector<float> y = rftest::ToColour(b);
  const size_t count = x.size() / 3;
  std::vector<unsigned char> all(count, 1);
  double psnr = 0.0;
  RF_REQUIRE(rf_psnr(x.data(), y.data(), count, 3, all.data(), &psnr) == RF_OK, "no PSNR");
  return psnr;
}

// The mean colour of a small square of pixels around (x, y).
void MeanColour(vtkImageData* image, int x, int y, double rgb[3])
{
  rgb[0] = rgb[1] = rgb[2] = 0.0;
  int n = 0;
  for (int dy = -2; dy <= 2; ++dy)
  {
    for (int dx = -2; dx <= 2; ++dx)
    {
      for (int c = 0; c < 3; ++c)
      {
        rgb[c] += image->GetScalarComponentAsDouble(x + dx, y + dy, 0, c);
      }
      ++n;
    }
  }
  for (int c = 0; c < 3; ++c)
  {
    rgb[c] /= n;
  }
}

// Where a world point lands on the window.
void ToPixel(vtkRenderer* renderer, const double world[3], int& x, int& y)
{
  renderer->SetWorldPoint(world[0], world[1], world[2], 1.0);
  renderer->WorldToDisplay();
  double display[3];
  renderer->GetDisplayPoint(display);
  x = static_cast<int>(std::lround(display[0]));
  y = static_cast<int>(std::lround(display[1]));
}

// The picture of `parts` through one composite actor (on `data`) and as separate actors.
int CompareWithActors(int method, vtkDataObject* data, const std::vector<Part>& parts,
  const char* name, vtkSmartPointer<vtkImageData>* compositePicture = nullptr,
  Scene** sceneOut = nullptr)
{
  auto* scene = new Scene(method);
  auto composite = CompositeActor(data, parts);
  vtkRefractionPass::MakeGlass(composite, 1.5);
  rftest::WithoutHighlights(composite);
  scene->Renderer->AddActor(composite);
  auto one = scene->Render();
  scene->Renderer->RemoveActor(composite);
  std::vector<vtkSmartPointer<vtkActor>> actors;
  for (const Part& part : parts)
  {
    actors.push_back(PartActor(part));
    vtkRefractionPass::MakeGlass(actors.back(), 1.5);
    rftest::WithoutHighlights(actors.back());
    scene->Renderer->AddActor(actors.back());
  }
  auto separate = scene->Render();
  rftest::WritePNG(one, std::string(name) + "_composite.png");
  rftest::WritePNG(separate, std::string(name) + "_actors.png");
  const double psnr = PSNR(one, separate);
  const int differing = rftest::DifferingPixels(one, separate, 2);
  std::printf("%s: one composite actor against %zu actors: PSNR %.2f dB, %d pixels differ by "
              "more than 2\n",
    name, parts.size(), psnr, differing);
  // Without the glass the comparison must see a difference (it can fail).
  for (auto& actor : actors)
  {
    actor->VisibilityOff();
  }
  auto none = scene->Render();
  for (auto& actor : actors)
  {
    scene->Renderer->RemoveActor(actor);
  }
  const double psnrNone = PSNR(one, none);
  std::printf("%s: the composite picture against the scene without glass: %.2f dB\n", name,
    psnrNone);
  RF_REQUIRE(psnr >= kMinPSNR, "composite and separate actors differ: %.2f dB (at least %.1f)",
    psnr, kMinPSNR);
  RF_REQUIRE(psnrNone < psnr - 20.0, "the comparison cannot tell glass from none (%.2f dB)",
    psnrNone);
  if (compositePicture)
  {
    *compositePicture = one;
  }
  if (sceneOut)
  {
    *sceneOut = scene;
  }
  else
  {
    delete scene;
  }
  return EXIT_SUCCESS;
}

int SameAsActors(int method, const char* name)
{
  const std::vector<Part> parts = ThreeSpheres();
  auto blocks = Multiblock(parts);
  vtkSmartPointer<vtkImageData> picture;
  Scene* scene = nullptr;
  const int result = CompareWithActors(method, blocks, parts, name, &picture, &scene);
  if (result != EXIT_SUCCESS || method == vtkRefractionPass::SSP)
  {
    delete scene;
    return result;
  }
  // The data's colours tint the glass: the red block reddish, the blue block bluish, the
  // scalar-coloured sphere red at its top and blue at its bottom.
  int x = 0;
  int y = 0;
  double red[3];
  double blue[3];
  const double redCentre[3] = { -0.9, -0.3, 0.6 };
  const double blueCentre[3] = { 0.9, -0.3, 0.6 };
  ToPixel(scene->Renderer, redCentre, x, y);
  MeanColour(picture, x, y, red);
  ToPixel(scene->Renderer, blueCentre, x, y);
  MeanColour(picture, x, y, blue);
  std::printf("%s: red block's centre (%.0f, %.0f, %.0f), blue block's (%.0f, %.0f, %.0f)\n",
    name, red[0], red[1], red[2], blue[0], blue[1], blue[2]);
  delete scene;
  RF_REQUIRE(red[0] - red[2] > blue[0] - blue[2] + 20.0,
    "the blocks' colours do not tint the glass (red block %.0f - %.0f, blue block %.0f - %.0f)",
    red[0], red[2], blue[0], blue[2]);
  return EXIT_SUCCESS;
}

int Partitioned()
{
  const std::vector<Part> parts = ThreeSpheres();
  auto partitions = vtkSmartPointer<vtkPartitionedDataSet>::New();
  partitions->SetNumberOfPartitions(static_cast<unsigned int>(parts.size()));
  for (size_t i = 0; i < parts.size(); ++i)
  {
    partitions->SetPartition(static_cast<unsigned int>(i), parts[i].Mesh);
  }
  return CompareWithActors(vtkRefractionPass::DIR, partitions, parts, "partitioned");
}

int NestedBlocks()
{
  const double centre[3] = { 0.0, 0.0, 0.0 };
  std::vector<Part> parts = { { rftest::SpherePoly(centre, 1.2, 64), { 0.5, 0.65, 1.0 }, false },
    { rftest::SpherePoly(centre, 0.55, 48), { 1.0, 0.25, 0.2 }, false } };
  auto blocks = Multiblock(parts);
  vtkSmartPointer<vtkImageData> picture;
  Scene* scene = nullptr;
  if (CompareWithActors(vtkRefractionPass::PEEL, blocks, parts, "nested_blocks", &picture,
        &scene) != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  // The inner block is told apart: hiding it changes the glass inside the outer one.
  auto composite = CompositeActor(blocks, parts);
  vtkCompositePolyDataMapper2::SafeDownCast(composite->GetMapper())->SetBlockVisibility(2, false);
  vtkRefractionPass::MakeGlass(composite, 1.5);
  rftest::WithoutHighlights(composite);
  scene->Renderer->AddActor(composite);
  auto outerOnly = scene->Render();
  rftest::WritePNG(outerOnly, "nested_blocks_outer_only.png");
  const int changed = rftest::DifferingPixels(picture, outerOnly, 8);
  delete scene;
  std::printf("nested_blocks: hiding the inner block changes %d pixels\n", changed);
  RF_REQUIRE(changed > 200, "the inner block does not show through the outer one (%d pixels)",
    changed);
  return EXIT_SUCCESS;
}

vtkSmartPointer<vtkPolyData> Wave(double z, double phase)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-1.5, -1.5, z);
  plane->SetPoint1(1.5, -1.5, z);
  plane->SetPoint2(-1.5, 1.5, z);
  plane->SetResolution(48, 48);
  plane->Update();
  auto poly = rftest::Detach(plane->GetOutput());
  vtkPoints* points = poly->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    p[2] += 0.15 * std::sin(3.0 * p[0] + phase);
    points->SetPoint(i, p);
  }
  poly->GetPointData()->SetNormals(nullptr);
  return poly;
}

int OpenBlocks()
{
  std::vector<Part> parts = { { Wave(0.4, 0.0), { 1.0, 1.0, 1.0 }, false },
    { Wave(-0.4, 1.0), { 1.0, 1.0, 1.0 }, false } };
  auto blocks = Multiblock(parts);
  vtkSmartPointer<vtkImageData> sheets;
  Scene* scene = nullptr;
  if (CompareWithActors(vtkRefractionPass::DIR, blocks, parts, "open_blocks", &sheets, &scene) !=
    EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  // Taken for sheets, not solids: forced to be a solid, the exit search pairs the first sheet
  // with the second and the picture changes.
  auto composite = CompositeActor(blocks, parts);
  vtkRefractionPass::MakeGlass(composite, 1.5);
  rftest::WithoutHighlights(composite);
  vtkRefractionPass::SetSurfaceModel(composite, vtkRefractionPass::SURFACE_SOLID);
  scene->Renderer->AddActor(composite);
  auto solid = scene->Render();
  delete scene;
  const double psnr = PSNR(sheets, solid);
  std::printf("open_blocks: drawn as sheets against forced solid: %.2f dB\n", psnr);
  RF_REQUIRE(psnr < 35.0, "the open blocks are drawn as a solid (%.2f dB from the solid)", psnr);
  return EXIT_SUCCESS;
}

int HiddenBlock()
{
  std::vector<Part> parts = ThreeSpheres();
  auto blocks = Multiblock(parts);
  Scene scene(vtkRefractionPass::DIR);
  auto composite = CompositeActor(blocks, parts);
  vtkCompositePolyDataMapper2::SafeDownCast(composite->GetMapper())->SetBlockVisibility(2, false);
  vtkRefractionPass::MakeGlass(composite, 1.5);
  rftest::WithoutHighlights(composite);
  scene.Renderer->AddActor(composite);
  auto one = scene.Render();
  scene.Renderer->RemoveActor(composite);
  for (size_t i : { 0u, 2u })
  {
    auto actor = PartActor(parts[i]);
    vtkRefractionPass::MakeGlass(actor, 1.5);
    rftest::WithoutHighlights(actor);
    scene.Renderer->AddActor(actor);
  }
  auto separate = scene.Render();
  const double psnr = PSNR(one, separate);
  std::printf("hidden_block: composite with block 2 hidden against actors without it: %.2f dB\n",
    psnr);
  RF_REQUIRE(psnr >= kMinPSNR, "a hidden block changes the glass: %.2f dB", psnr);
  return EXIT_SUCCESS;
}

int BadBlock()
{
  vtkNew<rftest::MessageLog> log;
  vtkOutputWindow::SetInstance(log);
  Scene scene(vtkRefractionPass::DIR);
  // NaN coordinates in block 3 of a composite actor.
  std::vector<Part> parts = ThreeSpheres();
  parts[2].Mesh->GetPoints()->SetPoint(5, std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0);
  auto blocks = Multiblock(parts);
  auto composite = CompositeActor(blocks, parts);
  vtkRefractionPass::MakeGlass(composite, 1.5);
  rftest::WithoutHighlights(composite);
  scene.Renderer->AddActor(composite);
  auto picture = scene.Render();
  scene.Render();
  const int nan = log->Count("error", { "block 3 of", "NaN, infinite or too large" });
  std::printf("bad_block: %d error(s) naming block 3 and its NaN point\n", nan);
  RF_REQUIRE(nan == 1, "expected one error naming block 3's NaN point (got %d)", nan);
  // The wall is still drawn: its orange half shows where nothing else is.
  double wall[3];
  MeanColour(picture, 10, kSize / 2, wall);
  RF_REQUIRE(wall[0] > 200.0 && wall[2] < 60.0, "the opaque wall is not drawn (%.0f, %.0f, %.0f)",
    wall[0], wall[1], wall[2]);

  // A triangle naming point 3 of 3 (an OBJ face "f 1 2 4" over three vertices). VTK 9.1
  // itself writes one byte per missing id into a byte array of one per point when anything
  // asks for the actor's bounds (vtkPolyData::GetCellsBounds; the renderer does, before any
  // render pass runs): with id 3 that byte lands in the allocation's rounding, with id 99 it
  // corrupts the heap whatever the pass does (valgrind shows both). The pass reads nothing
  // beyond the points: valgrind reports nothing else in this test but two reads in ld.so.
  vtkNew<vtkPolyData> broken;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0.0, 0.0, 0.0);
  points->InsertNextPoint(1.0, 0.0, 0.0);
  points->InsertNextPoint(0.0, 1.0, 0.0);
  broken->SetPoints(points);
  vtkNew<vtkCellArray> triangles;
  const vtkIdType ids[3] = { 0, 1, 3 };
  triangles->InsertNextCell(3, ids);
  broken->SetPolys(triangles);
  auto single = rftest::ActorFor(broken);
  vtkRefractionPass::MakeGlass(single, 1.5);
  rftest::WithoutHighlights(single);
  scene.Renderer->RemoveActor(composite);
  scene.Renderer->AddActor(single);
  picture = scene.Render();
  scene.Render();
  const int missing = log->Count("error", { "its data has a polygon cell naming point 3 of 3" });
  std::printf("bad_block: %d error(s) naming the missing point\n", missing);
  RF_REQUIRE(missing == 1, "expected one error naming point 3 (got %d)", missing);
  MeanColour(picture, 10, kSize / 2, wall);
  RF_REQUIRE(wall[0] > 200.0 && wall[2] < 60.0, "the opaque wall is not drawn (%.0f, %.0f, %.0f)",
    wall[0], wall[1], wall[2]);
  vtkOutputWindow::SetInstance(nullptr);
  return EXIT_SUCCESS;
}
}

int main(int argc, char* argv[])
{
  const std::string name = argc > 1 ? argv[1] : "";
  const struct
  {
    const char* Name;
    int Method;
  } methods[] = { { "same_as_actors_dir", vtkRefractionPass::DIR },
    { "same_as_actors_sir", vtkRefractionPass::SIR },
    { "same_as_actors_isr", vtkRefractionPass::ISR },
    { "same_as_actors_ssp", vtkRefractionPass::SSP },
    { "same_as_actors_peel", vtkRefractionPass::PEEL } };
  for (const auto& m : methods)
  {
    if (name == m.Name)
    {
      return SameAsActors(m.Method, m.Name);
    }
  }
  if (name == "partitioned")
  {
    return Partitioned();
  }
  if (name == "nested_blocks")
  {
    return NestedBlocks();
  }
  if (name == "open_blocks")
  {
    return OpenBlocks();
  }
  if (name == "hidden_block")
  {
    return HiddenBlock();
  }
  if (name == "bad_block")
  {
    return BadBlock();
  }
  std::fprintf(stderr, "unknown case '%s'\n", name.c_str());
  return EXIT_FAILURE;
}
