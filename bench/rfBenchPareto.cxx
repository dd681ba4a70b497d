#include "rfBenchPareto.h"

#include "rfBenchReport.h"

#include <vtkAxis.h>
#include <vtkChartMatrix.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>
#include <vtkRenderWindow.h>
#include <vtkTable.h>
#include <vtkVector.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rfbench
{
namespace
{
bool Measured(const CostError& p)
{
  return std::isfinite(p.first) && std::isfinite(p.second) && p.first >= 0.0 && p.second >= 0.0;
}

bool Dominates(const CostError& a, const CostError& b)
{
  return a.first <= b.first && a.second <= b.second && (a.first < b.first || a.second < b.second);
}

// The rows a mesh's front is made of: every glass setting at that size (not the pass without
// glass, not the scene rows without the scene refracted, which draw another picture).
std::vector<const Row*> Candidates(const std::vector<Row>& rows, const std::string& mesh, int size)
{
  std::vector<const Row*> out;
  for (const Row& r : rows)
  {
    if (r.Mesh == mesh && r.Size == size && r.Config.Method != "none" && !r.Config.NoScene)
      out.push_back(&r);
  }
  return out;
}

CostError Point(const Row& r)
{
  return { r.Ratio.Median, r.FullSS.Rmse };
}

// Beats b on the ratio, the glass's error and the rim's (the silhouette's glass pixels, a few
// percent of the glass's, so they weigh little in its figure): the same dominance with the
// rim's PSNR as a third axis, where both rows have rim pixels.
bool DominatesWithRim(const Row& a, const Row& b)
{
  const CostError pa = Point(a);
  const CostError pb = Point(b);
  const double rimA = a.FullSS.PsnrRim;
  const double rimB = b.FullSS.PsnrRim;
  if (!(rimA >= 0.0 && rimB >= 0.0))
    return Dominates(pa, pb);
  return pa.first <= pb.first && pa.second <= pb.second && rimA >= rimB &&
    (pa.first < pb.first || pa.second < pb.second || rimA > rimB);
}

std::string Describe(const Row& r)
{
  char text[160];
  std::snprintf(text, sizeof(text), "%s %.2fx / %s dB", r.Config.Label().c_str(),
    r.Ratio.Median, Db(r.FullSS.Psnr).c_str());
  return text;
}
}

std::vector<size_t> ParetoFront(const std::vector<CostError>& points)
{
  std::vector<size_t> front;
  for (size_t i = 0; i < points.size(); ++i)
  {
    if (!Measured(points[i]))
      continue;
    bool dominated = false;
    for (size_t j = 0; j < points.size() && !dominated; ++j)
    {
      dominated = j != i && Measured(points[j]) && Dominates(points[j], points[i]);
    }
    if (!dominated)
      front.push_back(i);
  }
  std::stable_sort(front.begin(), front.end(),
    [&points](size_t a, size_t b) { return points[a] < points[b]; });
  return front;
}

// The size the plot and the summary show: the one nearest 512 (the paper's Table 1 size).
int SizeNearest512(const std::vector<Row>& rows)
{
  int size = 0;
  for (const Row& r : rows)
  {
    if (size == 0 || std::abs(r.Size - 512) < std::abs(size - 512))
      size = r.Size;
  }
  return size;
}

std::vector<std::string> Meshes(const std::vector<Row>& rows)
{
  std::vector<std::string> meshes;
  for (const Row& r : rows)
  {
    if (std::find(meshes.begin(), meshes.end(), r.Mesh) == meshes.end())
      meshes.push_back(r.Mesh);
  }
  return meshes;
}

bool IsDefaultSetting(const Setting& s)
{
  return s.Method == "DIR" && s.Steps == 5 && !s.Bounds && !s.Adaptive && !s.Nearest &&
    !s.Paper && !s.NoScene && !s.AntiAliasing && !s.PixelComposite && s.Bounces == 0 &&
    !s.PointLookups && s.ExitReflection && !s.Smooth && !s.Coarse;
}

std::string ParetoSummary(const std::vector<Row>& rows)
{
  const int size = SizeNearest512(rows);
  std::string out = "## Pareto front (" + std::to_string(size) + "x" + std::to_string(size) +
    ")\n\nThe rows no other row of the same mesh beats on both the ratio to plain VTK (median) "
    "and the RMSE against the supersampled full reference (pareto.png's axes), in order of "
    "ratio, each as ratio / PSNR against that reference; and whether the pass's default setting "
    "(`DIR 5 exit`) is on the front or which rows dominate it (where the two rows' ratios over the "
    "repeats overlap, the verdict is inside the timing's noise); then the same verdict with "
    "the rim's PSNR as a third axis (a row dominates only if it is also as close on the "
    "silhouette's glass pixels, a few percent of the glass's, which weigh little in its "
    "figure).\n\n"
    "| mesh | on the front | default |\n|---|---|---|\n";
  for (const std::string& mesh : Meshes(rows))
  {
    const std::vector<const Row*> candidates = Candidates(rows, mesh, size);
    std::vector<CostError> points;
    for (const Row* r : candidates)
      points.push_back(Point(*r));
    std::string front;
    for (size_t index : ParetoFront(points))
      front += (front.empty() ? "" : ", ") + Describe(*candidates[index]);
    std::string standing = "not run";
    for (size_t i = 0; i < candidates.size(); ++i)
    {
      if (!IsDefaultSetting(candidates[i]->Config))
        continue;
      std::string by;
      std::string byWithRim;
      for (size_t j = 0; j < candidates.size(); ++j)
      {
        if (j != i && Measured(points[j]) && DominatesWithRim(*candidates[j], *candidates[i]))
        {
          byWithRim += (byWithRim.empty() ? "" : ", ") + candidates[j]->Config.Label();
        }
        if (j != i && Measured(points[j]) && Dominates(points[j], points[i]))
        {
          // Medians can cross by noise alone: say so where the repeats' ratios overlap.
          const bool overlap = candidates[j]->Ratio.Max >= candidates[i]->Ratio.Min &&
            candidates[j]->Ratio.Max > 0.0;
          by += (by.empty() ? "" : ", ") + Describe(*candidates[j]) +
            (overlap ? " (the ratios' spreads overlap)" : "");
        }
      }
      standing = by.empty() ? "on the front" : "dominated by " + by;
      standing += byWithRim.empty() ? "; with the rim's PSNR as a third axis, on the front"
                                    : "; with the rim's PSNR as a third axis, dominated by " +
          byWithRim;
    }
    out += "| " + mesh + " | " + front + " | " + standing + " |\n";
  }
  return out + "\n";
}

bool WritePareto(vtkRenderWindow* window, const std::string& path, const std::vector<Row>& rows)
{
  const std::vector<std::string> meshes = Meshes(rows);
  const int plotSize = SizeNearest512(rows);
  if (meshes.empty())
    return true; // nothing to plot
  vtkNew<vtkContextView> view;
  ShowChartView(window, view);
  window->SetSize(1200, 900);
  const int columns = meshes.size() > 1 ? 2 : 1;
  const int rowsCount = static_cast<int>((meshes.size() + columns - 1) / columns);
  vtkNew<vtkChartMatrix> matrix;
  view->GetScene()->AddItem(matrix);
  matrix->SetSize(vtkVector2i(columns, rowsCount));
  // Room between the charts for each one's axis titles and the title of the one below.
  matrix->SetGutter(vtkVector2f(90.0f, 80.0f));
  const char* families[] = { "SIR", "DIR reduction", "DIR bbox", "DIR adaptive", "ISR", "SSP",
    "DIR paper (no secant)", "DIR nearest back", "PEEL", "SH", "default (DIR 5 exit)",
    "Pareto front" };
  const int familyCount = 12;
  const int defaultFamily = 10;
  const unsigned char colours[][3] = { { 120, 120, 120 }, { 31, 119, 180 }, { 255, 127, 14 },
    { 44, 160, 44 }, { 214, 39, 40 }, { 148, 103, 189 }, { 140, 86, 75 }, { 23, 190, 207 },
    { 227, 119, 194 }, { 188, 189, 34 }, { 0, 0, 0 }, { 0, 0, 0 } };
  for (size_t m = 0; m < meshes.size(); ++m)
  {
    vtkChart* chart = matrix->GetChart(vtkVector2i(static_cast<int>(m % columns),
      rowsCount - 1 - static_cast<int>(m / columns)));
    chart->SetTitle(meshes[m] + " " + std::to_string(plotSize) + "x" + std::to_string(plotSize));
    chart->GetAxis(vtkAxis::BOTTOM)->SetTitle("frame time / plain VTK (median of repeats)");
    chart->GetAxis(vtkAxis::LEFT)->SetTitle("RMSE against the supersampled full reference");
    chart->SetShowLegend(m == 0);
    const std::vector<const Row*> candidates = Candidates(rows, meshes[m], plotSize);
    std::vector<CostError> all;
    for (const Row* r : candidates)
      all.push_back(Point(*r));
    double largest[2] = { 0.0, 0.0 }; // x, y over every plotted point
    for (int family = 0; family < familyCount; ++family)
    {
      std::vector<CostError> points;
      if (family == familyCount - 1)
      {
        for (size_t index : ParetoFront(all))
          points.push_back(all[index]);
      }
      for (size_t i = 0; family < familyCount - 1 && i < candidates.size(); ++i)
      {
        const Setting& s = candidates[i]->Config;
        const std::string& method = s.Method;
        const int f = method == "SH" ? 9
          : method == "PEEL" ? 8
          : method == "SIR" ? 0
          : method == "ISR" ? 4
          : method == "SSP" ? 5
          : s.Paper ? 6 : s.Nearest ? 7 : s.Adaptive ? 3 : s.Bounds ? 2 : 1;
        if ((f == family || (family == defaultFamily && IsDefaultSetting(s))) && Measured(all[i]))
          points.push_back(all[i]);
      }
      if (points.empty())
        continue;
      vtkNew<vtkTable> table;
      vtkNew<vtkFloatArray> x;
      vtkNew<vtkFloatArray> y;
      x->SetName("ratio");
      y->SetName(families[family]);
      table->AddColumn(x);
      table->AddColumn(y);
      table->SetNumberOfRows(static_cast<vtkIdType>(points.size()));
      for (size_t i = 0; i < points.size(); ++i)
      {
        table->SetValue(static_cast<vtkIdType>(i), 0, points[i].first);
        table->SetValue(static_cast<vtkIdType>(i), 1, points[i].second);
        largest[0] = std::max(largest[0], points[i].first);
        largest[1] = std::max(largest[1], points[i].second);
      }
      const bool front = family == familyCount - 1;
      // A front of one row (it beats every other) is a mark, not a line: VTK draws no line
      // through one point (and says so on the error output).
      const bool frontLine = front && points.size() > 1;
      vtkPlot* plot = chart->AddPlot(frontLine ? vtkChart::LINE : vtkChart::POINTS);
      plot->SetInputData(table, 0, 1);
      plot->SetColor(colours[family][0], colours[family][1], colours[family][2], 255);
      plot->SetWidth(front ? 1.5f : 2.0f);
      if (auto* markers = vtkPlotPoints::SafeDownCast(plot))
      {
        markers->SetMarkerStyle(frontLine ? vtkPlotPoints::NONE
            : front                       ? vtkPlotPoints::DIAMOND
            : family == defaultFamily     ? vtkPlotPoints::PLUS
                                          : vtkPlotPoints::CIRCLE);
        markers->SetMarkerSize(family == defaultFamily || front ? 14.0f : 7.0f);
      }
    }
    // From zero with a margin, so that a point is never drawn on the frame (VTK's automatic
    // range puts the extreme points on it).
    for (int a = 0; a < 2; ++a)
    {
      vtkAxis* axis = chart->GetAxis(a == 0 ? vtkAxis::BOTTOM : vtkAxis::LEFT);
      axis->SetBehavior(vtkAxis::FIXED);
      axis->SetRange(0.0, largest[a] > 0.0 ? 1.1 * largest[a] : 1.0);
    }
  }
  return WriteChartPng(window, view, path);
}
}
