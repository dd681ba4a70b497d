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

// The line of an existing results.md that describes its run ("Renderer: ...": the renderer,
// the run's settings, how long it took, the machine's load), or "" where there is none.
std::string ReadRunLine(const std::string& path);

// Puts `runLine` in place of the run line of the results.md at `path` (a report remade from
// its CSV keeps what the run itself recorded); false when the file cannot be rewritten.
bool ReplaceRunLine(const std::string& path, const std::string& runLine);

// Puts a chart view in the window in place of its renderers.
void ShowChartView(vtkRenderWindow* window, vtkContextView* view);

// Renders the chart view over white and writes the window to a PNG; false when it cannot.
bool WriteChartPng(vtkRenderWindow* window, vtkContextView* view, const std::string& path);
}

#endif
