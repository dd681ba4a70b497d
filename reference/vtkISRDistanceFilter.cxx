#include "vtkISRDistanceFilter.h"

#include "rfGlassMeshArrays.h"
#include "rf_normal_distance.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiThreader.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRefractionGlassChecker.h"
#include "vtkTimerLog.h"

#include <algorithm>
#include <string>

vtkStandardNewMacro(vtkISRDistanceFilter);

//------------------------------------------------------------------------------
vtkISRDistanceFilter::vtkISRDistanceFilter()
  : Threads(std::max(1, vtkMultiThreader::GetGlobalDefaultNumberOfThreads()))
{
}

//------------------------------------------------------------------------------
void vtkISRDistanceFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LastComputeSeconds: " << this->LastComputeSeconds << "\n";
  os << indent << "Threads: " << this->Threads << "\n";
}

//------------------------------------------------------------------------------
int vtkISRDistanceFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  this->UpdateProgress(0.0);
  output->ShallowCopy(input);
  const vtkIdType pointCount = input->GetNumberOfPoints();
  vtkNew<vtkFloatArray> distances;
  distances->SetName(GetArrayName());
  distances->SetNumberOfTuples(pointCount);
  distances->Fill(0.0);
  output->GetPointData()->AddArray(distances);
  std::string malformed;
  if (!vtkRefractionGlassChecker::CheckMesh(input, malformed))
  {
    // The pass refuses such glass too; reading its cells would go beyond its points.
    vtkErrorMacro(
      "Cannot compute ISR distances: the input " << malformed << "; the output keeps zeros.");
    this->LastComputeSeconds = 0.0;
    this->UpdateProgress(1.0);
    return 1;
  }
  if (pointCount == 0 || input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    this->LastComputeSeconds = 0.0;
    this->UpdateProgress(1.0);
    return 1;
  }

  vtkDataArray* normals = rfGlassMeshNormals(input, output, false);
  // Coarse steps: normals, triangles and the copy come first; the ray casts that follow are
  // one call into the C core, which reports nothing while it runs.
  this->UpdateProgress(0.1);
  const rfGlassMeshArrays mesh = rfGetGlassMeshArrays(input, normals);
  this->UpdateProgress(0.2);
  this->UpdateProgress(0.3);
  const rf_status status = rf_normal_distances(mesh.Positions.data(), mesh.Normals.data(),
    static_cast<size_t>(pointCount), mesh.Triangles.data(), mesh.Triangles.size() / 3,
    static_cast<float*>(distances->GetVoidPointer(0)), this->Threads);
  timer->StopTimer();
  this->LastComputeSeconds = timer->GetElapsedTime();
  if (status != RF_OK)
  {
    vtkErrorMacro("Cannot compute ISR distances: " << rf_status_message(status));
    distances->Fill(0.0);
  }
  this->UpdateProgress(1.0);
  return 1;
}
