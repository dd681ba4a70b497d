// The default demo: a time-varying metaball isosurface rendered as refractive glass (DIR) over
// the built-in environment, beside an ordinary opaque actor.
//
//   RefractionDemo [--frames N] [--size PIXELS] [--out DIR] [--method dir|sir|isr|ssp] [--steps N]
//                  [--environment IMAGE] [--interactive] [--egl] [--timing-frames N]
//
// Without --interactive it renders off screen (through EGL with --egl: no X server needed,
// else through an X window, e.g. under xvfb-run), writes DIR/frame_0000.png ... and prints
// the median frame time of the glass (DIR, SIR, ISR, SSP) and of a plain render of the same
// mesh. With --interactive it opens a window: 'm' cycles DIR/SIR/ISR/SSP, '+'/'-' change the
// search steps, 'a' starts/stops the animation.
#include "vtkRefractionPass.h"
#include "vtkMetaballsSource.h"
#include "vtkISRDistanceFilter.h"
#include "vtkRefractionEGL.h"
#ifdef REFRACTION_HAVE_IO
#include "vtkRefractionImageIO.h"
#include "vtkEquirectangularToCubeMapTexture.h"
#include "vtkOpenGLTexture.h"
#endif

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkConeSource.h>
#include <vtkFlyingEdges3D.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTimerLog.h>
#include <vtkWindowToImageFilter.h>
#include <vtk_glew.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <sys/stat.h>
#include <vector>

namespace
{
struct Options
{
  int Frames = 48;
  int Size = 512;
  int TimingFrames = 50;
  int Steps = 5;
  std::string Method = "dir";
  std::string OutDir = "out/demo";
  std::string Environment;
  bool Interactive = false;
  bool EGL = false;
};

bool ParseOptions(int argc, char* argv[], Options& o)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    const bool hasValue = i + 1 < argc;
    if (a == "--frames" && hasValue)
      o.Frames = std::atoi(argv[++i]);
    else if (a == "--size" && hasValue)
      o.Size = std::atoi(argv[++i]);
    else if (a == "--timing-frames" && hasValue)
      o.TimingFrames = std::atoi(argv[++i]);
    else if (a == "--steps" && hasValue)
      o.Steps = std::atoi(argv[++i]);
    else if (a == "--method" && hasValue)
      o.Method = argv[++i];
    else if (a == "--out" && hasValue)
      o.OutDir = argv[++i];
    else if (a == "--environment" && hasValue)
      o.Environment = argv[++i];
    else if (a == "--interactive")
      o.Interactive = true;
    else if (a == "--egl")
      o.EGL = true;
    else
    {
      std::fprintf(stderr, "unknown or incomplete option: %s\n", a.c_str());
      return false;
    }
  }
  if (o.Size < 1 || o.Frames < 0 || o.TimingFrames < 1 ||
    (o.Method != "dir" && o.Method != "sir" && o.Method != "isr" && o.Method != "ssp"))
  {
    std::fprintf(stderr, "bad option value (size >= 1, frames >= 0, method dir|sir|isr|ssp)\n");
    return false;
  }
  return true;
}

void MakeDirectories(const std::string& path)
{
  for (size_t i = 1; i <= path.size(); ++i)
  {
    if (i == path.size() || path[i] == '/')
    {
      mkdir(path.substr(0, i).c_str(), 0755);
    }
  }
}

double MedianFrameMilliseconds(vtkRenderWindow* window, vtkRenderer* renderer, int frames)
{
  std::vector<double> times;
  vtkNew<vtkTimerLog> timer;
  for (int i = 0; i < 5 + frames; ++i)
  {
    renderer->GetActiveCamera()->Azimuth(1.0);
    timer->StartTimer();
    window->Render();
    glFinish();
    timer->StopTimer();
    if (i >= 5)
    {
      times.push_back(timer->GetElapsedTime() * 1e3);
    }
  }
  std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
  return times[times.size() / 2];
}

const char* MethodName(int method)
{
  static const char* const names[] = { "SIR", "DIR", "ISR", "SSP" };
  return names[method];
}

int MethodFromOption(const std::string& name)
{
  return name == "sir" ? vtkRefractionPass::SIR
                       : name == "isr" ? vtkRefractionPass::ISR
                                       : name == "ssp" ? vtkRefractionPass::SSP
                                                       : vtkRefractionPass::DIR;
}

struct InteractiveState
{
  vtkRefractionPass* Glass;
  vtkFlyingEdges3D* Surface;
  vtkMetaballsSource* Blobs;
  bool Animate = true;
  int Step = 0;
};

