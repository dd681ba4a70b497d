// RefractionViewer: any mesh VTK reads, or a time series of them, optionally contoured, drawn
// as refractive glass; interactive in a window, or headless (EGL, no X server) writing a
// screenshot, a numbered PNG sequence, a contact sheet and frame times. `--help` says it all.
#include "rfViewer.h"
#include "rfViewerOptions.h"

#include "vtkCheckerboardSource.h"
#include "vtkISRDistanceFilter.h"
#include "vtkMetaballsSource.h"
#include "vtkRefractionEGL.h"
#include "vtkRefractionPass.h"
#include "vtkRefractionSeriesReader.h"
#include "vtkWaveEquationSource.h"
#ifdef REFRACTION_HAVE_IO
#include "vtkRefractionImageIO.h"
#endif

#include <vtkActor.h>
#include <vtkBoundingBox.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkAppendPolyData.h>
#include <vtkConeSource.h>
#include <vtkContourFilter.h>
#include <vtkDataSet.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageAppend.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkLookupTable.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkSkybox.h>
#include <vtkSmartPointer.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTexture.h>
#include <vtkTimerLog.h>
#include <vtkWindowToImageFilter.h>
#include <vtk_glew.h>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <unistd.h>

namespace
{
const char* MethodName(int method)
{
  static const char* const names[] = { "SIR", "DIR", "ISR", "SSP", "PEEL" };
  return names[method];
}

// A progress line for long runs: rewritten in place on a terminal, one line per tenth in a log.
class ProgressLine
{
public:
  ProgressLine(const char* label, int total)
    : Label(label)
    , Total(total)
    , Terminal(isatty(fileno(stdout)) != 0)
  {
  }
  void Update(int done)
  {
    const int percent = this->Total > 0 ? 100 * done / this->Total : 100;
    if (this->Terminal)
    {
      std::printf("\r%s %d/%d (%d%%)", this->Label, done, this->Total, percent);
      if (done == this->Total)
      {
        std::printf("\n");
      }
      std::fflush(stdout);
    }
    else if (percent / 10 > this->LastTenth || done == this->Total)
    {
      this->LastTenth = percent / 10;
      std::printf("%s %d/%d (%d%%)\n", this->Label, done, this->Total, percent);
      std::fflush(stdout);
    }
  }

private:
  const char* Label;
  int Total;
  bool Terminal;
  int LastTenth = -1;
};

// Shows the progress of a pipeline stage that runs long (the wave equation from t = 0, ISR's
// ray casts on a big mesh): silent under a second, a percentage on a terminal after that,
// and the time taken at the end.
struct StageProgress
{
  const char* Label;
  double Start = 0.0;
  bool Shown = false;
};

void OnStageProgress(vtkObject*, unsigned long, void* clientData, void* callData)
{
  auto* stage = static_cast<StageProgress*>(clientData);
  const double fraction = *static_cast<double*>(callData);
  const double now = vtkTimerLog::GetUniversalTime();
  if (fraction <= 0.0)
  {
    stage->Start = now;
    stage->Shown = false;
    return;
  }
  const double elapsed = now - stage->Start;
  if (fraction >= 1.0)
  {
    if (stage->Shown || elapsed > 1.0)
    {
      std::printf("%s%s: %.1f s\n", stage->Shown ? "\r" : "", stage->Label, elapsed);
      std::fflush(stdout);
    }
    return;
  }
  if (elapsed > 1.0 && isatty(fileno(stdout)))
  {
    std::printf("\r%s %3.0f%%", stage->Label, 100.0 * fraction);
    std::fflush(stdout);
    stage->Shown = true;
  }
}

struct Scene
{
  vtkSmartPointer<vtkAlgorithm> Source;
  vtkSmartPointer<vtkAlgorithm> Surface; // what the mapper pulls from
  vtkSmartPointer<vtkISRDistanceFilter> Distances;
  vtkSmartPointer<vtkActor> Glass;
  vtkSmartPointer<vtkActor> Cone;
  vtkSmartPointer<vtkActor> Floor; // the demo's checkered floor and back wall
  vtkSmartPointer<vtkSkybox> Sky;
  vtkSmartPointer<vtkTextActor> Text;
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkRefractionPass> Pass;
  std::vector<double> Times;
  std::string Description;
  StageProgress SourceProgress{ "computing the data" };
  StageProgress DistanceProgress{ "ISR distances" };
};

// The time is requested on the algorithm the mapper pulls from, so that it reaches the
// source through every filter in between (a request on an upstream filter alone leaves the
// filters below it holding the old time step).
void ShowTime(Scene& scene, double time)
{
  if (!scene.Times.empty())
  {
    scene.Surface->UpdateTimeStep(time);
  }
}

int BuildPipeline(const rfViewerOptions& o, const rfViewerSettings& s, Scene& scene)
{
  vtkSmartPointer<vtkAlgorithm> surface;
  if (!o.Demo.empty())
  {
    vtkNew<vtkFlyingEdges3D> contour;
    contour->ComputeNormalsOn();
    if (o.Demo == "metaballs")
    {
      vtkNew<vtkMetaballsSource> blobs;
      blobs->SetSampleDimensions(64);
      contour->SetValue(0, blobs->GetIsoValue());
      scene.Source = blobs;
      scene.Description = "metaballs (vtkMetaballsSource), contoured at 1";
    }
    else
    {
      vtkNew<vtkWaveEquationSource> waves;
      waves->SetSampleDimensions(64);
      contour->SetValue(0, waves->GetIsoValue());
      scene.Source = waves;
      scene.Description = "the wave equation in a box (vtkWaveEquationSource), contoured at " +
        std::to_string(waves->GetIsoValue());
    }
    for (size_t i = 0; i < s.ContourValues.size(); ++i)
    {
      contour->SetValue(static_cast<int>(i), s.ContourValues[i]);
    }
    contour->SetInputConnection(scene.Source->GetOutputPort());
    surface = contour;
  }
  else
  {
    vtkNew<vtkRefractionSeriesReader> reader;
    const bool ok = o.Inputs.size() == 1 ? reader->SetFileName(o.Inputs[0], o.Series)
                                         : reader->SetFileNames(o.Inputs);
    if (!ok)
    {
      return rfViewerBadInput(reader->GetLastError());
    }
    // Read the first file now, so that an unreadable input is reported before any window.
    reader->UpdateInformation();
    if (!reader->GetLastError().empty())
    {
      return rfViewerBadInput(reader->GetLastError());
    }
    reader->Update();
    vtkDataSet* first = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
    if (!first)
    {
      return rfViewerBadInput(reader->GetLastError().empty() ? "cannot read " + rfViewerQuote(o.Inputs[0])
                                                     : reader->GetLastError());
    }
    scene.Source = reader;
    scene.Description = std::to_string(reader->GetFiles().size()) + " file" +
      (reader->GetFiles().size() > 1 ? "s" : "") + " from " + reader->GetFiles()[0];
    if (!s.ContourValues.empty())
    {
      vtkDataArray* scalars = o.Array.empty() ? first->GetPointData()->GetScalars()
                                              : first->GetPointData()->GetArray(o.Array.c_str());
      if (!scalars)
      {
        std::string names;
        for (int i = 0; i < first->GetPointData()->GetNumberOfArrays(); ++i)
        {
          const char* name = first->GetPointData()->GetArrayName(i);
          names += std::string(names.empty() ? "" : ", ") + (name ? name : "(unnamed)");
        }
        return rfViewerBadInput("--contour: " + rfViewerQuote(reader->GetFiles()[0]) + " has no point " +
          (o.Array.empty() ? std::string("scalars") : "array " + rfViewerQuote(o.Array)) +
          " (point arrays: " + (names.empty() ? "none" : names) + ")");
      }
      vtkNew<vtkContourFilter> contour;
      contour->SetInputConnection(reader->GetOutputPort());
      if (!o.Array.empty())
      {
        contour->SetInputArrayToProcess(
          0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, o.Array.c_str());
      }
      for (size_t i = 0; i < s.ContourValues.size(); ++i)
      {
        contour->SetValue(static_cast<int>(i), s.ContourValues[i]);
      }
      contour->ComputeScalarsOff();
      // Smooth normals across the whole surface: glass with creases where the contour's
      // triangles meet at an angle would show every facet.
      vtkNew<vtkPolyDataNormals> normals;
      normals->SetInputConnection(contour->GetOutputPort());
      normals->SplittingOff();
      surface = normals;
    }
    else
    {
      if (first->GetNumberOfCells() > 0 && first->GetMaxCellSize() > 4 &&
        first->GetPointData()->GetScalars())
      {
        // Hexahedra, voxels, tetrahedra...: a volume with scalars, and glass of its outer box
        // is rarely what was meant.
        std::fprintf(stderr,
          "%s: note: %s is a volume; drawing its outer surface (--contour VALUES draws an "
          "isosurface of its point scalars)\n",
          rfViewerProgram(), rfViewerQuote(reader->GetFiles()[0]).c_str());
      }
      vtkNew<vtkDataSetSurfaceFilter> outside;
      outside->SetInputConnection(reader->GetOutputPort());
      if (first->GetPointData()->GetNormals())
      {
        surface = outside;
      }
      else
      {
        // VTK's default: sharp edges above 30 degrees stay sharp (a cube stays a cube).
        vtkNew<vtkPolyDataNormals> normals;
        normals->SetInputConnection(outside->GetOutputPort());
        surface = normals;
      }
    }
  }

  vtkNew<vtkCallbackCommand> sourceProgress;
  sourceProgress->SetCallback(OnStageProgress);
  sourceProgress->SetClientData(&scene.SourceProgress);
  scene.Source->AddObserver(vtkCommand::ProgressEvent, sourceProgress);

  // ISR's d_N, recomputed whenever the surface changes; DIR needs nothing of the kind.
  scene.Distances = vtkSmartPointer<vtkISRDistanceFilter>::New();
  scene.Distances->SetInputConnection(surface->GetOutputPort());
  vtkNew<vtkCallbackCommand> distanceProgress;
  distanceProgress->SetCallback(OnStageProgress);
  distanceProgress->SetClientData(&scene.DistanceProgress);
  scene.Distances->AddObserver(vtkCommand::ProgressEvent, distanceProgress);
  scene.Surface = scene.Distances;

  scene.Surface->UpdateInformation();
  vtkInformation* info = scene.Surface->GetOutputInformation(0);
  if (info->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()))
  {
    const double* steps = info->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    scene.Times.assign(
      steps, steps + info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()));
  }

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(scene.Surface->GetOutputPort());
  mapper->ScalarVisibilityOff();
  scene.Glass = vtkSmartPointer<vtkActor>::New();
  scene.Glass->SetMapper(mapper);
  vtkRefractionPass::MakeGlass(scene.Glass, s.IOR);
  if (s.Dispersion.size() == 3)
  {
    vtkRefractionPass::SetDispersion(
      scene.Glass, s.Dispersion[0], s.Dispersion[1], s.Dispersion[2]);
  }
  if (!o.Demo.empty() || !s.ContourValues.empty())
  {
    // A contour bounds a solid region of the field: where the sampling box cuts it, it has
    // boundary edges, but it is still the surface of a solid, not a thin sheet.
    vtkRefractionPass::SetSurfaceModel(scene.Glass, vtkRefractionPass::SURFACE_SOLID);
  }
  return RF_VIEWER_OK;
}

