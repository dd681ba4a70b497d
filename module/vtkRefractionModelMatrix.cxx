#include "vtkRefractionModelMatrix.h"

#include "vtkActor.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"

#include <cmath>

//------------------------------------------------------------------------------
double vtkRefractionModelMatrix::GetDeterminant(vtkProp* prop)
{
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  double mirror = 1.0;
  if (actor)
  {
    double m[3][3];
    vtkMatrix4x4* matrix = actor->GetMatrix();
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        m[r][c] = matrix->GetElement(r, c);
      }
    }
    mirror = vtkMath::Determinant3x3(m);
  }
  return mirror;
}

//------------------------------------------------------------------------------
double vtkRefractionModelMatrix::GetScale(vtkProp* prop)
{
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  double scale = 1.0;
  if (actor)
  {
    vtkMatrix4x4* m = actor->GetMatrix();
    double columns[3] = { 0.0, 0.0, 0.0 };
    for (int c = 0; c < 3; ++c)
    {
      columns[c] = std::sqrt(m->GetElement(0, c) * m->GetElement(0, c) +
        m->GetElement(1, c) * m->GetElement(1, c) + m->GetElement(2, c) * m->GetElement(2, c));
    }
    scale = std::cbrt(columns[0] * columns[1] * columns[2]);
  }
  return scale;
}
