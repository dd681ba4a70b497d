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

// The line of results.md that describes its run: the renderer, its window, and `run` (the
// environment, repeats, duration, the machine's load).
std::string RunLine(
  const std::string& renderer, const std::string& windowPath, const std::string& run);

// The run line of an existing results.md (RunLine), or "" where there is none: a report
// remade from its CSV keeps what the run itself recorded.
std::string ReadRunLine(const std::string& path);

// Writes results.md, its run described by `runLine` (RunLine).
bool WriteMarkdown(
  const std::string& path, const std::vector<Row>& rows, const std::string& runLine);

// Puts a chart view in the window in place of its renderers.
void ShowChartView(vtkRenderWindow* window, vtkContextView* view);

// Renders the chart view over white and writes the window to a PNG; false when it cannot.
bool WriteChartPng(vtkRenderWindow* window, vtkContextView* view, const std::string& path);
}

#endif