// One checkered rectangle of the demo's floor or wall.
vtkSmartPointer<vtkPolyData> MakeCheckered(
  const double origin[3], const double point1[3], const double point2[3], int cells1, int cells2)
{
  vtkNew<vtkCheckerboardSource> board;
  board->SetOrigin(origin[0], origin[1], origin[2]);
  board->SetPoint1(point1[0], point1[1], point1[2]);
  board->SetPoint2(point2[0], point2[1], point2[2]);
  board->SetResolution(cells1, cells2);
  board->Update();
  auto squares = vtkSmartPointer<vtkPolyData>::New();
  squares->ShallowCopy(board->GetOutput());
  return squares;
}

// The demo's stage: a checkered floor under the data and a wall behind it (the camera looks
// down -z), opaque, so that the glass shows a scene bent through it, not only the background.
vtkSmartPointer<vtkActor> MakeDemoStage(const double bounds[6])
{
  const double size = std::max(
    { bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4], 1e-6 });
  const double cell = size / 4.0;
  const double x0 = bounds[0] - 2.5 * size;
  const double x1 = bounds[1] + 2.5 * size;
  const double y0 = bounds[2] - 0.15 * size;
  const double z0 = bounds[4] - 1.2 * size;
  const double z1 = bounds[5] + 1.5 * size;
  const double y1 = bounds[2] + 0.55 * size;
  const int across = static_cast<int>(std::lround((x1 - x0) / cell));
  const double floorOrigin[3] = { x0, y0, z1 };
  const double floorRight[3] = { x1, y0, z1 };
  const double floorBack[3] = { x0, y0, z0 };
  const double wallUp[3] = { x0, y1, z0 };
  const double wallRight[3] = { x1, y0, z0 };
  vtkNew<vtkAppendPolyData> stage;
  stage->AddInputData(MakeCheckered(floorOrigin, floorRight, floorBack, across,
    static_cast<int>(std::lround((z1 - z0) / cell))));
  stage->AddInputData(MakeCheckered(floorBack, wallRight, wallUp, across,
    static_cast<int>(std::lround((y1 - y0) / cell))));
  vtkNew<vtkLookupTable> colours;
  colours->SetNumberOfTableValues(2);
  colours->SetTableValue(0, 0.85, 0.83, 0.78);
  colours->SetTableValue(1, 0.22, 0.3, 0.42);
  colours->SetTableRange(0.0, 1.0);
  colours->Build();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(stage->GetOutputPort());
  mapper->SetLookupTable(colours);
  mapper->SetScalarModeToUseCellData();
  mapper->SetScalarRange(0.0, 1.0);
  mapper->InterpolateScalarsBeforeMappingOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetAmbient(0.45);
  actor->GetProperty()->SetDiffuse(0.6);
  return actor;
}

