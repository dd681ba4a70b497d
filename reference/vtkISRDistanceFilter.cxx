#include "vtkISRDistanceFilter.h"

#include "rf_normal_distance.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkTimerLog.h"
#include "vtkTriangleFilter.h"

#include <vector>

vtkStandardNewMacro(vtkISRDistanceFilter);

//------------------------------------------------------------------------------
void vtkISRDistanceFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LastComputeSeconds: " << this->LastComputeSeconds << "\n";
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
  if (pointCount == 0 || input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    this->LastComputeSeconds = 0.0;
    this->UpdateProgress(1.0);
    return 1;
  }

  vtkDataArray* normals = input->GetPointData()->GetNormals();
  vtkNew<vtkPolyDataNormals> normalFilter;
  if (!normals)
  {
    normalFilter->SetInputData(input);
    normalFilter->SplittingOff();
    normalFilter->ConsistencyOn();
    normalFilter->ComputeCellNormalsOff();
    normalFilter->Update();
    normals = normalFilter->GetOutput()->GetPointData()->GetNormals();
    output->GetPointData()->SetNormals(normals);
  }
  // Coarse steps: normals, triangles and the copy come first; the ray casts that follow are
  // one call into the C core, which reports nothing while it runs.
  this->UpdateProgress(0.1);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(input);
  triangles->PassLinesOff();
  triangles->PassVertsOff();
  triangles->Update();
  vtkPolyData* mesh = triangles->GetOutput();
  this->UpdateProgress(0.2);

  std::vector<float> positions(3 * pointCount);
  std::vector<float> normalValues(3 * pointCount);
  for (vtkIdType i = 0; i < pointCount; ++i)
  {
    double p[3];
    double n[3];
    mesh->GetPoint(i, p);
    normals->GetTuple(i, n);
    for (int k = 0; k < 3; ++k)
    {
      positions[3 * i + k] = static_cast<float>(p[k]);
      normalValues[3 * i + k] = static_cast<float>(n[k]);
    }
  }
  std::vector<unsigned> indices;
  indices.reserve(3 * mesh->GetNumberOfPolys());
  vtkCellArray* polys = mesh->GetPolys();
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
  {
    if (count == 3)
    {
      for (int k = 0; k < 3; ++k)
      {
        indices.push_back(static_cast<unsigned>(ids[k]));
      }
    }
  }
  this->UpdateProgress(0.3);
  const rf_status status = rf_normal_distances(positions.data(), normalValues.data(),
    static_cast<size_t>(pointCount), indices.data(), indices.size() / 3,
    static_cast<float*>(distances->GetVoidPointer(0)));
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
