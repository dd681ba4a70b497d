// Frame times: the medians of timed frames of one window (CPU, GPU and the pass's stages),
// and the statistics of the repeats.
#ifndef rfBenchTiming_h
#define rfBenchTiming_h

#include "rfBenchRow.h"

#include <vector>

class vtkRefractionPass;
class vtkRenderWindow;

namespace rfbench
{
// The median of v (-1 when empty), and median, min and max of v (rfSpread.h, which the
// viewer's --timing shares).
using rftiming::Median;
using rftiming::SpreadOf;

struct Timing
{
  double Cpu = -1, GpuFrame = -1;
  std::vector<double> Stages; // vtkRefractionPass's timed stages, 0..TIMED_STAGE_COUNT-1
};

// Renders `frames` timed frames after 5 warm-up frames; `pass` (or nullptr for a plain
// render) also gives its stage times.
Timing TimeFrames(vtkRenderWindow* window, vtkRefractionPass* pass, int frames);
}

#endif