int BuildScene(const rfViewerOptions& o, const rfViewerSettings& s, Scene& scene)
{
  const int status = BuildPipeline(o, s, scene);
  if (status != RF_VIEWER_OK)
  {
    return status;
  }
  scene.Renderer = vtkSmartPointer<vtkRenderer>::New();
  scene.Renderer->AddActor(scene.Glass);
  if (!o.Demo.empty())
  {
    vtkNew<vtkConeSource> cone;
    cone->SetResolution(48);
    cone->SetCenter(1.9, -0.3, 0.0);
    cone->SetDirection(0.0, 1.0, 0.0);
    cone->SetHeight(1.4);
    cone->SetRadius(0.5);
    vtkNew<vtkPolyDataMapper> coneMapper;
    coneMapper->SetInputConnection(cone->GetOutputPort());
    scene.Cone = vtkSmartPointer<vtkActor>::New();
    scene.Cone->SetMapper(coneMapper);
    scene.Cone->GetProperty()->SetColor(0.9, 0.55, 0.1);
    scene.Renderer->AddActor(scene.Cone);
    vtkDataSet* volume = vtkDataSet::SafeDownCast(scene.Source->GetOutputDataObject(0));
    scene.Source->Update();
    if (volume && volume->GetNumberOfPoints() > 0)
    {
      double bounds[6];
      volume->GetBounds(bounds);
      scene.Floor = MakeDemoStage(bounds);
      scene.Renderer->AddActor(scene.Floor);
    }
  }
  scene.Renderer->SetBackground(s.Background);
  if (s.Gradient)
  {
    scene.Renderer->SetBackground2(s.Background + 3);
    scene.Renderer->GradientBackgroundOn();
  }
  const bool builtinSky = o.Environment == "builtin";
  if (!o.Environment.empty() && !builtinSky)
  {
#ifdef REFRACTION_HAVE_IO
    std::string error;
    vtkSmartPointer<vtkTexture> environment =
      vtkRefractionImageIO::ReadEnvironment(o.Environment, &error);
    if (!environment)
    {
      return rfViewerBadInput("--environment: " + error);
    }
    scene.Renderer->SetEnvironmentTexture(environment);
    scene.Sky = vtkSmartPointer<vtkSkybox>::New();
    scene.Sky->SetTexture(environment);
    scene.Sky->SetProjectionToCube();
    scene.Renderer->AddActor(scene.Sky);
#else
    return rfViewerBadInput("--environment: built without image I/O (REFRACTION_BUILD_IO=OFF)");
#endif
  }
  scene.Pass = vtkSmartPointer<vtkRefractionPass>::New();
  if (builtinSky)
  {
    scene.Pass->SetEnvironmentModeToBuiltin();
  }
  scene.Pass->SetMethod(s.Method);
  scene.Pass->SetSearchSteps(s.Steps);
  scene.Pass->SetPeelLayers(s.Layers);
  scene.Pass->SetAntiAliasing(o.AntiAliasing);
  scene.Renderer->SetPass(scene.Pass);

  scene.Text = vtkSmartPointer<vtkTextActor>::New();
  scene.Text->GetTextProperty()->SetFontSize(std::max(10, std::min(s.Width, s.Height) / 32));
  scene.Text->GetTextProperty()->SetColor(1.0, 1.0, 1.0);
  scene.Text->GetTextProperty()->SetBackgroundColor(0.0, 0.0, 0.0);
  scene.Text->GetTextProperty()->SetBackgroundOpacity(0.5);
  scene.Text->SetPosition(4, 4);
  scene.Text->SetVisibility(!o.NoText);
  scene.Renderer->AddActor2D(scene.Text);
  return RF_VIEWER_OK;
}

