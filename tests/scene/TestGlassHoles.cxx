// The surface model of an open mesh (issue 23): a mesh that is closed but for small holes (a
// scan, a contour touching the domain at a few cells) is a solid; one open as a whole (a bowl,
// a height field) is a thin sheet, with the warning that says so.
//   small_hole  a sphere with a cap of 10 degrees cut: drawn exactly as when forced to be a
//               solid, no thin-sheet warning
//   bowl        a hemisphere: drawn exactly as when forced to be a thin sheet, one warning
#include "vtkRefractionPass.h"

#include "rfTestRig.h"
#include "rfTestScene.h"
#include "rf_require.h"

#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkOutputWindow.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

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
  std::fprintf(stderr, "unknown case '%s'\n", name.c_str());
  return EXIT_FAILURE;
}
