#include "rfViewerScene.h"

#include "rfViewer.h"

#include "vtkCheckerboardSource.h"
#include "vtkMetaballsSource.h"
#include "vtkRefractionSeriesReader.h"
#include "vtkWaveEquationSource.h"
#ifdef REFRACTION_HAVE_IO
#include "vtkRefractionImageIO.h"
#endif

#include <vtkAppendPolyData.h>
#include <vtkBoundingBox.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkConeSource.h>
#include <vtkContourFilter.h>
#include <vtkDataSet.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkFlyingEdges3D.h>
#include <vtkInformation.h>
#include <vtkLookupTable.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkTextProperty.h>
#include <vtkTexture.h>
#include <vtkTimerLog.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <unistd.h>

namespace rfviewer
{
namespace
{
const char* MethodName(int method)
{
  static const char* const names[] = { "SIR", "DIR", "ISR", "SSP", "PEEL" };
  return names[method];
}

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
}

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

namespace
{
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
    // Read the first file now, so that an unreadable input is reported before any window,
    // once, in the viewer's words.
    if (!reader->ReadFirstFile())
    {
      return rfViewerBadInput(reader->GetLastError());
    }
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
  scene.Pass->SetPeelCapture(s.PeelCapture);
  scene.Pass->SetAntiAliasing(o.AntiAliasing);
  scene.Pass->SetCoarseShading(o.CoarseShading);
  scene.Pass->SetExitReflection(!o.NoExitReflection);
  scene.Pass->SetSmoothInternalReflections(o.SmoothInternalReflections);
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
  if (scene.Pass->GetCoarseShading() && !scene.Pass->GetAntiAliasing())
  {
    line << "  coarse";
  }
  if (!scene.Pass->GetExitReflection() && scene.Pass->GetMethod() == vtkRefractionPass::DIR)
  {
    line << "  no exit reflection";
  }
  if (scene.Pass->GetSmoothInternalReflections() && !scene.Pass->GetAntiAliasing())
  {
    line << "  smooth TIR";
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
}
