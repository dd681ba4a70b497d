// Settings the shading program is built with, not given as uniforms (the search's step count
// without adaptive steps, RF_FIXED_SEARCH_STEPS; the number of the renderer's lights,
// RF_LIGHT_COUNT), changed between two frames of one pass: the next frame must be a fresh
// pass's picture with the new settings, pixel by pixel, and not the old one's. A program kept
// from before the change would show the old step count or lose (or keep) a light's highlight.
#include "vtkRefractionPass.h"

#include "rfTestScene.h"

#include <vtkActor.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkRenderer.h>

#include <cstdio>
#include <functional>

namespace
{
struct Check
{
  const char* Name;
  std::function<void(vtkRefractionPass*, vtkRenderer*)> Before;
  std::function<void(vtkRefractionPass*, vtkRenderer*)> After;
};
}

int main()
{
  const int size = 128;
  // A torus: its exits move with the search's steps over much of the glass (a sphere's back
  // is nearly the depth range's plane, where even no step finds it).
  vtkSmartPointer<vtkActor> actor = rftest::MakeTorus();
  RF_REQUIRE(vtkRefractionPass::MakeGlass(actor, 1.5), "MakeGlass refused IOR 1.5");
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkSmartPointer<vtkRenderWindow> window = rftest::MakeWindow(renderer, size, size);
  rftest::LookAtOrigin(renderer, 3.0, 35.0);
  vtkNew<vtkLight> second; // positional, coloured: a highlight of its own on the torus
  second->SetPositional(true);
  second->SetPosition(-2.0, 3.0, 2.5);
  second->SetFocalPoint(0.0, 0.0, 0.0);
  second->SetColor(1.0, 0.6, 0.3);
  second->SetIntensity(2.0);

  auto steps = [](int count) {
    return [count](vtkRefractionPass* pass, vtkRenderer*) { pass->SetSearchSteps(count); };
  };
  auto nothing = [](vtkRefractionPass*, vtkRenderer*) {};
  auto addSecond = [&second](vtkRefractionPass*, vtkRenderer* r) { r->AddLight(second); };
  auto removeSecond = [&second](vtkRefractionPass*, vtkRenderer* r) { r->RemoveLight(second); };
  const Check checks[] = {
    { "search steps 5 -> 1", steps(5), steps(1) },
    { "search steps 1 -> 5", steps(1), steps(5) },
    { "a second light", nothing, addSecond },
    { "the second light removed", addSecond, removeSecond },
  };
  for (const Check& check : checks)
  {
    renderer->RemoveAllLights();
    renderer->CreateLight(); // the headlight the renderer makes where it has none
    vtkNew<vtkRefractionPass> used;
    used->SetEnvironmentModeToBuiltin();
    renderer->SetPass(used);
    check.Before(used, renderer);
    window->Render();
    vtkSmartPointer<vtkImageData> before = rftest::Grab(window);
    check.After(used, renderer);
    window->Render();
    vtkSmartPointer<vtkImageData> changed = rftest::Grab(window);

    vtkNew<vtkRefractionPass> fresh;
    fresh->SetEnvironmentModeToBuiltin();
    fresh->SetSearchSteps(used->GetSearchSteps());
    renderer->SetPass(fresh);
    window->Render();
    vtkSmartPointer<vtkImageData> expected = rftest::Grab(window);
    renderer->SetPass(nullptr);
    used->ReleaseGraphicsResources(window);
    fresh->ReleaseGraphicsResources(window);

    const int moved = rftest::DifferingPixels(before, expected, 2);
    const int differing = rftest::DifferingPixels(changed, expected, 0);
    std::printf("%s: %d pixels differ between the settings; after the change %d differ from a "
                "fresh pass (largest difference %d of 255)\n",
      check.Name, moved, differing, rftest::MaxChannelDifference(changed, expected));
    RF_REQUIRE(moved > 50, "%s: the change moves only %d pixels, too few to tell", check.Name,
      moved);
    RF_REQUIRE(differing == 0, "%s: %d pixels differ from a fresh pass's picture", check.Name,
      differing);
  }
  return EXIT_SUCCESS;
}
