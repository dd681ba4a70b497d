// vtkSHTransferFilter (the SH method's precomputation): the point array it adds, the cache on
// disk (a second filter on the same mesh and settings loads the first one's result, exactly;
// other settings or moved points miss it), and the progress it reports.
#include "vtkSHTransferFilter.h"

#include "rf_require.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace
{
void CountProgress(vtkObject*, unsigned long, void* clientData, void*)
{
  ++*static_cast<int*>(clientData);
}

vtkSmartPointer<vtkSHTransferFilter> Run(vtkAlgorithmOutput* port, const std::string& cache,
  int order, int* progressEvents)
{
  auto filter = vtkSmartPointer<vtkSHTransferFilter>::New();
  filter->SetInputConnection(port);
  filter->SetOrder(order);
  filter->SetDirections(64);
  filter->SetMaxBounces(4);
  filter->SetCacheDirectory(cache);
  vtkNew<vtkCallbackCommand> progress;
  progress->SetCallback(CountProgress);
  progress->SetClientData(progressEvents);
  filter->AddObserver(vtkCommand::ProgressEvent, progress);
  filter->Update();
  return filter;
}
}

int main(int argc, char* argv[])
{
  const std::string cache = std::string(argc > 1 ? argv[1] : ".") + "/sh-cache";
  vtksys::SystemTools::RemoveADirectory(cache);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(24);
  sphere->SetPhiResolution(12);
  int events = 0;
  auto first = Run(sphere->GetOutputPort(), cache, 4, &events);
  vtkPolyData* out = first->GetOutput();
  vtkDataArray* transfer = out->GetPointData()->GetArray(vtkSHTransferFilter::GetArrayName());
  RF_REQUIRE(transfer && transfer->GetNumberOfComponents() == 4 * 25 &&
      transfer->GetNumberOfTuples() == out->GetNumberOfPoints(),
    "no SHTransfer array of 100 components per point");
  RF_REQUIRE(out->GetFieldData()->GetArray(vtkSHTransferFilter::GetSettingsArrayName()),
    "no settings array");
  RF_REQUIRE(!first->GetLastCacheHit() && !first->GetLastCacheFile().empty() &&
      vtksys::SystemTools::FileExists(first->GetLastCacheFile(), true),
    "the first run did not write the cache (%s)", first->GetLastCacheFile().c_str());
  RF_REQUIRE(events >= 3, "only %d progress events", events);
  // The exit direction's z coefficient of order 0 is nonzero on a ball (light goes on through).
  double sum = 0.0;
  for (vtkIdType i = 0; i < transfer->GetNumberOfTuples(); ++i)
  {
    sum += std::abs(transfer->GetComponent(i, 0)) + std::abs(transfer->GetComponent(i, 50));
  }
  RF_REQUIRE(sum > 0.0, "all coefficients are zero");

  int ignored = 0;
  auto second = Run(sphere->GetOutputPort(), cache, 4, &ignored);
  vtkDataArray* again =
    second->GetOutput()->GetPointData()->GetArray(vtkSHTransferFilter::GetArrayName());
  RF_REQUIRE(second->GetLastCacheHit(), "the second run missed the cache");
  double largest = 0.0;
  for (vtkIdType i = 0; i < transfer->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < transfer->GetNumberOfComponents(); ++c)
    {
      largest = std::max(largest, std::abs(transfer->GetComponent(i, c) - again->GetComponent(i, c)));
    }
  }
  RF_REQUIRE(largest == 0.0, "the cached values differ (%g)", largest);

  auto otherOrder = Run(sphere->GetOutputPort(), cache, 3, &ignored);
  RF_REQUIRE(!otherOrder->GetLastCacheHit(), "another order hit the cache");
  vtkNew<vtkTransform> scale;
  scale->Scale(1.0, 1.0, 1.1);
  vtkNew<vtkTransformPolyDataFilter> moved;
  moved->SetTransform(scale);
  moved->SetInputConnection(sphere->GetOutputPort());
  auto movedRun = Run(moved->GetOutputPort(), cache, 4, &ignored);
  RF_REQUIRE(!movedRun->GetLastCacheHit(), "moved points hit the cache");
  std::printf("SH transfer of %lld points: computed in %.3f s, loaded from the cache in %.4f s\n",
    static_cast<long long>(out->GetNumberOfPoints()), first->GetLastComputeSeconds(),
    second->GetLastComputeSeconds());
  vtksys::SystemTools::RemoveADirectory(cache);
  return EXIT_SUCCESS;
}