void SetStatus(Scene& scene, double milliseconds, int timeIndex)
{
  std::ostringstream line;
  line.setf(std::ios::fixed);
  line.precision(2);
  line << MethodName(scene.Pass->GetMethod()) << "  IOR "
       << vtkRefractionPass::GetIndexOfRefraction(scene.Glass);
  if (scene.Pass->GetMethod() == vtkRefractionPass::DIR)
  {
    line << "  " << scene.Pass->GetSearchSteps() << " steps";
  }
  if (scene.Pass->GetAntiAliasing())
  {
    line << "  AA";
  }
  line.precision(1);
  line << "  " << milliseconds << " ms";
  if (!scene.Times.empty())
  {
    line.precision(3);
    line << "  time " << scene.Times[timeIndex] << " (" << timeIndex + 1 << "/" << scene.Times.size()
         << ")";
  }
  scene.Text->SetInput(line.str().c_str());
}

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

int TimeIndexOf(const Scene& scene, double time)
{
  if (scene.Times.empty())
  {
    return 0;
  }
  const auto after = std::upper_bound(scene.Times.begin(), scene.Times.end(), time + 1e-12);
  return after == scene.Times.begin() ? 0 : static_cast<int>(after - scene.Times.begin()) - 1;
}

// Fitted to the input's bounds rather than the first surface: a contour can grow to fill its
// volume later on, and the camera should not have to move for it.
void PlaceCamera(Scene& scene, const rfViewerSettings& s)
{
  vtkRenderer* renderer = scene.Renderer;
  double bounds[6];
  vtkBoundingBox box;
  vtkDataSet* data = vtkDataSet::SafeDownCast(scene.Source->GetOutputDataObject(0));
  if (data && data->GetNumberOfPoints() > 0)
  {
    data->GetBounds(bounds);
    box.AddBounds(bounds);
  }
  for (vtkActor* actor : { scene.Glass.Get(), scene.Cone.Get() })
  {
    if (actor && vtkMath::AreBoundsInitialized(actor->GetBounds()))
    {
      box.AddBounds(actor->GetBounds());
    }
  }
  if (box.IsValid())
  {
    box.GetBounds(bounds);
    renderer->ResetCamera(bounds);
  }
  else
  {
    renderer->ResetCamera();
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->Azimuth(s.Azimuth);
  camera->Elevation(s.Elevation);
  camera->OrthogonalizeViewUp();
  camera->Dolly(s.Zoom);
  renderer->ResetCameraClippingRange();
}

double RenderMilliseconds(vtkRenderWindow* window)
{
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  window->Render();
  glFinish();
  timer->StopTimer();
  return timer->GetElapsedTime() * 1e3;
}

vtkSmartPointer<vtkImageData> Grab(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(grab->GetOutput());
  return image;
}

bool WritePNG(vtkImageData* image, const std::string& path)
{
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    std::fprintf(stderr, "%s: cannot write %s\n", rfViewerProgram(), path.c_str());
    return false;
  }
  return true;
}

