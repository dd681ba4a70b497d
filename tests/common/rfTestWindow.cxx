#include "rfTestWindow.h"

#include "vtkRefractionEGL.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkNew.h>
#include <vtk_glew.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace rftest
{
namespace
{
// VTK's default (8 samples, vtkRenderWindow's global maximum) unless RF_TEST_MULTISAMPLES
// names another count: CTest runs the GL tests both ways (label msaa0 for the single-sampled
// runs), since users' windows are multisampled and a pass can break either way.
// Every GL error is a bug: after each frame the window has rendered (its EndEvent, while its
// context is current), a pending error ends the test with a failure and the frame's number.
void CheckGLErrorAfterFrame(vtkObject* caller, unsigned long, void* clientData, void*)
{
  auto* frames = static_cast<int*>(clientData);
  ++*frames;
  const GLenum code = glGetError();
  if (code != GL_NO_ERROR)
  {
    std::fprintf(stderr, "FAILED: OpenGL error 0x%04x after frame %d of %s %p\n",
      static_cast<unsigned>(code), *frames, caller->GetClassName(), static_cast<void*>(caller));
    std::exit(EXIT_FAILURE);
  }
}

void WatchGLErrors(vtkRenderWindow* window)
{
  static int frames = 0; // one count for the test's windows, in the message only
  vtkNew<vtkCallbackCommand> check;
  check->SetCallback(CheckGLErrorAfterFrame);
  check->SetClientData(&frames);
  window->AddObserver(vtkCommand::EndEvent, check);
}

void ApplyMultiSamples(vtkRenderWindow* window)
{
  const char* samples = std::getenv("RF_TEST_MULTISAMPLES");
  if (samples && *samples)
  {
    window->SetMultiSamples(std::atoi(samples));
  }
}
}

vtkSmartPointer<vtkRenderWindow> NewRenderWindow(int width, int height)
{
  const char* kind = std::getenv("RF_TEST_WINDOW");
  if (kind && std::string(kind) == "x11")
  {
    // For comparing the two paths: VTK's own (X) window, off screen.
    auto window = vtkSmartPointer<vtkRenderWindow>::New();
    window->SetSize(width, height);
    ApplyMultiSamples(window);
    WatchGLErrors(window);
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
  ApplyMultiSamples(window);
  WatchGLErrors(window);
  std::printf("render window: %d x %d, %s, %d samples asked\n", width, height,
    description.c_str(), window->GetMultiSamples());
  return window;
}
}