void OnKey(vtkObject* caller, unsigned long, void* clientData, void*)
{
  auto* state = static_cast<InteractiveState*>(clientData);
  auto* interactor = static_cast<vtkRenderWindowInteractor*>(caller);
  const std::string key = interactor->GetKeySym() ? interactor->GetKeySym() : "";
  if (key == "m")
  {
    // DIR -> SIR -> ISR -> SSP -> DIR
    static const int next[] = { vtkRefractionPass::ISR, vtkRefractionPass::SIR,
      vtkRefractionPass::SSP, vtkRefractionPass::DIR };
    state->Glass->SetMethod(next[state->Glass->GetMethod()]);
  }
  else if (key == "plus" || key == "equal")
  {
    state->Glass->SetSearchSteps(std::min(state->Glass->GetSearchSteps() + 1, 16));
  }
  else if (key == "minus")
  {
    state->Glass->SetSearchSteps(std::max(state->Glass->GetSearchSteps() - 1, 0));
  }
  else if (key == "a")
  {
    state->Animate = !state->Animate;
  }
  else
  {
    return;
  }
  std::printf("method %s, %d search steps, animation %s\n", MethodName(state->Glass->GetMethod()),
    state->Glass->GetSearchSteps(), state->Animate ? "on" : "off");
  interactor->GetRenderWindow()->Render();
}

void OnTimer(vtkObject* caller, unsigned long, void* clientData, void*)
{
  auto* state = static_cast<InteractiveState*>(clientData);
  if (!state->Animate)
  {
    return;
  }
  auto* interactor = static_cast<vtkRenderWindowInteractor*>(caller);
  const int steps = state->Blobs->GetNumberOfTimeSteps();
  state->Step = (state->Step + 1) % steps;
  state->Surface->UpdateTimeStep(state->Blobs->GetTimePeriod() * state->Step / steps);
  interactor->GetRenderWindow()->Render();
}
}

