// The test scenes' parts, shared by the regression, stability and bad-input tests: the
// shapes (as vtkPolyData or as a live pipeline), their actors, the camera, the window (EGL,
// small, VTK's default multisampling) and the image comparisons.
#ifndef rfTestScene_h
#define rfTestScene_h

#include "rfTestWindow.h"
#include "rf_require.h"
#include "vtkRefractionPass.h"

#include <vtkActor.h>
#include <vtkAlgorithmOutput.h>
#include <vtkCamera.h>
#include <vtkConeSource.h>
#include <vtkCubeSource.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkImageDifference.h>
#include <vtkNew.h>
#include <vtkParametricFunctionSource.h>
#include <vtkParametricTorus.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>
#include <vtkWindowToImageFilter.h>

#include <cstdio>
#include <cstdlib>
#include <vector>

namespace rftest
{
//------------------------------------------------------------------------------
// Windows and cameras.
inline vtkSmartPointer<vtkRenderWindow> MakeWindow(vtkRenderer* renderer, int width, int height)
{
  auto window = NewRenderWindow(width, height);
  window->SetSize(width, height);
  window->AddRenderer(renderer);
  return window;
}

inline void LookAt(vtkCamera* camera, const double eye[3], const double focal[3],
  const double up[3], double viewAngle, double nearPlane, double farPlane)
{
  camera->SetPosition(eye[0], eye[1], eye[2]);
  camera->SetFocalPoint(focal[0], focal[1], focal[2]);
  camera->SetViewUp(up[0], up[1], up[2]);
  camera->OrthogonalizeViewUp();
  camera->SetViewAngle(viewAngle);
  camera->SetClippingRange(nearPlane, farPlane);
}

/// From `distance` along +z, raised by `elevation` degrees, at the origin; 30 degree view.
inline void LookAtOrigin(vtkRenderer* renderer, double distance, double elevation)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(0.0, 0.0, distance);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->Elevation(elevation);
  camera->OrthogonalizeViewUp();
  camera->SetViewAngle(30.0);
  renderer->ResetCameraClippingRange();
}

//------------------------------------------------------------------------------
// Shapes as data (a copy, detached from its source: the tests edit points and normals).
inline vtkSmartPointer<vtkPolyData> Detach(vtkPolyData* output)
{
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->DeepCopy(output);
  return poly;
}

inline vtkSmartPointer<vtkPolyData> SpherePoly(const double centre[3], double radius,
  int resolution, bool doublePoints = false, double endPhi = 180.0)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(centre[0], centre[1], centre[2]);
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(resolution);
  sphere->SetPhiResolution(resolution);
  sphere->SetEndPhi(endPhi);
  sphere->SetOutputPointsPrecision(
    doublePoints ? vtkAlgorithm::DOUBLE_PRECISION : vtkAlgorithm::SINGLE_PRECISION);
  sphere->Update();
  return Detach(sphere->GetOutput());
}

/// An axis-aligned box, centred at the origin unless a centre is given.
inline vtkSmartPointer<vtkPolyData> BoxPoly(const double lengths[3], const double* centre = nullptr)
{
  vtkNew<vtkCubeSource> cube;
  if (centre)
  {
    cube->SetCenter(centre[0], centre[1], centre[2]);
  }
  cube->SetXLength(lengths[0]);
  cube->SetYLength(lengths[1]);
  cube->SetZLength(lengths[2]);
  cube->Update();
  return Detach(cube->GetOutput());
}

inline vtkSmartPointer<vtkPolyData> ConePoly(
  const double centre[3], double height, double radius, int resolution)
{
  vtkNew<vtkConeSource> cone;
  cone->SetCenter(centre[0], centre[1], centre[2]);
  cone->SetHeight(height);
  cone->SetRadius(radius);
  cone->SetResolution(resolution);
  cone->Update();
  return Detach(cone->GetOutput());
}

/// A renderer drawing through the glass pass under the built-in sky (what the baselines and
/// closed forms show; no environment file to find), in a window of its own.
struct GlassView
{
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRefractionPass> Glass;
  vtkSmartPointer<vtkRenderWindow> Window;

