#include "rfGlassMeshArrays.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkTriangleFilter.h"

//------------------------------------------------------------------------------
vtkDataArray* rfGlassMeshNormals(vtkPolyData* input, vtkPolyData* output, bool orientOutward)
{
  vtkDataArray* normals = input->GetPointData()->GetNormals();
  if (normals)
  {
    return normals;
  }
  vtkNew<vtkPolyDataNormals> normalFilter;
  normalFilter->SetInputData(input);
  normalFilter->SplittingOff();
  normalFilter->ConsistencyOn();
  normalFilter->SetAutoOrientNormals(orientOutward);
  normalFilter->ComputeCellNormalsOff();
  normalFilter->Update();
  normals = normalFilter->GetOutput()->GetPointData()->GetNormals();
  // The output holds the array, which outlives the filter.
  output->GetPointData()->SetNormals(normals);
  return normals;
}

//------------------------------------------------------------------------------
rfGlassMeshArrays rfGetGlassMeshArrays(vtkPolyData* input, vtkDataArray* normals)
{
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(input);
  triangles->PassLinesOff();
  triangles->PassVertsOff();
  triangles->Update();
  vtkPolyData* mesh = triangles->GetOutput();
  const vtkIdType pointCount = input->GetNumberOfPoints();
  rfGlassMeshArrays arrays;
  arrays.Positions.resize(3 * pointCount);
  arrays.Normals.resize(3 * pointCount);
  for (vtkIdType i = 0; i < pointCount; ++i)
  {
    double p[3];
    double n[3];
    mesh->GetPoint(i, p);
    normals->GetTuple(i, n);
    for (int k = 0; k < 3; ++k)
    {
      arrays.Positions[3 * i + k] = static_cast<float>(p[k]);
      arrays.Normals[3 * i + k] = static_cast<float>(n[k]);
    }
  }
  arrays.Triangles.reserve(3 * mesh->GetNumberOfPolys());
  vtkCellArray* polys = mesh->GetPolys();
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
  {
    if (count == 3)
    {
      for (int k = 0; k < 3; ++k)
      {
        arrays.Triangles.push_back(static_cast<unsigned>(ids[k]));
      }
    }
  }
  return arrays;
}
