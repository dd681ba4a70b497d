// The renderer's own settings, honoured as VTK's renderer honours them without a pass:
// three overlapping translucent spheres (opacity 0.4), drawn
//   peeling            with the renderer's depth peeling
//   order_independent  without it (VTK 9.1's renderer then uses order-independent
//                      translucency)
//   fxaa               without it, and with the renderer's FXAA on
// (VTK's depth peeling and FXAA need a single-sampled window: those two cases ask for one).
// A vtkRenderStepsPass draws translucent geometry unsorted and no FXAA, so with the pass set
// (its default delegate is one) the pictures came out differently, glass or not. Asserts:
//  - the pass without glass draws exactly plain VTK's picture;
//  - with a glass sphere below the translucent ones (in the picture's lower half), the upper
//    half, where they are, equals plain VTK's, and the glass is drawn (over 500 pixels
//    changed).
// Usage: TestRendererSettings peeling|order_independent|fxaa
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
  if (mode != "peeling" && mode != "order_independent" && mode != "fxaa")
  {
    std::fprintf(stderr, "usage: %s peeling|order_independent|fxaa\n", argv[0]);
    return EXIT_FAILURE;
  }
  auto plain = Render(mode, PLAIN);
  auto passOnly = Render(mode, PASS);
  const int differing = rftest::DifferingPixels(plain, passOnly, 0);
  std::printf("%s: the pass without glass differs from plain VTK in %d pixels\n", mode.c_str(),
    differing);
  RF_REQUIRE(differing == 0, "the pass changes what VTK draws");

  auto withGlass = Render(mode, PASS_AND_GLASS);
  // The glass lies in the lower half of the picture, the translucent spheres in the upper.
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
  std::printf("%s: the glass changes %d pixels, %d of them in the translucent spheres' half\n",
    mode.c_str(), changed, changedAbove);
  RF_REQUIRE(changed > 500, "the glass is not drawn");
  RF_REQUIRE(changedAbove == 0, "the glass changes the translucent spheres' picture");
  return EXIT_SUCCESS;
}