// The glass's silhouette: the glass actor alone, flat white on black.
vtkSmartPointer<vtkImageData> GrabMask(Scene& scene, vtkRenderWindow* window)
{
  vtkRenderer* renderer = scene.Renderer;
  const double ior = vtkRefractionPass::GetIndexOfRefraction(scene.Glass);
  double background[3];
  renderer->GetBackground(background);
  const bool gradient = renderer->GetGradientBackground();
  std::vector<vtkProp*> hidden;
  for (vtkProp* prop : { static_cast<vtkProp*>(scene.Cone.Get()),
         static_cast<vtkProp*>(scene.Floor.Get()), static_cast<vtkProp*>(scene.Sky.Get()),
         static_cast<vtkProp*>(scene.Text.Get()) })
  {
    if (prop && prop->GetVisibility())
    {
      prop->SetVisibility(false);
      hidden.push_back(prop);
    }
  }
  vtkRefractionPass::ClearGlass(scene.Glass);
  vtkProperty* property = scene.Glass->GetProperty();
  property->LightingOff();
  property->SetColor(1.0, 1.0, 1.0);
  renderer->SetBackground(0.0, 0.0, 0.0);
  renderer->GradientBackgroundOff();
  // The pass draws the glass where a pixel's centre is covered; a multisampled window would
  // blend the plain actor's edge pixels by coverage instead, so the mask is single-sampled.
  const int samples = window->GetMultiSamples();
  window->SetMultiSamples(0);
  window->Render();
  vtkSmartPointer<vtkImageData> mask = Grab(window);
  window->SetMultiSamples(samples);
  property->LightingOn();
  renderer->SetBackground(background);
  renderer->SetGradientBackground(gradient);
  vtkRefractionPass::MakeGlass(scene.Glass, ior);
  for (vtkProp* prop : hidden)
  {
    prop->SetVisibility(true);
  }
  return mask;
}

