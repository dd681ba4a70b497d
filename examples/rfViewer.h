// The viewer program (RefractionViewer) as a function, so that the demo is the same program
// with preset options (RefractionDemo): see rfViewer.cxx and `RefractionViewer --help`.
#ifndef rfViewer_h
#define rfViewer_h

#include <string>
#include <vector>

// Exit codes of the programs, also listed by --help.
enum rfViewerExit
{
  RF_VIEWER_OK = 0,
  RF_VIEWER_FAILED = 1,     // rendering or writing failed on the way
  RF_VIEWER_USAGE = 2,      // unknown option, missing or wrong value
  RF_VIEWER_NO_CONTEXT = 3, // no headless (EGL) context and no display
  RF_VIEWER_BAD_INPUT = 4   // an input, environment or output path that cannot be used
};

// Runs the viewer on argv; @a preset comes before argv's options, which override it.
int rfViewerMain(int argc, char* argv[], const std::vector<std::string>& preset);

#endif
