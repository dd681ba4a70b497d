#include "fuzz_contract.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>

vtkStandardNewMacro(rfCountingOutputWindow);

rfCountingOutputWindow* rfFuzzMessages()
{
  static vtkNew<rfCountingOutputWindow> messages;
  static const bool installed = [] {
    vtkOutputWindow::SetInstance(messages);
    // VTK 9.1 also logs errors through vtkLogger on stderr: counted above, not printed.
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
    return true;
  }();
  (void)installed;
  return messages;
}

bool rfFuzzWellFormed(vtkPolyData* mesh)
{
  const vtkIdType points = mesh->GetNumberOfPoints();
  vtkCellArray* kinds[4] = { mesh->GetVerts(), mesh->GetLines(), mesh->GetPolys(),
    mesh->GetStrips() };
  for (int k = 0; k < 4; ++k)
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    auto it = vtk::TakeSmartPointer(kinds[k]->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      it->GetCurrentCell(n, ids);
      if (k >= 2 && n < 3)
      {
        return false; // a polygon or strip of fewer than 3 points
      }
      for (vtkIdType i = 0; i < n; ++i)
      {
        if (ids[i] < 0 || ids[i] >= points)
        {
          return false;
        }
      }
    }
  }
  for (vtkIdType i = 0; i < points; ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    if (!(std::fabs(p[0]) <= FLT_MAX && std::fabs(p[1]) <= FLT_MAX && std::fabs(p[2]) <= FLT_MAX))
    {
      return false;
    }
  }
  return true;
}

void rfFuzzRequire(bool condition, const char* target, const char* what)
{
  if (!condition)
  {
    std::fprintf(stderr, "%s: contract violated: %s\n", target, what);
    std::abort();
  }
}