vtkSmartPointer<vtkImageData> ContactSheet(
  const std::vector<vtkSmartPointer<vtkImageData>>& tiles, int columns)
{
  const int rows = static_cast<int>((tiles.size() + columns - 1) / columns);
  vtkNew<vtkImageAppend> sheet;
  sheet->SetAppendAxis(1);
  // VTK's rows go up: append the last row of tiles first so that the first frame is top left.
  for (int row = rows - 1; row >= 0; --row)
  {
    vtkNew<vtkImageAppend> line;
    line->SetAppendAxis(0);
    for (int column = 0; column < columns; ++column)
    {
      const size_t index = static_cast<size_t>(row) * columns + column;
      if (index < tiles.size())
      {
        line->AddInputData(tiles[index]);
      }
      else
      {
        vtkNew<vtkImageData> blank;
        blank->CopyStructure(tiles[0]);
        blank->AllocateScalars(tiles[0]->GetScalarType(), tiles[0]->GetNumberOfScalarComponents());
        std::memset(blank->GetScalarPointer(), 0,
          static_cast<size_t>(blank->GetNumberOfPoints()) *
            blank->GetNumberOfScalarComponents() * blank->GetScalarSize());
        line->AddInputData(blank);
      }
    }
    line->Update();
    auto copy = vtkSmartPointer<vtkImageData>::New();
    copy->DeepCopy(line->GetOutput());
    sheet->AddInputData(copy);
  }
  sheet->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(sheet->GetOutput());
  return image;
}

struct InteractiveState
{
  Scene* TheScene;
  bool Animate = true;
  int TimeIndex = 0;
};

void OnRenderEnd(vtkObject*, unsigned long, void* clientData, void*)
{
  auto* state = static_cast<InteractiveState*>(clientData);
  SetStatus(*state->TheScene, state->TheScene->Renderer->GetLastRenderTimeInSeconds() * 1e3,
    state->TimeIndex);
}

void OnKey(vtkObject* caller, unsigned long, void* clientData, void*)
{
  auto* state = static_cast<InteractiveState*>(clientData);
  Scene& scene = *state->TheScene;
  auto* interactor = static_cast<vtkRenderWindowInteractor*>(caller);
  const std::string key = interactor->GetKeySym() ? interactor->GetKeySym() : "";
  const int steps = static_cast<int>(scene.Times.size());
  if (key == "m")
  {
    // DIR -> SIR -> ISR -> SSP -> PEEL -> DIR
    static const int next[] = { vtkRefractionPass::ISR, vtkRefractionPass::SIR,
      vtkRefractionPass::SSP, vtkRefractionPass::PEEL, vtkRefractionPass::DIR };
    scene.Pass->SetMethod(next[scene.Pass->GetMethod()]);
  }
  else if (key == "i" || key == "I")
  {
    const double ior = vtkRefractionPass::GetIndexOfRefraction(scene.Glass);
    const double changed = std::min(10.0, std::max(0.1, ior + (key == "I" ? 0.05 : -0.05)));
    vtkRefractionPass::MakeGlass(scene.Glass, changed);
  }
  else if (key == "plus" || key == "equal" || key == "KP_Add")
  {
    scene.Pass->SetSearchSteps(std::min(scene.Pass->GetSearchSteps() + 1, 16));
  }
  else if (key == "minus" || key == "KP_Subtract")
  {
    scene.Pass->SetSearchSteps(std::max(scene.Pass->GetSearchSteps() - 1, 0));
  }
  else if (key == "space")
  {
    state->Animate = !state->Animate;
  }
  else if ((key == "Right" || key == "Left") && steps > 0)
  {
    // Arrows rather than letters: the interactor style takes 'p' (pick) and others.
    state->Animate = false;
    state->TimeIndex = (state->TimeIndex + (key == "Right" ? 1 : steps - 1)) % steps;
    ShowTime(scene, scene.Times[state->TimeIndex]);
  }
  else
  {
    return;
  }
  interactor->GetRenderWindow()->Render();
  // The same line in the terminal, for a record of what was looked at.
  std::printf("%s\n", scene.Text->GetInput());
  std::fflush(stdout);
}

void OnTimer(vtkObject* caller, unsigned long, void* clientData, void*)
{
  auto* state = static_cast<InteractiveState*>(clientData);
  Scene& scene = *state->TheScene;
  if (!state->Animate || scene.Times.size() < 2)
  {
    return;
  }
  state->TimeIndex = (state->TimeIndex + 1) % static_cast<int>(scene.Times.size());
  ShowTime(scene, scene.Times[state->TimeIndex]);
  static_cast<vtkRenderWindowInteractor*>(caller)->GetRenderWindow()->Render();
}

