#include "rfBenchScaling.h"

#include "rfBenchReport.h"
#include "rfBenchScene.h"
#include "rfBenchSettings.h"
#include "rfBenchTiming.h"
#include "vtkISRDistanceFilter.h"
#include "vtkRefractionPass.h"

#include <vtkAxis.h>
#include <vtkCamera.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDelimitedTextWriter.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkStringArray.h>
#include <vtkTable.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <random>

namespace rfbench
{
namespace
{
// One point of the sweep: a sphere of `Resolution` (theta = phi) in a window of Width x Height.
struct Cell
{
  int Resolution, Width, Height;
};

// The triangles sweep at the benchmark's 512 x 512, the pixels sweep at 79,200 triangles
// (the 8 thousand to 4 million triangles; 512 to 3840 x 2160 pixels); --smoke keeps
// the same shape, tiny, for the test that the sweep runs and writes what it should.
std::vector<Cell> Cells(const Options& o)
{
  if (o.Smoke)
  {
    return { { 12, 96, 96 }, { 24, 96, 96 }, { 24, 192, 108 } };
  }
  const int middle = 200;
  std::vector<Cell> cells;
  for (int resolution : { 64, middle, 640, 1400 })
    cells.push_back({ resolution, 512, 512 });
  cells.push_back({ middle, 1024, 1024 });
  cells.push_back({ middle, 2048, 2048 });
  cells.push_back({ middle, 3840, 2160 });
  return cells;
}

// The glass methods at their defaults (DIR 5, PEEL with 4 layers) and DIR 5 with coarse
// shading, less those --methods leaves out; plain VTK is timed with each of them.
std::vector<Setting> ScalingSettings(const Options& o)
{
  Setting peel{ "PEEL", 0 };
  peel.Layers = 4;
  Setting coarse{ "DIR", 5 };
  coarse.Coarse = true;
  std::vector<Setting> settings;
  for (const Setting& s : { Setting{ "DIR", 5 }, coarse, Setting{ "SIR", 0 }, Setting{ "ISR", 0 },
         Setting{ "SSP", 0 }, peel })
  {
    if (o.Methods.empty() || std::find(o.Methods.begin(), o.Methods.end(), s.Method) != o.Methods.end())
    {
      settings.push_back(s);
    }
  }
  return settings;
}

struct Samples
{
  std::vector<double> Glass, Plain, Ratio;
  double PrecomputeMs = 0.0, BytesPerPixel = 0.0;
};

// The sphere fills the window's height (VTK's view angle is vertical).
void Frame(vtkRenderWindow* window, vtkRenderer* renderer, vtkActor* actor, const Cell& cell)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 0.0, 1.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(30.0);
  renderer->ResetCamera(actor->GetBounds());
  // ResetCamera fits the bounding box's sphere (sqrt 3 times the ball's radius) in the view.
  camera->Dolly(1.6);
  renderer->ResetCameraClippingRange();
  window->SetSize(cell.Width, cell.Height);
}

std::string SizeLabel(const Cell& c)
{
  return std::to_string(c.Width) + "x" + std::to_string(c.Height);
}

// One chart per PNG: milliseconds (log) against triangles or pixels (log), one line per
// method, plain VTK included.
bool Plot(vtkRenderWindow* window, const std::string& path, const std::string& title,
  const std::string& xTitle, const std::vector<std::string>& methods,
  const std::map<std::string, std::vector<std::pair<double, double>>>& lines)
{
  vtkNew<vtkContextView> view;
  ShowChartView(window, view);
  window->SetSize(900, 700);
  vtkNew<vtkChartXY> chart;
  view->GetScene()->AddItem(chart);
  chart->SetTitle(title);
  chart->SetShowLegend(true);
  chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::LEFT);
  chart->GetLegend()->SetVerticalAlignment(vtkChartLegend::TOP);
  chart->GetAxis(vtkAxis::BOTTOM)->SetTitle(xTitle);
  chart->GetAxis(vtkAxis::LEFT)->SetTitle("milliseconds per frame (median of repeats)");
  const unsigned char colours[][3] = { { 0, 0, 0 }, { 31, 119, 180 }, { 120, 120, 120 },
    { 214, 39, 40 }, { 148, 103, 189 }, { 227, 119, 194 }, { 44, 160, 44 } };
  double range[2][2] = { { 1e300, 0.0 }, { 1e300, 0.0 } };
  int colour = 0;
  for (const std::string& method : methods)
  {
    auto found = lines.find(method);
    if (found == lines.end() || found->second.empty())
    {
      ++colour;
      continue;
    }
    std::vector<std::pair<double, double>> points = found->second;
    std::sort(points.begin(), points.end());
    vtkNew<vtkTable> table;
    vtkNew<vtkDoubleArray> x;
    vtkNew<vtkDoubleArray> y;
    x->SetName("x");
    y->SetName(method.c_str());
    table->AddColumn(x);
    table->AddColumn(y);
    table->SetNumberOfRows(static_cast<vtkIdType>(points.size()));
    for (size_t i = 0; i < points.size(); ++i)
    {
      table->SetValue(static_cast<vtkIdType>(i), 0, points[i].first);
      table->SetValue(static_cast<vtkIdType>(i), 1, points[i].second);
      range[0][0] = std::min(range[0][0], points[i].first);
      range[0][1] = std::max(range[0][1], points[i].first);
      range[1][0] = std::min(range[1][0], points[i].second);
      range[1][1] = std::max(range[1][1], points[i].second);
    }
    vtkPlot* plot = chart->AddPlot(vtkChart::LINE);
    plot->SetInputData(table, 0, 1);
    const unsigned char* c = colours[colour % 7];
    plot->SetColor(c[0], c[1], c[2], 255);
    plot->SetWidth(method == "plain VTK" ? 3.0 : 2.0);
    if (auto* line = vtkPlotPoints::SafeDownCast(plot))
    {
      line->SetMarkerStyle(vtkPlotPoints::CIRCLE);
    }
    ++colour;
  }
  if (range[0][1] <= 0.0)
  {
    return true; // nothing to plot
  }
  for (int a = 0; a < 2; ++a)
  {
    vtkAxis* axis = chart->GetAxis(a == 0 ? vtkAxis::BOTTOM : vtkAxis::LEFT);
    axis->SetLogScale(true);
    axis->SetBehavior(vtkAxis::FIXED);
    // A margin of a fifth of a decade, so that no point is drawn on the frame.
    axis->SetUnscaledRange(range[a][0] / 1.6, range[a][1] * 1.6);
  }
  return WriteChartPng(window, view, path);
}
}

