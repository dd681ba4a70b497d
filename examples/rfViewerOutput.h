// The viewer's output without a window: the screenshot, the numbered frames (and masks), the
// contact sheet and the frame times; and the check of the output paths before any rendering.
#ifndef rfViewerOutput_h
#define rfViewerOutput_h

#include "rfViewerScene.h"

class vtkRenderWindow;

namespace rfviewer
{
// Writes what the options ask for from the time step firstIndex; RF_VIEWER_OK or the exit
// code.
int RunHeadless(const rfViewerOptions& o, const rfViewerSettings& s, Scene& scene, vtkRenderWindow* window,
  int firstIndex);

// RF_VIEWER_OK when every output path can be written, else RF_VIEWER_BAD_INPUT (printed).
int CheckOutputs(const rfViewerOptions& o);
}

#endif
