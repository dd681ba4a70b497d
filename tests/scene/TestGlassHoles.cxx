// The surface model of an open mesh (issue 23): a mesh that is closed but for small holes (a
// scan, a contour touching the domain at a few cells) is a solid; one open as a whole (a bowl,
// a height field) is a thin sheet, with the warning that says so.
//   small_hole  a sphere with a cap of 10 degrees cut: drawn exactly as when forced to be a
//               solid, no thin-sheet warning
//   bowl        a hemisphere: drawn exactly as when forced to be a thin sheet, one warning
//   mixed_pieces  one polydata holding a closed sphere and an open bowl beside it, over a
//               checkered wall: the sphere's half of the picture is refracted as the sphere
//               alone (a solid), the sheet's half as the sheet alone (a thin sheet); the one
//               warning names 1 of 2 pieces (per connected piece, issue 23)
//   mixed_pieces_peel   the same with the PEEL method (the per-fragment material in the layers)
//   mixed_pieces_edges  the same with the glass's edges shown (through VTK's edge geometry
//               shader)
#include "vtkRefractionPass.h"

#include "rfTestRig.h"
#include "rfTestScene.h"
#include "rf_require.h"

#include <vtkActor.h>
#include <vtkAppendPolyData.h>
#include <vtkCellData.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkUnsignedCharArray.h>
#include <vtkOutputWindow.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace
{
int Check(double endPhi, int expected, const char* name)
{
  vtkNew<rftest::MessageLog> log;
  vtkOutputWindow::SetInstance(log);
  const double centre[3] = { 0.0, 0.0, 0.0 };
  auto glass = rftest::GlassActor(rftest::SpherePoly(centre, 1.0, 64, false, endPhi), 1.5);
  vtkNew<vtkRenderer> renderer;
  const double wallCentre[3] = { 0.0, 0.0, -2.5 };
  const double wallSize[3] = { 1.0, 6.0, 0.1 };
  renderer->AddActor(rftest::FlatActor(rftest::BoxPoly(wallSize, wallCentre), 1.0, 0.5, 0.1));
  renderer->AddActor(glass);
  renderer->SetBackground(0.1, 0.1, 0.2);
  vtkNew<vtkRefractionPass> pass;
  renderer->SetPass(pass);
  auto window = rftest::MakeWindow(renderer, 128, 128);
  rftest::LookAtOrigin(renderer, 6.0, 20.0);
  window->Render();
  auto automatic = rftest::Grab(window);
  vtkRefractionPass::SetSurfaceModel(glass, expected);
  window->Render();
  auto forced = rftest::Grab(window);
  vtkRefractionPass::SetSurfaceModel(glass, expected == vtkRefractionPass::SURFACE_SOLID
      ? vtkRefractionPass::SURFACE_THIN_SHEET
      : vtkRefractionPass::SURFACE_SOLID);
  window->Render();
  auto other = rftest::Grab(window);
  const int sheetWarnings = log->Count("warning", { "thin sheets" });
  vtkOutputWindow::SetInstance(nullptr);
  const int same = rftest::DifferingPixels(automatic, forced, 0);
  const int differ = rftest::DifferingPixels(automatic, other, 2);
  std::printf("%s: against the forced %s model %d pixels differ, against the other model %d; "
              "%d thin-sheet warning(s)\n",
    name, expected == vtkRefractionPass::SURFACE_SOLID ? "solid" : "thin-sheet", same, differ,
    sheetWarnings);
  RF_REQUIRE(differ > 100, "the two models look alike here (%d pixels): the check cannot tell",
    differ);
  RF_REQUIRE(same == 0, "drawn as the other model (%d pixels differ from the expected one)",
    same);
  RF_REQUIRE(sheetWarnings == (expected == vtkRefractionPass::SURFACE_SOLID ? 0 : 1),
    "%d thin-sheet warnings", sheetWarnings);
  return EXIT_SUCCESS;
}

// A wall of unlit checkers (squares of 0.5) at depth z, coloured by cell scalars.
vtkSmartPointer<vtkActor> CheckeredWall(double z)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-6.0, -4.0, z);
  plane->SetPoint1(6.0, -4.0, z);
  plane->SetPoint2(-6.0, 4.0, z);
  plane->SetResolution(24, 16);
  plane->Update();
  auto wall = rftest::Detach(plane->GetOutput());
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < wall->GetNumberOfCells(); ++i)
  {
    const bool dark = ((i % 24) + (i / 24)) % 2 == 0;
    colours->InsertNextTuple3(dark ? 30 : 230, dark ? 60 : 200, dark ? 160 : 40);
  }
  wall->GetCellData()->SetScalars(colours);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(wall);
  mapper->SetColorModeToDirectScalars();
  mapper->SetScalarModeToUseCellData();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->LightingOff();
  return actor;
}