void ScalingWindowSize(const Options& o, int& width, int& height)
{
  width = 900; // the plots'
  height = 700;
  for (const Cell& c : Cells(o))
  {
    width = std::max(width, c.Width);
    height = std::max(height, c.Height);
  }
}

bool RunScaling(vtkRenderWindow* window, vtkRenderer* renderer, const Options& o,
  const std::string& rendererName)
{
  const std::vector<Cell> cells = Cells(o);
  const std::vector<Setting> settings = ScalingSettings(o);
  if (settings.empty())
  {
    std::fprintf(stderr, "--methods leaves no method of the scaling sweep (DIR, SIR, ISR, SSP, PEEL)\n");
    return false;
  }
  // One mesh per resolution, with ISR's d_N (its seconds reported as the precomputation).
  std::map<int, Scene> meshes;
  for (const Cell& cell : cells)
  {
    if (meshes.count(cell.Resolution))
    {
      continue;
    }
    vtkNew<vtkSphereSource> sphere;
    sphere->SetThetaResolution(cell.Resolution);
    sphere->SetPhiResolution(cell.Resolution);
    auto distances = vtkSmartPointer<vtkISRDistanceFilter>::New();
    distances->SetInputConnection(sphere->GetOutputPort());
    distances->Update();
    Scene scene;
    scene.Name = "sphere";
    scene.Mesh = distances;
    scene.Triangles = vtkPolyData::SafeDownCast(distances->GetOutput())->GetNumberOfPolys();
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(distances->GetOutputPort());
    mapper->ScalarVisibilityOff();
    scene.Actor = vtkSmartPointer<vtkActor>::New();
    scene.Actor->SetMapper(mapper);
    meshes[cell.Resolution] = scene;
    std::printf("sphere of %lld triangles: d_N in %.2f s\n",
      static_cast<long long>(scene.Triangles), distances->GetLastComputeSeconds());
    std::fflush(stdout);
  }

  vtkNew<vtkRefractionPass> pass;
  pass->SetEnvironmentModeToBuiltin();
  pass->SetPeelCapture(o.PeelCapture);
  renderer->SetBackground(0.0, 0.0, 0.0);
  renderer->SetGradientBackground(false);
  // Every (cell, method) job `Repeats` times in one seeded shuffled order; each times the glass
  // and then plain VTK on the same mesh in the same window.
  std::vector<std::pair<size_t, size_t>> jobs;
  for (size_t c = 0; c < cells.size(); ++c)
    for (size_t s = 0; s < settings.size(); ++s)
      for (int k = 0; k < o.Repeats; ++k)
        jobs.emplace_back(c, s);
  std::mt19937 random(static_cast<unsigned>(o.Seed));
  std::shuffle(jobs.begin(), jobs.end(), random);
  std::vector<std::vector<Samples>> samples(cells.size(), std::vector<Samples>(settings.size()));
  for (size_t j = 0; j < jobs.size(); ++j)
  {
    const Cell& cell = cells[jobs[j].first];
    const Setting& setting = settings[jobs[j].second];
    const Scene& scene = meshes[cell.Resolution];
    renderer->RemoveAllViewProps();
    renderer->AddActor(scene.Actor);
    Frame(window, renderer, scene.Actor, cell);
    renderer->SetPass(pass);
    SetGlass(scene, true);
    Apply(pass, setting);
    const Timing glass = TimeFrames(window, nullptr, o.Frames);
    Samples& s = samples[jobs[j].first][jobs[j].second];
    s.BytesPerPixel = static_cast<double>(pass->GetTextureBytes()) /
      (static_cast<double>(cell.Width) * cell.Height);
    if (setting.Method == "ISR")
    {
      s.PrecomputeMs =
        vtkISRDistanceFilter::SafeDownCast(scene.Mesh)->GetLastComputeSeconds() * 1e3;
    }
    SetGlass(scene, false);
    renderer->SetPass(nullptr);
    const Timing plain = TimeFrames(window, nullptr, o.Frames);
    s.Glass.push_back(glass.Cpu);
    s.Plain.push_back(plain.Cpu);
    s.Ratio.push_back(glass.Cpu / plain.Cpu);
    std::printf("job %zu of %zu: %9lld triangles %-9s %-7s %9.1f ms, plain %8.1f ms, ratio %.2f\n",
      j + 1, jobs.size(), static_cast<long long>(scene.Triangles), SizeLabel(cell).c_str(),
      setting.Label().c_str(), glass.Cpu, plain.Cpu, glass.Cpu / plain.Cpu);
    std::fflush(stdout);
  }
  renderer->RemoveAllViewProps();
  pass->ReleaseGraphicsResources(window);

  // The table: one row per cell and method, plain VTK's own row from all its samples there.
  vtkNew<vtkTable> table;
  const char* intColumns[] = { "triangles", "width", "height", "repeats" };
  const char* doubleColumns[] = { "ms_median", "ms_min", "ms_max", "ratio_median", "ratio_min",
    "ratio_max", "precompute_ms", "bytes_per_pixel" };
  vtkNew<vtkStringArray> methodColumn;
  methodColumn->SetName("method");
  table->AddColumn(methodColumn);
  for (const char* name : intColumns)
  {
    vtkNew<vtkIntArray> column;
    column->SetName(name);
    table->AddColumn(column);
  }
  for (const char* name : doubleColumns)
  {
    vtkNew<vtkDoubleArray> column;
    column->SetName(name);
    table->AddColumn(column);
  }
  std::vector<std::string> methods{ "plain VTK" };
  for (const Setting& s : settings)
    methods.push_back(s.Label());
  std::map<std::string, std::vector<std::pair<double, double>>> byTriangles, byPixels;
  std::ofstream md(o.Out + "/scaling.md");
  md << "# Scaling: frame time against triangles and pixels\n\nRenderer: " << rendererName
     << ". A glass sphere filling the window's height, over the built-in environment; "
     << o.Repeats << " repeats of " << o.Frames
     << " timed frames (after 5 warm-up frames) per method and cell, in one shuffled order "
        "(seed "
     << o.Seed << "); each timed with plain VTK right after it. Median (min-max) over the "
                  "repeats; the ratio is of each repeat to its own plain render.\n\n"
     << "| triangles | pixels | method | ms | x plain | precompute ms | bytes/pixel |\n"
     << "|---|---|---|---|---|---|---|\n";
  char text[256];
  for (size_t c = 0; c < cells.size(); ++c)
  {
    const Cell& cell = cells[c];
    const vtkIdType triangles = meshes[cell.Resolution].Triangles;
    std::vector<double> plain;
    for (const Samples& s : samples[c])
      plain.insert(plain.end(), s.Plain.begin(), s.Plain.end());
    for (size_t m = 0; m < methods.size(); ++m)
    {
      const Samples* s = m == 0 ? nullptr : &samples[c][m - 1];
      const Spread ms = SpreadOf(m == 0 ? plain : s->Glass);
      const Spread ratio = m == 0 ? SpreadOf({ 1.0 }) : SpreadOf(s->Ratio);
      const vtkIdType row = table->InsertNextBlankRow();
      table->SetValue(row, 0, vtkVariant(methods[m]));
      table->SetValue(row, 1, vtkVariant(static_cast<int>(triangles)));
      table->SetValue(row, 2, cell.Width);
      table->SetValue(row, 3, cell.Height);
      table->SetValue(row, 4, static_cast<int>(m == 0 ? plain.size() : s->Glass.size()));
      const double values[] = { ms.Median, ms.Min, ms.Max, ratio.Median, ratio.Min, ratio.Max,
        s ? s->PrecomputeMs : 0.0, s ? s->BytesPerPixel : 0.0 };
      for (int v = 0; v < 8; ++v)
        table->SetValue(row, 5 + v, values[v]);
      std::snprintf(text, sizeof(text),
        "| %lld | %s | %s | %.1f (%.1f-%.1f) | %.2f (%.2f-%.2f) | %s | %s |\n",
        static_cast<long long>(triangles), SizeLabel(cell).c_str(), methods[m].c_str(),
        ms.Median, ms.Min, ms.Max, ratio.Median, ratio.Min, ratio.Max,
        s && s->PrecomputeMs > 0.0 ? std::to_string(static_cast<int>(s->PrecomputeMs)).c_str()
                                   : "",
        s ? std::to_string(static_cast<int>(s->BytesPerPixel + 0.5)).c_str() : "");
      md << text;
      if (cell.Width == cells[0].Width && cell.Height == cells[0].Height)
        byTriangles[methods[m]].emplace_back(static_cast<double>(triangles), ms.Median);
      if (cell.Resolution == cells[cells.size() - 1].Resolution)
        byPixels[methods[m]].emplace_back(static_cast<double>(cell.Width) * cell.Height, ms.Median);
    }
  }
  md << "\n![milliseconds against triangles](scaling_triangles.png)\n"
     << "![milliseconds against pixels](scaling_pixels.png)\n";
  md.close();
  vtkNew<vtkDelimitedTextWriter> csv;
  csv->SetInputData(table);
  csv->SetFileName((o.Out + "/scaling.csv").c_str());
  csv->SetUseStringDelimiter(false);
  const bool written = md.good() && csv->Write() == 1;
  const Cell& last = cells[cells.size() - 1];
  const std::string triangleTitle = "Glass sphere filling " + SizeLabel(cells[0]) + " (" +
    rendererName + ")";
  const std::string pixelTitle = "Glass sphere of " +
    std::to_string(meshes[last.Resolution].Triangles) + " triangles filling the window's height";
  if (!written ||
    !Plot(window, o.Out + "/scaling_triangles.png", triangleTitle, "triangles", methods,
      byTriangles) ||
    !Plot(window, o.Out + "/scaling_pixels.png", pixelTitle, "pixels", methods, byPixels))
  {
    std::fprintf(stderr, "cannot write the scaling results into %s\n", o.Out.c_str());
    return false;
  }
  std::printf("wrote %s/scaling.csv, scaling.md, scaling_triangles.png, scaling_pixels.png\n",
    o.Out.c_str());
  return true;
}
}