int RunInteractive(Scene& scene, vtkRenderWindow* window, int timeIndex)
{
  vtkNew<vtkRenderWindowInteractor> interactor;
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  interactor->SetInteractorStyle(style);
  interactor->SetRenderWindow(window);
  InteractiveState state{ &scene, true, timeIndex };
  vtkNew<vtkCallbackCommand> keys;
  keys->SetCallback(OnKey);
  keys->SetClientData(&state);
  // Before the style's own handlers: 'i' would otherwise be taken by nothing, but '+'/'-'
  // and others are harmless; keep ours first anyway.
  interactor->AddObserver(vtkCommand::KeyPressEvent, keys, 1.0);
  vtkNew<vtkCallbackCommand> timer;
  timer->SetCallback(OnTimer);
  timer->SetClientData(&state);
  interactor->AddObserver(vtkCommand::TimerEvent, timer);
  vtkNew<vtkCallbackCommand> status;
  status->SetCallback(OnRenderEnd);
  status->SetClientData(&state);
  scene.Renderer->AddObserver(vtkCommand::EndEvent, status);
  interactor->Initialize();
  interactor->CreateRepeatingTimer(40);
  SetStatus(scene, 0.0, timeIndex);
  window->Render();
  std::printf("keys: m method, i/I index of refraction, +/- search steps, space animation, "
              "Right/Left time step\n");
  std::fflush(stdout);
  interactor->Start();
  return RF_VIEWER_OK;
}

double MedianFrameMilliseconds(Scene& scene, vtkRenderWindow* window, int frames)
{
  std::vector<double> times;
  for (int i = 0; i < 5 + frames; ++i)
  {
    scene.Renderer->GetActiveCamera()->Azimuth(1.0);
    const double ms = RenderMilliseconds(window);
    if (i >= 5)
    {
      times.push_back(ms);
    }
  }
  std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
  return times[times.size() / 2];
}

