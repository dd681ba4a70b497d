// The report a person reads: results.md (the paper's Table 1 analogue, every row, the noise)
// and the chart helpers pareto.png and the scaling plots are drawn with (rfBenchPareto.h).
#ifndef rfBenchReport_h
#define rfBenchReport_h

#include "rfBenchRow.h"

#include <string>
#include <vector>

class vtkContextView;
class vtkRenderWindow;

namespace rfbench
{
// A PSNR in dB with one decimal, or "-" where there is none (negative).
std::string Db(double v);

// Writes results.md; `run` describes the run (environment, repeats, load).
bool WriteMarkdown(const std::string& path, const std::vector<Row>& rows,
  const std::string& renderer, const std::string& windowPath, const std::string& run);

// Puts a chart view in the window in place of its renderers.
void ShowChartView(vtkRenderWindow* window, vtkContextView* view);

// Renders the chart view over white and writes the window to a PNG; false when it cannot.
bool WriteChartPng(vtkRenderWindow* window, vtkContextView* view, const std::string& path);
}

#endif
