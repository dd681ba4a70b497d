// Small scenes shared by the rendering tests: every window is small, single-sampled and
// off screen, so the tests run under Xvfb on llvmpipe.
#ifndef rfTestScene_h
#define rfTestScene_h

#include "../common/rf_require.h"
#include "vtkRefractionPass.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkImageDifference.h>
#include <vtkNew.h>
#include <vtkParametricFunctionSource.h>
#include <vtkParametricTorus.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>
#include <vtkWindowToImageFilter.h>

#include <cstdio>

namespace rftest
{
inline vtkSmartPointer<vtkRenderWindow> MakeWindow(vtkRenderer* renderer, int width, int height)
{
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetSize(width, height);
  window->SetMultiSamples(0);
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  return window;
}

inline vtkSmartPointer<vtkActor> MakeActor(vtkAlgorithmOutput* port)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(port);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

inline vtkSmartPointer<vtkActor> MakeSphere(double radius, int resolution)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(resolution);
  sphere->SetPhiResolution(resolution);
  sphere->Update();
  return MakeActor(sphere->GetOutputPort());
}

inline vtkSmartPointer<vtkActor> MakeTorus()
{
  vtkNew<vtkParametricTorus> torus;
  torus->SetRingRadius(0.7);
  torus->SetCrossSectionRadius(0.3);
  vtkNew<vtkParametricFunctionSource> source;
  source->SetParametricFunction(torus);
  source->SetUResolution(96);
  source->SetVResolution(48);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(source->GetOutputPort());
  normals->Update();
  return MakeActor(normals->GetOutputPort());
}

inline vtkSmartPointer<vtkImageData> Grab(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(grab->GetOutput());
  return image;
}

// VTK's own image difference (the measure the regression test applies).
inline double ImageError(vtkImageData* a, vtkImageData* b)
{
  vtkNew<vtkImageDifference> difference;
  difference->SetInputData(a);
  difference->SetImageData(b);
  difference->Update();
  return difference->GetThresholdedError();
}

// Largest per-channel difference, 0..255.
inline int MaxChannelDifference(vtkImageData* a, vtkImageData* b)
{
  const int* dims = a->GetDimensions();
  int worst = 0;
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        const int d = static_cast<int>(a->GetScalarComponentAsDouble(x, y, 0, c)) -
          static_cast<int>(b->GetScalarComponentAsDouble(x, y, 0, c));
        worst = d < 0 ? (-d > worst ? -d : worst) : (d > worst ? d : worst);
      }
    }
  }
  return worst;
}

}
#endif
