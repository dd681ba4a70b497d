// RefractionViewer: any mesh VTK reads, or a time series of them, optionally contoured, drawn
// as refractive glass; interactive in a window, or headless (EGL, no X server) writing a
// screenshot, a numbered PNG sequence, a contact sheet and frame times. `--help` says it all.
// The pieces: the options (rfViewerOptions), the scene (rfViewerScene), the window's event
// loop (rfViewerInteractive) and the headless output (rfViewerOutput); this file opens the
// window and runs one of the two.

#include "rfViewer.h"
#include "rfViewerOptions.h"
#include "rfViewerInteractive.h"
#include "rfViewerOutput.h"
#include "rfViewerScene.h"

#include "vtkRefractionEGL.h"

#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

using namespace rfviewer;

namespace
{
vtkSmartPointer<vtkRenderWindow> MakeWindow(const rfViewerSettings& s, bool interactive, int& status)
{
  status = RF_VIEWER_OK;
  const bool haveDisplay = std::getenv("DISPLAY") && *std::getenv("DISPLAY");
  if (interactive)
  {
    if (!haveDisplay)
    {
      status = rfViewerUsage("--interactive needs a display (DISPLAY is not set)");
      return nullptr;
    }
    auto window = vtkSmartPointer<vtkRenderWindow>::New();
    window->SetSize(s.Width, s.Height);
    window->SetWindowName(rfViewerProgram());
    return window;
  }
  std::string error;
  std::string path;
  vtkSmartPointer<vtkRenderWindow> window =
    vtkRefractionCreateEGLWindow(s.Width, s.Height, &error, &path);
  if (window)
  {
    return window;
  }
  if (!haveDisplay)
  {
    std::fprintf(stderr, "%s: no headless rendering context (EGL: %s) and no display\n",
      rfViewerProgram(), error.c_str());
    status = RF_VIEWER_NO_CONTEXT;
    return nullptr;
  }
  std::fprintf(stderr, "%s: EGL: %s; rendering off screen through the X server\n", rfViewerProgram(),
    error.c_str());
  window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetSize(s.Width, s.Height);
  window->SetOffScreenRendering(1);
  return window;
}
}

int rfViewerMain(int argc, char* argv[], const std::vector<std::string>& preset)
{
  rfViewerOptions options;
  rfViewerSettings settings;
  const int parsed = rfViewerParseOptions(argc, argv, preset, options, settings);
  if (parsed != RF_VIEWER_OK)
  {
    return parsed < 0 ? RF_VIEWER_OK : parsed;
  }
  int status = CheckOutputs(options);
  if (status != RF_VIEWER_OK)
  {
    return status;
  }
  Scene scene;
  status = BuildScene(options, settings, scene);
  if (status != RF_VIEWER_OK)
  {
    return status;
  }
  vtkSmartPointer<vtkRenderWindow> window = MakeWindow(settings, options.Interactive, status);
  if (!window)
  {
    return status;
  }
  window->AddRenderer(scene.Renderer);

  const int firstIndex = settings.HaveTime ? TimeIndexOf(scene, settings.Time) : 0;
  if (settings.HaveTime && scene.Times.empty())
  {
    std::fprintf(stderr, "%s: the input has no time steps; --time ignored\n", rfViewerProgram());
  }
  if (!scene.Times.empty())
  {
    ShowTime(scene, scene.Times[firstIndex]);
  }
  else
  {
    scene.Surface->Update();
  }
  vtkPolyData* first = vtkPolyData::SafeDownCast(scene.Surface->GetOutputDataObject(0));
  if (!first || first->GetNumberOfPolys() + first->GetNumberOfStrips() == 0)
  {
    std::fprintf(stderr, "%s: note: the first frame has no surface%s\n", rfViewerProgram(),
      settings.ContourValues.empty() ? "" : " (no point reaches the contour values)");
  }
  std::printf("%s: %s, %zu time step%s, %lld triangles in the first frame\n", rfViewerProgram(),
    scene.Description.c_str(), std::max<size_t>(scene.Times.size(), 1),
    scene.Times.size() > 1 ? "s" : "",
    static_cast<long long>(first ? first->GetNumberOfPolys() : 0));
  PlaceCamera(scene, settings);

  if (options.Interactive)
  {
    return RunInteractive(scene, window, firstIndex);
  }
  return RunHeadless(options, settings, scene, window, firstIndex);
}
