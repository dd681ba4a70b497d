// vtkRefractionReference on bad input: no renderer, no glass actor, an empty polydata,
// non-finite points, no size. Each must return false with an error message, and never crash;
// a valid scene afterwards must still trace.
#include "vtkRefractionPass.h"
#include "vtkRefractionReference.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace
{
int failures = 0;

void Expect(bool condition, const char* what)
{
  std::printf("%s: %s\n", condition ? "ok" : "FAILED", what);
  failures += condition ? 0 : 1;
}

vtkSmartPointer<vtkActor> MakeActor(vtkPolyData* data)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}
}

int main(int, char*[])
{
  vtkNew<vtkRefractionReference> reference;
  std::ostringstream printed;
  reference->Print(printed);
  Expect(printed.str().find("MaxDepth: 8") != std::string::npos, "PrintSelf shows the settings");

  Expect(!reference->Trace(nullptr, 8, 8), "no renderer");

  vtkNew<vtkRenderer> renderer;
  Expect(!reference->Trace(renderer, 8, 8), "no actor at all");

  vtkNew<vtkSphereSource> sphere;
  sphere->Update();
  auto opaque = MakeActor(sphere->GetOutput());
  renderer->AddActor(opaque);
  Expect(!reference->Trace(renderer, 8, 8), "an actor, but none is glass");

  vtkNew<vtkPolyData> empty;
  auto emptyActor = MakeActor(empty);
  vtkRefractionPass::MakeGlass(emptyActor, 1.5);
  renderer->AddActor(emptyActor);
  Expect(!reference->Trace(renderer, 8, 8), "glass with empty polydata");
  renderer->RemoveActor(emptyActor);

  vtkNew<vtkPolyData> broken;
  broken->DeepCopy(sphere->GetOutput());
  broken->GetPoints()->SetPoint(3, NAN, 0.0, 0.0);
  auto brokenActor = MakeActor(broken);
  vtkRefractionPass::MakeGlass(brokenActor, 1.5);
  renderer->AddActor(brokenActor);
  Expect(!reference->Trace(renderer, 8, 8), "glass with a NaN point");
  renderer->RemoveActor(brokenActor);

  vtkRefractionPass::MakeGlass(opaque, 1.5);
  Expect(!reference->Trace(renderer), "no size and no render window");
  Expect(reference->GetOutput() == nullptr, "no output after failures");
  Expect(reference->Trace(renderer, 16, 12), "a valid scene still traces");
  Expect(reference->GetOutput() != nullptr && reference->GetOutput()->GetDimensions()[0] == 16 &&
      reference->GetOutput()->GetDimensions()[1] == 12,
    "output has the requested size");
  Expect(reference->GetNumberOfGlassActors() == 1 &&
      reference->GetNumberOfTriangles() == sphere->GetOutput()->GetNumberOfPolys(),
    "one glass actor with the sphere's triangles");
  Expect(std::fabs(reference->GetGlassDiagonal() - std::sqrt(3.0)) < 0.05,
    "glass diagonal of the unit-diameter sphere's box");
  opaque->VisibilityOff();
  Expect(!reference->Trace(renderer, 16, 12), "invisible glass is not traced");
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
