// The long-running algorithms the programs show progress for report ProgressEvent from 0 to 1,
// never going back: vtkISRDistanceFilter (ISR's ray casts) and vtkWaveEquationSource.
#include "../common/rf_require.h"
#include "vtkISRDistanceFilter.h"
#include "vtkWaveEquationSource.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkNew.h>
#include <vtkSphereSource.h>

#include <cstdio>
#include <cstdlib>
#include <vector>

namespace
{
void Record(vtkObject*, unsigned long, void* clientData, void* callData)
{
  static_cast<std::vector<double>*>(clientData)->push_back(*static_cast<double*>(callData));
}

int CheckProgress(const char* name, const std::vector<double>& progress)
{
  std::printf("%s: %zu progress events:", name, progress.size());
  for (double p : progress)
  {
    std::printf(" %.2f", p);
  }
  std::printf("\n");
  RF_REQUIRE(progress.size() >= 3, "%s reported %zu progress events", name, progress.size());
  RF_REQUIRE(progress.front() == 0.0 && progress.back() == 1.0, "%s: progress from %g to %g",
    name, progress.front(), progress.back());
  for (size_t i = 1; i < progress.size(); ++i)
  {
    RF_REQUIRE(progress[i] >= progress[i - 1], "%s: progress went back from %g to %g", name,
      progress[i - 1], progress[i]);
  }
  return EXIT_SUCCESS;
}
}

int main()
{
  std::vector<double> distanceProgress;
  vtkNew<vtkCallbackCommand> recordDistances;
  recordDistances->SetCallback(Record);
  recordDistances->SetClientData(&distanceProgress);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(64);
  vtkNew<vtkISRDistanceFilter> distances;
  distances->SetInputConnection(sphere->GetOutputPort());
  distances->AddObserver(vtkCommand::ProgressEvent, recordDistances);
  distances->Update();
  if (CheckProgress("vtkISRDistanceFilter", distanceProgress) != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }

  std::vector<double> waveProgress;
  vtkNew<vtkCallbackCommand> recordWaves;
  recordWaves->SetCallback(Record);
  recordWaves->SetClientData(&waveProgress);
  vtkNew<vtkWaveEquationSource> waves;
  waves->SetSampleDimensions(32);
  waves->AddObserver(vtkCommand::ProgressEvent, recordWaves);
  waves->UpdateTimeStep(waves->GetEndTime());
  return CheckProgress("vtkWaveEquationSource", waveProgress);
}