  GlassView(int width, int height)
  {
    this->Glass->SetEnvironmentModeToBuiltin();
    this->Renderer->SetPass(this->Glass);
    this->Window = MakeWindow(this->Renderer, width, height);
  }
  vtkSmartPointer<vtkImageData> RenderAndGrab();
};

//------------------------------------------------------------------------------
// Actors. Scalars off: every test colours through the property or the glass alone.
inline vtkSmartPointer<vtkActor> ActorFor(vtkPolyData* poly)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

/// An actor fed by a live pipeline (the time-varying and d_N cases re-execute it).
inline vtkSmartPointer<vtkActor> ActorFor(vtkAlgorithmOutput* port)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(port);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

/// An unlit actor of one pure colour: its pixels are known exactly.
inline vtkSmartPointer<vtkActor> FlatActor(vtkPolyData* poly, double r, double g, double b)
{
  auto actor = ActorFor(poly);
  actor->GetProperty()->LightingOff();
  actor->GetProperty()->SetColor(r, g, b);
  return actor;
}

/// MakeGlass gives an actor at VTK's default specular terms glass's highlights of the
/// renderer's lights. Tests of the refraction turn them off: the reference tracer traces no
/// light sources, and the baselines and closed forms are of the refraction alone (the
/// highlights have their own test, TestGlassHighlights).
inline void WithoutHighlights(vtkProp* prop)
{
  if (auto* actor = vtkActor::SafeDownCast(prop))
  {
    actor->GetProperty()->SetSpecular(0.0);
  }
}

/// Marks a prop as glass of index `ior`, refraction alone (WithoutHighlights).
inline void MakeRefractingGlass(vtkProp* prop, double ior)
{
  vtkRefractionPass::MakeGlass(prop, ior);
  WithoutHighlights(prop);
}

inline vtkSmartPointer<vtkActor> GlassActor(vtkPolyData* poly, double ior)
{
  auto actor = ActorFor(poly);
  MakeRefractingGlass(actor, ior);
  return actor;
}

/// A sphere at the origin through a live source.
inline vtkSmartPointer<vtkActor> MakeSphere(double radius, int resolution)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(resolution);
  sphere->SetPhiResolution(resolution);
  sphere->Update();
  return ActorFor(sphere->GetOutputPort());
}

/// A torus (ring 0.7, cross-section 0.3) through a live source, with point normals.
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
  return ActorFor(normals->GetOutputPort());
}

//------------------------------------------------------------------------------
// Pictures.
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

// An 8-bit picture's colour as floats in [0, 1], 3 per pixel, bottom row first (the layout
// of the reference's "Colour" and of rf_metrics).
inline vtkSmartPointer<vtkImageData> GlassView::RenderAndGrab()
{
  this->Window->Render();
  return Grab(this->Window);
}

inline std::vector<float> ToColour(vtkImageData* image)
{
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  std::vector<float> colour(3 * static_cast<size_t>(scalars->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < scalars->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      colour[3 * i + c] = static_cast<float>(scalars->GetComponent(i, c) / 255.0);
    }
  }
  return colour;
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

// Whether any channel of pixel (x, y) differs by more than `tolerance` (0..255).
inline bool PixelDiffers(vtkImageData* a, vtkImageData* b, int x, int y, double tolerance)
{
  for (int c = 0; c < 3; ++c)
  {
    const double d =
      a->GetScalarComponentAsDouble(x, y, 0, c) - b->GetScalarComponentAsDouble(x, y, 0, c);
    if (d > tolerance || d < -tolerance)
    {
      return true;
    }
  }
  return false;
}

// Pixels where any channel differs by more than `tolerance` (0..255).
inline int DifferingPixels(vtkImageData* a, vtkImageData* b, int tolerance)
{
  const int* dims = a->GetDimensions();
  int count = 0;
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      count += PixelDiffers(a, b, x, y, tolerance) ? 1 : 0;
    }
  }
  return count;
}

}
#endif
