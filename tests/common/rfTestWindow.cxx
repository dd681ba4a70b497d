#include "rfTestWindow.h"

#include "vtkRefractionEGL.h"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace rftest
{
vtkSmartPointer<vtkRenderWindow> NewRenderWindow(int width, int height)
{
  const char* kind = std::getenv("RF_TEST_WINDOW");
  if (kind && std::string(kind) == "x11")
  {
    // For comparing the two paths: VTK's own (X) window, off screen.
    auto window = vtkSmartPointer<vtkRenderWindow>::New();
    window->SetSize(width, height);
    window->SetMultiSamples(0);
    window->SetOffScreenRendering(1);
    std::printf("render window: %d x %d, VTK's X window (RF_TEST_WINDOW=x11)\n", width, height);
    return window;
  }
  std::string error;
  std::string description;
  auto window = vtkRefractionCreateEGLWindow(width, height, &error, &description);
  if (!window)
  {
    std::fprintf(stderr, "cannot create an EGL render window of %d x %d: %s\n", width, height,
      error.c_str());
    std::exit(EXIT_FAILURE);
  }
  std::printf("render window: %d x %d, %s\n", width, height, description.c_str());
  window->SetMultiSamples(0);
  return window;
}
}
