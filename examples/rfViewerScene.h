// The viewer's scene: the input's pipeline (read, contoured or its surface, ISR's d_N) ending
// in the glass actor, the demo's stage, the environment, the pass and the status line, and
// the camera that frames them; shared by the interactive and the headless runs.
#ifndef rfViewerScene_h
#define rfViewerScene_h

#include "rfViewerOptions.h"

#include "vtkISRDistanceFilter.h"
#include "vtkRefractionPass.h"

#include <vtkActor.h>
#include <vtkAlgorithm.h>
#include <vtkRenderer.h>
#include <vtkSkybox.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>

#include <string>
#include <vector>

namespace rfviewer
{
// Shows the progress of a pipeline stage that runs long (the wave equation from t = 0, ISR's
// ray casts on a big mesh): silent under a second, a percentage on a terminal after that,
// and the time taken at the end.
struct StageProgress
{
  const char* Label;
  double Start = 0.0;
  bool Shown = false;
};

struct Scene
{
  vtkSmartPointer<vtkAlgorithm> Source;
  vtkSmartPointer<vtkAlgorithm> Surface; // what the mapper pulls from
  vtkSmartPointer<vtkISRDistanceFilter> Distances;
  vtkSmartPointer<vtkActor> Glass;
  vtkSmartPointer<vtkActor> Cone;
  vtkSmartPointer<vtkActor> Floor; // the demo's checkered floor and back wall
  vtkSmartPointer<vtkSkybox> Sky;
  vtkSmartPointer<vtkTextActor> Text;
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkRefractionPass> Pass;
  std::vector<double> Times;
  std::string Description;
  StageProgress SourceProgress{ "computing the data" };
  StageProgress DistanceProgress{ "ISR distances" };
};

// Shows the time step at `time` (nothing for a static input).
void ShowTime(Scene& scene, double time);

// Builds the scene from the options; RF_VIEWER_OK or the exit code (its message printed).
int BuildScene(const rfViewerOptions& o, const rfViewerSettings& s, Scene& scene);

// The status line: method, IOR, steps, the frame time and the time step.
void SetStatus(Scene& scene, double milliseconds, int timeIndex);

// The index of the last time step at or before `time` (0 for a static input).
int TimeIndexOf(const Scene& scene, double time);

// Frames the input with the options' azimuth, elevation and zoom.
void PlaceCamera(Scene& scene, const rfViewerSettings& s);
}

#endif