void ReportTiming(Scene& scene, vtkRenderWindow* window, const rfViewerSettings& s)
{
  const bool text = scene.Text->GetVisibility() != 0;
  scene.Text->SetVisibility(false);
  const vtkIdType triangles =
    vtkPolyData::SafeDownCast(scene.Surface->GetOutputDataObject(0))->GetNumberOfPolys();
  double ms[5];
  for (int method : { vtkRefractionPass::DIR, vtkRefractionPass::SIR, vtkRefractionPass::ISR,
         vtkRefractionPass::SSP, vtkRefractionPass::PEEL })
  {
    scene.Pass->SetMethod(method);
    ms[method] = MedianFrameMilliseconds(scene, window, s.Timing);
  }
  scene.Pass->SetMethod(s.Method);
  const double ior = vtkRefractionPass::GetIndexOfRefraction(scene.Glass);
  vtkRefractionPass::ClearGlass(scene.Glass);
  const double plain = MedianFrameMilliseconds(scene, window, s.Timing);
  vtkRefractionPass::MakeGlass(scene.Glass, ior);
  scene.Text->SetVisibility(text);
  std::printf("median frame time over %d frames at %dx%d, %lld triangles, renderer: %s\n",
    s.Timing, s.Width, s.Height, static_cast<long long>(triangles),
    reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  std::printf("  DIR (%d steps)  %8.2f ms  (%.2fx plain)\n", s.Steps, ms[vtkRefractionPass::DIR],
    ms[vtkRefractionPass::DIR] / plain);
  std::printf("  SIR             %8.2f ms  (%.2fx plain)\n", ms[vtkRefractionPass::SIR],
    ms[vtkRefractionPass::SIR] / plain);
  std::printf("  ISR             %8.2f ms  (%.2fx plain), plus %.2f ms of d_N ray casting each "
              "time the surface changes\n",
    ms[vtkRefractionPass::ISR], ms[vtkRefractionPass::ISR] / plain,
    scene.Distances->GetLastComputeSeconds() * 1e3);
  std::printf("  SSP             %8.2f ms  (%.2fx plain)\n", ms[vtkRefractionPass::SSP],
    ms[vtkRefractionPass::SSP] / plain);
  std::printf("  PEEL (%d layers) %7.2f ms  (%.2fx plain)\n", s.Layers,
    ms[vtkRefractionPass::PEEL], ms[vtkRefractionPass::PEEL] / plain);
  std::printf("  plain VTK       %8.2f ms\n", plain);
}

int RunHeadless(const rfViewerOptions& o, const rfViewerSettings& s, Scene& scene, vtkRenderWindow* window,
  int firstIndex)
{
  // The first frame compiles shaders and converts the environment: not a frame time to show.
  scene.Text->SetInput("");
  window->Render();
  if (!o.Screenshot.empty())
  {
    const double ms = RenderMilliseconds(window);
    SetStatus(scene, ms, firstIndex);
    window->Render();
    if (!WritePNG(Grab(window), o.Screenshot))
    {
      return RF_VIEWER_FAILED;
    }
    std::printf("wrote %s (%dx%d)\n", o.Screenshot.c_str(), s.Width, s.Height);
  }

  const bool sequence = !o.OutDir.empty() || !o.ContactSheet.empty();
  if (sequence)
  {
    const int steps = static_cast<int>(scene.Times.size());
    const int frames = s.Frames > 0 ? s.Frames : std::max(steps, 1);
    // The frames that go on the contact sheet, spread evenly from the first to the last.
    std::vector<int> sheetFrames;
    const int tiles = std::min(frames, s.SheetFrames);
    for (int k = 0; k < tiles; ++k)
    {
      sheetFrames.push_back(tiles > 1 ? static_cast<int>(std::lround(
                                          static_cast<double>(k) * (frames - 1) / (tiles - 1)))
                                      : 0);
    }
    std::vector<vtkSmartPointer<vtkImageData>> sheet;
    ProgressLine progress("frames", frames);
    double lastMs = RenderMilliseconds(window);
    for (int frame = 0; frame < frames; ++frame)
    {
      const int index = steps > 0 ? frame % steps : 0;
      if (steps > 0)
      {
        ShowTime(scene, scene.Times[index]);
      }
      if (frame > 0 && s.Orbit != 0.0)
      {
        scene.Renderer->GetActiveCamera()->Azimuth(s.Orbit);
      }
      scene.Renderer->ResetCameraClippingRange();
      // The status line shows the time of the frame before (it is drawn within the frame).
      SetStatus(scene, lastMs, index);
      lastMs = RenderMilliseconds(window);
      vtkSmartPointer<vtkImageData> image = Grab(window);
      if (!o.OutDir.empty())
      {
        char name[32];
        std::snprintf(name, sizeof(name), "frame_%04d.png", frame);
        if (!WritePNG(image, o.OutDir + "/" + name))
        {
          return RF_VIEWER_FAILED;
        }
        if (o.Masks)
        {
          std::snprintf(name, sizeof(name), "mask_%04d.png", frame);
          if (!WritePNG(GrabMask(scene, window), o.OutDir + "/" + name))
          {
            return RF_VIEWER_FAILED;
          }
        }
      }
      if (std::find(sheetFrames.begin(), sheetFrames.end(), frame) != sheetFrames.end())
      {
        sheet.push_back(image);
      }
      progress.Update(frame + 1);
    }
    if (!o.OutDir.empty())
    {
      std::printf("wrote %d frames to %s/frame_NNNN.png (%dx%d)%s\n", frames, o.OutDir.c_str(),
        s.Width, s.Height, o.Masks ? " and mask_NNNN.png" : "");
    }
    if (!o.ContactSheet.empty())
    {
      const int columns = std::min(s.SheetColumns, static_cast<int>(sheet.size()));
      if (!WritePNG(ContactSheet(sheet, columns), o.ContactSheet))
      {
        return RF_VIEWER_FAILED;
      }
      std::printf("wrote %s (%zu frames, %d columns)\n", o.ContactSheet.c_str(), sheet.size(),
        columns);
    }
  }

  if (s.Timing > 0)
  {
    ShowTime(scene, scene.Times.empty() ? 0.0 : scene.Times[firstIndex]);
    ReportTiming(scene, window, s);
  }
  return RF_VIEWER_OK;
}

// Output paths are checked before anything is rendered, so that a typo costs no time.
int CheckOutputs(const rfViewerOptions& o)
{
  if (!o.OutDir.empty())
  {
    if (vtksys::SystemTools::FileExists(o.OutDir, true))
    {
      return rfViewerBadInput("--out: " + rfViewerQuote(o.OutDir) + " is a file, not a folder");
    }
    if (!vtksys::SystemTools::MakeDirectory(o.OutDir))
    {
      return rfViewerBadInput("--out: cannot create the folder " + rfViewerQuote(o.OutDir));
    }
  }
  for (const std::string* file : { &o.Screenshot, &o.ContactSheet })
  {
    if (file->empty())
    {
      continue;
    }
    const std::string folder = vtksys::SystemTools::GetFilenamePath(*file);
    if (!folder.empty() && !vtksys::SystemTools::FileIsDirectory(folder))
    {
      return rfViewerBadInput("cannot write " + rfViewerQuote(*file) + ": no folder " + rfViewerQuote(folder));
    }
    if (vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(*file)) !=
      ".png")
    {
      return rfViewerBadInput("cannot write " + rfViewerQuote(*file) + ": images are written as .png");
    }
  }
  return RF_VIEWER_OK;
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
