// Renders the glass contour in an ordinary VTK window and compares it with a baseline, as VTK
// does and pixel by pixel (the tests' rfTestBaseline.h):
//   GlassContour -V baseline.png -T output_dir
#include "GlassContourScene.h"
#include "rfTestBaseline.h"

#include <vtkRenderWindow.h>

#include <cstdio>

int main(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  GlassContourScene scene = BuildGlassContourScene(window, 200);
  window->Render();
  if (scene.Pass->GetNumberOfGlassProps() != 1)
  {
    std::fprintf(stderr, "GlassContour: the pass drew %d glass props, expected 1\n",
      scene.Pass->GetNumberOfGlassProps());
    return 1;
  }
  return rftest::CompareWithBaseline(argc, argv, window, 0.15);
}