// An open bowl: a hemisphere of radius 0.7 centred at (1.1, 0, 0), its pole toward +x, so that
// the camera on +z looks through both of its walls (where a solid and a sheet differ).
vtkSmartPointer<vtkPolyData> Bowl()
{
  const double origin[3] = { 0.0, 0.0, 0.0 };
  auto bowl = rftest::SpherePoly(origin, 0.7, 48, false, 90.0);
  vtkPoints* points = bowl->GetPoints();
  vtkDataArray* normals = bowl->GetPointData()->GetNormals();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    points->SetPoint(i, p[2] + 1.1, p[1], -p[0]);
    double n[3];
    normals->GetTuple(i, n);
    normals->SetTuple3(i, n[2], n[1], -n[0]);
  }
  return bowl;
}

// PSNR (dB) of two pictures over the columns [x0, x1), and the pixels differing by more than
// 2 levels there.
double HalfPSNR(vtkImageData* a, vtkImageData* b, int x0, int x1, int* differing)
{
  const int* dims = a->GetDimensions();
  double sum = 0.0;
  long count = 0;
  *differing = 0;
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = x0; x < x1; ++x)
    {
      bool differs = false;
      for (int c = 0; c < 3; ++c)
      {
        const double d = a->GetScalarComponentAsDouble(x, y, 0, c) -
          b->GetScalarComponentAsDouble(x, y, 0, c);
        sum += d * d;
        ++count;
        differs = differs || std::abs(d) > 2.0;
      }
      *differing += differs ? 1 : 0;
    }
  }
  const double mse = sum / static_cast<double>(count);
  return mse > 0.0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : 99.0;
}