int main(int argc, char* argv[])
{
  Options options;
  if (!ParseOptions(argc, argv, options))
  {
    return 2;
  }
  const bool haveDisplay = std::getenv("DISPLAY") && *std::getenv("DISPLAY");
  if (options.Interactive && !haveDisplay)
  {
    std::fprintf(stderr, "--interactive needs a display (DISPLAY is not set)\n");
    return 2;
  }

  vtkNew<vtkMetaballsSource> blobs;
  blobs->SetSampleDimensions(64);
  vtkNew<vtkFlyingEdges3D> surface;
  surface->SetInputConnection(blobs->GetOutputPort());
  surface->SetValue(0, blobs->GetIsoValue());
  surface->ComputeNormalsOn();
  // d_N for ISR, recomputed whenever the surface changes (DIR needs nothing of the kind).
  vtkNew<vtkISRDistanceFilter> distances;
  distances->SetInputConnection(surface->GetOutputPort());
  vtkNew<vtkPolyDataMapper> glassMapper;
  glassMapper->SetInputConnection(distances->GetOutputPort());
  glassMapper->ScalarVisibilityOff();
  vtkNew<vtkActor> glassActor;
  glassActor->SetMapper(glassMapper);
  vtkRefractionPass::MakeGlass(glassActor, 1.5);

  vtkNew<vtkConeSource> cone;
  cone->SetResolution(48);
  cone->SetCenter(1.9, -0.3, 0.0);
  cone->SetDirection(0.0, 1.0, 0.0);
  cone->SetHeight(1.4);
  cone->SetRadius(0.5);
  vtkNew<vtkPolyDataMapper> coneMapper;
  coneMapper->SetInputConnection(cone->GetOutputPort());
  vtkNew<vtkActor> coneActor;
  coneActor->SetMapper(coneMapper);
  coneActor->GetProperty()->SetColor(0.9, 0.55, 0.1);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(glassActor);
  renderer->AddActor(coneActor);
  renderer->GradientBackgroundOn();
  renderer->SetBackground(0.12, 0.12, 0.14);
  renderer->SetBackground2(0.35, 0.45, 0.6);
  vtkNew<vtkRefractionPass> glass;
  glass->SetMethod(MethodFromOption(options.Method));
  glass->SetSearchSteps(options.Steps);
  renderer->SetPass(glass);

#ifdef REFRACTION_HAVE_IO
  if (!options.Environment.empty())
  {
    std::string error;
    auto image = vtkRefractionImageIO::ReadImage(options.Environment, &error);
    if (!image)
    {
      std::fprintf(stderr, "environment: %s; using the built-in environment\n", error.c_str());
    }
    else
    {
      vtkNew<vtkOpenGLTexture> latLong;
      latLong->SetInputData(image);
      vtkNew<vtkEquirectangularToCubeMapTexture> cubeMap;
      cubeMap->SetInputTexture(latLong);
      cubeMap->SetCubeMapSize(512);
      renderer->SetEnvironmentTexture(cubeMap);
    }
  }
#else
  if (!options.Environment.empty())
  {
    std::fprintf(stderr, "built without image I/O: --environment ignored\n");
  }
#endif

  vtkSmartPointer<vtkRenderWindow> window;
  std::string path = "GLX window";
  if (options.EGL && !options.Interactive)
  {
    std::string error;
    window = vtkRefractionCreateEGLWindow(options.Size, options.Size, &error, &path);
    if (!window)
    {
      std::fprintf(stderr, "EGL: %s\n", error.c_str());
      return 3;
    }
  }
  else
  {
    window = vtkSmartPointer<vtkRenderWindow>::New();
    window->SetSize(options.Size, options.Size);
    window->SetMultiSamples(0);
    if (!options.Interactive)
    {
      window->SetOffScreenRendering(1);
    }
  }
  window->AddRenderer(renderer);

  surface->UpdateTimeStep(0.0);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Elevation(20.0);
  renderer->GetActiveCamera()->Dolly(1.1);
  renderer->ResetCameraClippingRange();

  if (options.Interactive)
  {
    vtkNew<vtkRenderWindowInteractor> interactor;
    vtkNew<vtkInteractorStyleTrackballCamera> style;
    interactor->SetInteractorStyle(style);
    interactor->SetRenderWindow(window);
    InteractiveState state{ glass, surface, blobs };
    vtkNew<vtkCallbackCommand> keys;
    keys->SetCallback(OnKey);
    keys->SetClientData(&state);
    interactor->AddObserver(vtkCommand::KeyPressEvent, keys);
    vtkNew<vtkCallbackCommand> timer;
    timer->SetCallback(OnTimer);
    timer->SetClientData(&state);
    interactor->AddObserver(vtkCommand::TimerEvent, timer);
    interactor->Initialize();
    interactor->CreateRepeatingTimer(40);
    window->Render();
    std::printf("keys: m = DIR/SIR, +/- = search steps, a = animation\n");
    interactor->Start();
    return 0;
  }

  // The numbered image sequence: the isosurface deforms with the pipeline's time.
  MakeDirectories(options.OutDir);
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  const int timeSteps = blobs->GetNumberOfTimeSteps();
  for (int frame = 0; frame < options.Frames; ++frame)
  {
    const double time = blobs->GetTimePeriod() * (frame % timeSteps) / timeSteps;
    surface->UpdateTimeStep(time);
    window->Render();
    grab->Modified();
    char name[64];
    std::snprintf(name, sizeof(name), "/frame_%04d.png", frame);
    writer->SetFileName((options.OutDir + name).c_str());
    writer->Write();
  }
  if (options.Frames > 0)
  {
    std::printf("wrote %d frames to %s/frame_NNNN.png (%dx%d)\n", options.Frames,
      options.OutDir.c_str(), options.Size, options.Size);
  }

  // Frame times at a fixed time step, the camera turning 1 degree a frame.
  surface->UpdateTimeStep(0.25 * blobs->GetTimePeriod());
  const vtkIdType triangles = surface->GetOutput()->GetNumberOfPolys();
  double methodMs[4];
  for (int method : { vtkRefractionPass::DIR, vtkRefractionPass::SIR, vtkRefractionPass::ISR,
         vtkRefractionPass::SSP })
  {
    glass->SetMethod(method);
    methodMs[method] = MedianFrameMilliseconds(window, renderer, options.TimingFrames);
  }
  const double dirMs = methodMs[vtkRefractionPass::DIR];
  const double sirMs = methodMs[vtkRefractionPass::SIR];
  vtkRefractionPass::ClearGlass(glassActor);
  const double plainMs = MedianFrameMilliseconds(window, renderer, options.TimingFrames);
  std::printf("median frame time over %d frames at %dx%d, %lld triangles, %s, renderer: %s\n",
    options.TimingFrames, options.Size, options.Size, static_cast<long long>(triangles),
    path.c_str(), reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  std::printf("  DIR (%d steps)  %8.2f ms  (%.2fx plain)\n", options.Steps, dirMs, dirMs / plainMs);
  std::printf("  SIR             %8.2f ms  (%.2fx plain)\n", sirMs, sirMs / plainMs);
  std::printf("  ISR             %8.2f ms  (%.2fx plain), plus %.2f ms of d_N ray casting each "
              "time the surface changes\n", methodMs[vtkRefractionPass::ISR],
    methodMs[vtkRefractionPass::ISR] / plainMs, distances->GetLastComputeSeconds() * 1e3);
  std::printf("  SSP             %8.2f ms  (%.2fx plain)\n", methodMs[vtkRefractionPass::SSP],
    methodMs[vtkRefractionPass::SSP] / plainMs);
  std::printf("  plain VTK       %8.2f ms\n", plainMs);
  return 0;
}
