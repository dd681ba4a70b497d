// The scaling sweep (--scaling): how each method's frame time grows with the glass's triangles
// and with the window's pixels, a glass sphere filling the view, timed against plain VTK in
// the same run. Writes scaling.csv, scaling.md, scaling_triangles.png and scaling_pixels.png.
#ifndef rfBenchScaling_h
#define rfBenchScaling_h

#include "rfBenchOptions.h"

#include <string>

class vtkRenderWindow;
class vtkRenderer;

namespace rfbench
{
// The largest window the sweep draws (the EGL surface must hold it).
void ScalingWindowSize(const Options& o, int& width, int& height);

// Runs the sweep into o.Out; false (after a message) when a result cannot be written.
bool RunScaling(vtkRenderWindow* window, vtkRenderer* renderer, const Options& o,
  const std::string& rendererName);
}

#endif