// One polydata of two connected pieces, a closed sphere (left) and an open bowl (right),
// against the same pieces as actors of their own: each half of the picture as its piece alone.
int MixedPieces(int method, bool edges, const char* name)
{
  vtkNew<rftest::MessageLog> log;
  vtkOutputWindow::SetInstance(log);
  const double centre[3] = { -1.1, 0.0, 0.0 };
  auto sphere = rftest::SpherePoly(centre, 0.8, 48);
  auto sheet = Bowl();
  vtkNew<vtkAppendPolyData> append;
  append->AddInputData(sphere);
  append->AddInputData(sheet);
  append->Update();
  auto both = rftest::Detach(append->GetOutput());
  auto mixed = rftest::GlassActor(both, 1.5);
  auto sphereAlone = rftest::GlassActor(sphere, 1.5);
  auto sheetAlone = rftest::GlassActor(sheet, 1.5);
  for (vtkActor* actor : { mixed.GetPointer(), sphereAlone.GetPointer(), sheetAlone.GetPointer() })
  {
    actor->GetProperty()->SetEdgeVisibility(edges);
    actor->GetProperty()->SetEdgeColor(0.2, 0.2, 0.2);
  }
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(CheckeredWall(-2.5));
  renderer->AddActor(mixed);
  renderer->AddActor(sphereAlone);
  renderer->AddActor(sheetAlone);
  renderer->SetBackground(0.1, 0.1, 0.2);
  vtkNew<vtkRefractionPass> pass;
  pass->SetMethod(method);
  renderer->SetPass(pass);
  const int width = 192;
  const int height = 96;
  auto window = rftest::MakeWindow(renderer, width, height);
  rftest::LookAtOrigin(renderer, 7.0, 0.0);
  auto show = [&](bool m, bool sp, bool sh) {
    mixed->SetVisibility(m);
    sphereAlone->SetVisibility(sp);
    sheetAlone->SetVisibility(sh);
    window->Render();
    return rftest::Grab(window);
  };
  auto mixedImage = show(true, false, false);
  const int mixedWarnings = log->Count("warning", { "thin sheet", "1 of 2 pieces" });
  auto sphereImage = show(false, true, false);
  auto sheetImage = show(false, false, true);
  auto none = show(false, false, false);
  vtkRefractionPass::SetSurfaceModel(sheetAlone, vtkRefractionPass::SURFACE_SOLID);
  auto sheetSolid = show(false, false, true);
  vtkRefractionPass::SetSurfaceModel(sphereAlone, vtkRefractionPass::SURFACE_THIN_SHEET);
  auto sphereSheet = show(false, true, false);
  vtkOutputWindow::SetInstance(nullptr);
  const int half = width / 2;
  int sphereDiffering = 0;
  int sheetDiffering = 0;
  const double spherePSNR = HalfPSNR(mixedImage, sphereImage, 0, half, &sphereDiffering);
  const double sheetPSNR = HalfPSNR(mixedImage, sheetImage, half, width, &sheetDiffering);
  // How far the wrong models are: the scale the two measures are read against.
  int sphereAsSheetDiffering = 0;
  int sheetAsSolidDiffering = 0;
  const double sphereAsSheet =
    HalfPSNR(mixedImage, sphereSheet, 0, half, &sphereAsSheetDiffering);
  const double sheetAsSolid =
    HalfPSNR(mixedImage, sheetSolid, half, width, &sheetAsSolidDiffering);
  int sphereShows = 0;
  int sheetShows = 0;
  HalfPSNR(sphereImage, none, 0, half, &sphereShows);
  HalfPSNR(sheetImage, none, half, width, &sheetShows);
  std::printf("%s: sphere half %.2f dB against the sphere alone (%d pixels differ by more than "
              "2; %.2f dB, %d pixels against it as a sheet; %d pixels of glass), sheet half "
              "%.2f dB against the sheet alone (%d pixels; %.2f dB, %d pixels against it as a "
              "solid; %d pixels of glass); %d warning(s) naming 1 of 2 pieces\n",
    name, spherePSNR, sphereDiffering, sphereAsSheet, sphereAsSheetDiffering, sphereShows,
    sheetPSNR, sheetDiffering, sheetAsSolid, sheetAsSolidDiffering, sheetShows, mixedWarnings);
  // Measured on llvmpipe: each half exactly as its piece alone with DIR and PEEL (99 dB: no
  // pixel differs); with edges 51.6 dB (1 pixel) and 99 dB single-sampled, 85.6 dB (0 pixels)
  // and 99 dB multisampled (the glass drawn at the window's samples). The wrong models: the sphere as a
  // sheet 19.2 dB (DIR, PEEL) and 37.8 dB (edges), the bowl as a solid 24.2 (DIR), 21.7
  // (PEEL) and 46.8 dB (edges), each with hundreds of pixels differing. Before the surface
  // model was decided per piece, the whole polydata was a sheet (its boundary, 4.4, against
  // the square root of both pieces' area, 3.3): the sphere half read 19.3 dB (DIR), 19.6
  // (PEEL) and 37.9 (edges) against the sphere alone.
  RF_REQUIRE(sphereShows > 500 && sheetShows > 500,
    "the glass hardly shows (%d and %d pixels): the check cannot tell", sphereShows, sheetShows);
  RF_REQUIRE(sphereAsSheetDiffering > 100 && sheetAsSolidDiffering > 100,
    "the wrong models look alike here (%d and %d pixels): the check cannot tell",
    sphereAsSheetDiffering, sheetAsSolidDiffering);
  RF_REQUIRE(spherePSNR > 45.0 && sphereDiffering <= 5,
    "the sphere is not drawn as the sphere alone (%.2f dB, %d pixels)", spherePSNR,
    sphereDiffering);
  RF_REQUIRE(sheetPSNR > 45.0 && sheetDiffering <= 5,
    "the bowl is not drawn as the bowl alone (%.2f dB, %d pixels)", sheetPSNR, sheetDiffering);
  RF_REQUIRE(mixedWarnings == 1, "%d warnings naming 1 of 2 pieces as thin sheets",
    mixedWarnings);
  return EXIT_SUCCESS;
}
}

int main(int argc, char* argv[])
{
  const std::string name = argc > 1 ? argv[1] : "";
  if (name == "small_hole")
  {
    return Check(170.0, vtkRefractionPass::SURFACE_SOLID, "small_hole");
  }
  if (name == "bowl")
  {
    return Check(90.0, vtkRefractionPass::SURFACE_THIN_SHEET, "bowl");
  }
  if (name == "mixed_pieces")
  {
    return MixedPieces(vtkRefractionPass::DIR, false, "mixed_pieces");
  }
  if (name == "mixed_pieces_peel")
  {
    return MixedPieces(vtkRefractionPass::PEEL, false, "mixed_pieces_peel");
  }
  if (name == "mixed_pieces_edges")
  {
    return MixedPieces(vtkRefractionPass::DIR, true, "mixed_pieces_edges");
  }
  std::fprintf(stderr, "unknown case '%s'\n", name.c_str());
  return EXIT_FAILURE;
}
