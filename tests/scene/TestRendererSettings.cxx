// The renderer's own settings, honoured as VTK's renderer honours them without a pass:
// three overlapping translucent spheres (opacity 0.4) before an opaque wall, cone and
// wireframe sphere, drawn
//   peeling            with the renderer's depth peeling
//   order_independent  without it (VTK 9.1's renderer then uses order-independent
//                      translucency)
//   fxaa               without it, and with the renderer's FXAA on
//   ssao               with the renderer's screen-space ambient occlusion
//   hidden_lines       with the renderer's hidden line removal
// (VTK's depth peeling and FXAA need a single-sampled window: those two cases ask for one).
// A vtkRenderStepsPass draws translucent geometry unsorted, and neither FXAA, SSAO nor hidden
// line removal, so with the pass set (its default delegate is one) the pictures came out
// differently, glass or not. Asserts:
//  - the pass without glass draws exactly plain VTK's picture;
//  - with a glass sphere below the others (in the picture's lower half), the upper half
//    equals plain VTK's, and the glass is drawn (over 500 pixels changed).
// Usage: TestRendererSettings peeling|order_independent|fxaa|ssao|hidden_lines
#include "vtkRefractionPass.h"

#include "rfTestScene.h"
#include "rf_require.h"

#include <vtkActor.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace
{
const int kSize = 160;

enum Mode
{
  PLAIN,
  PASS,
  PASS_AND_GLASS
};

vtkSmartPointer<vtkImageData> Render(const std::string& setting, Mode mode)
{
  const bool peeling = setting == "peeling";
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.1, 0.1, 0.2);
  renderer->SetUseDepthPeeling(peeling);
  renderer->SetUseFXAA(setting == "fxaa");
  renderer->SetMaximumNumberOfPeels(8);
  renderer->SetOcclusionRatio(0.0);
  const double centres[3][3] = { { -0.4, 0.3, 0.0 }, { 0.4, 0.3, -0.3 }, { 0.0, 0.7, 0.3 } };
  const double colours[3][3] = { { 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 }, { 0.0, 0.0, 1.0 } };
  for (int i = 0; i < 3; ++i)
  {
    auto veil = rftest::ActorFor(rftest::SpherePoly(centres[i], 0.6, 32));
    veil->GetProperty()->SetColor(colours[i][0], colours[i][1], colours[i][2]);
    veil->GetProperty()->SetOpacity(0.4);
    renderer->AddActor(veil);
  }
  // Opaque geometry for the opaque settings: a wall behind everything, a cone standing out
  // of it (ambient occlusion where they meet) and a sphere shown as wireframe (hidden lines).
  const double wallSize[3] = { 6.0, 6.0, 0.2 };
  const double wallCentre[3] = { 0.0, 0.0, -2.0 };
  auto wall = rftest::ActorFor(rftest::BoxPoly(wallSize, wallCentre));
  wall->GetProperty()->SetColor(0.8, 0.8, 0.7);
  renderer->AddActor(wall);
  const double coneCentre[3] = { 1.1, 0.9, -1.4 };
  auto cone = rftest::ActorFor(rftest::ConePoly(coneCentre, 1.0, 0.4, 24));
  cone->GetProperty()->SetColor(1.0, 0.6, 0.2);
  renderer->AddActor(cone);
  const double wireCentre[3] = { -1.1, 0.9, -1.0 };
  auto wire = rftest::ActorFor(rftest::SpherePoly(wireCentre, 0.4, 16));
  wire->GetProperty()->SetRepresentationToWireframe();
  renderer->AddActor(wire);
  renderer->SetUseHiddenLineRemoval(setting == "hidden_lines");
  renderer->SetUseSSAO(setting == "ssao");
  renderer->SetSSAORadius(0.5);
  renderer->SetSSAOKernelSize(32);
  const double below[3] = { 0.0, -1.0, 0.0 };
  auto glass = rftest::GlassActor(rftest::SpherePoly(below, 0.5, 32), 1.5);
  if (mode == PASS_AND_GLASS)
  {
    renderer->AddActor(glass);
  }
  vtkNew<vtkRefractionPass> pass;
  if (mode != PLAIN)
  {
    renderer->SetPass(pass);
  }
  auto window = rftest::MakeWindow(renderer, kSize, kSize);
  if (peeling || setting == "fxaa")
  {
    // VTK's depth peeling and its FXAA (which stands in for multisampling) need a
    // single-sampled window: in a multisampled one VTK 9.1 alone, without the pass, leaves
    // GL_INVALID_OPERATION after the frame.
    window->SetMultiSamples(0);
  }
  rftest::LookAtOrigin(renderer, 6.0, 0.0);
  window->Render();
  window->Render();
  return rftest::Grab(window);
}
}

int main(int argc, char* argv[])
{
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode != "peeling" && mode != "order_independent" && mode != "fxaa" && mode != "ssao" &&
    mode != "hidden_lines")
  {
    std::fprintf(
      stderr, "usage: %s peeling|order_independent|fxaa|ssao|hidden_lines\n", argv[0]);
    return EXIT_FAILURE;
  }
  auto plain = Render(mode, PLAIN);
  auto passOnly = Render(mode, PASS);
  const int differing = rftest::DifferingPixels(plain, passOnly, 0);
  std::printf("%s: the pass without glass differs from plain VTK in %d pixels\n", mode.c_str(),
    differing);
  RF_REQUIRE(differing == 0, "the pass changes what VTK draws");

  auto withGlass = Render(mode, PASS_AND_GLASS);
  // The glass lies in the lower half of the picture, the others in the upper.
  int changed = 0;
  int changedAbove = 0;
  for (int y = 0; y < kSize; ++y)
  {
    for (int x = 0; x < kSize; ++x)
    {
      const bool differs = rftest::PixelDiffers(plain, withGlass, x, y, 0);
      changed += differs ? 1 : 0;
      changedAbove += differs && y >= kSize / 2 ? 1 : 0;
    }
  }
  std::printf("%s: the glass changes %d pixels, %d of them in the upper half\n",
    mode.c_str(), changed, changedAbove);
  RF_REQUIRE(changed > 500, "the glass is not drawn");
  RF_REQUIRE(changedAbove == 0, "the glass changes the picture's upper half");
  return EXIT_SUCCESS;
}
