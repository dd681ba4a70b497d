// The shading stage runs only where a depth test ahead of its program lets it
// (vtkRefractionShadeStage: the front capture's depth buffer, with anti-aliasing the corner
// depth buffer, with coarse shading the blocks' and the trace's depth buffers), and the
// composite shows what it wrote. So every pixel (every corner) the
// composite reads must have been shaded in this frame. A pass that drew the glass a little
// elsewhere in the frame before and a fresh pass must then draw the moved glass identically:
// a pixel or corner culled wrongly would show the earlier frame's colour through the first and
// the never-written target through the second. Pixel by pixel, with anti-aliasing and with
// coarse shading; the glass must cover enough of the picture for "identical" to mean
// something.
#include "vtkRefractionPass.h"

#include "rfTestScene.h"

#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkRenderer.h>

#include <cstdio>

int main()
{
  const int size = 160;
  vtkSmartPointer<vtkActor> actor = rftest::MakeSphere(0.5, 48);
  RF_REQUIRE(vtkRefractionPass::MakeGlass(actor, 1.5), "MakeGlass refused IOR 1.5");
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.1, 0.1, 0.1);
  vtkSmartPointer<vtkRenderWindow> window = rftest::MakeWindow(renderer, size, size);
  rftest::LookAtOrigin(renderer, 3.0, 15.0);

  window->Render(); // no pass: the background wherever the glass is not
  vtkSmartPointer<vtkImageData> plain = rftest::Grab(window);
  enum Mode
  {
    PIXELS,
    ANTI_ALIASED,
    COARSE
  };
  for (int mode : { PIXELS, ANTI_ALIASED, COARSE })
  {
    const char* name = mode == ANTI_ALIASED ? "anti-aliased" : mode == COARSE ? "coarse" : "pixels";
    vtkNew<vtkRefractionPass> used;
    used->SetEnvironmentModeToBuiltin();
    used->SetAntiAliasing(mode == ANTI_ALIASED);
    used->SetCoarseShading(mode == COARSE);
    renderer->SetPass(used);
    actor->SetPosition(-0.12, 0.08, 0.0);
    window->Render();
    actor->SetPosition(0.0, 0.0, 0.0);
    window->Render();
    vtkSmartPointer<vtkImageData> afterMove = rftest::Grab(window);

    vtkNew<vtkRefractionPass> fresh;
    fresh->SetEnvironmentModeToBuiltin();
    fresh->SetAntiAliasing(mode == ANTI_ALIASED);
    fresh->SetCoarseShading(mode == COARSE);
    renderer->SetPass(fresh);
    window->Render();
    vtkSmartPointer<vtkImageData> firstFrame = rftest::Grab(window);
    renderer->SetPass(nullptr);
    used->ReleaseGraphicsResources(window);
    fresh->ReleaseGraphicsResources(window);

    const int glass = rftest::DifferingPixels(afterMove, plain, 2);
    const int differing = rftest::DifferingPixels(afterMove, firstFrame, 0);
    std::printf("%s: %d of %d pixels show glass; %d differ between the moved glass and a fresh "
                "pass (largest difference %d of 255)\n",
      name, glass, size * size, differing, rftest::MaxChannelDifference(afterMove, firstFrame));
    RF_REQUIRE(glass > size * size / 8, "%s: only %d pixels show glass", name, glass);
    RF_REQUIRE(differing == 0, "%s: %d pixels differ from a fresh pass's picture", name,
      differing);
  }
  return EXIT_SUCCESS;
}
