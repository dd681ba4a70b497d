// The viewer in a window: trackball camera, keys for the method, the IOR, the search steps
// and the time steps, and the animation of a time series.
#ifndef rfViewerInteractive_h
#define rfViewerInteractive_h

#include "rfViewerScene.h"

class vtkRenderWindow;

namespace rfviewer
{
// Runs the window's event loop from the time step timeIndex; RF_VIEWER_OK when closed.
int RunInteractive(Scene& scene, vtkRenderWindow* window, int timeIndex);
}

#endif
