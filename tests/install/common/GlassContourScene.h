// The scene of examples/glass_contour.py in C++, for the consumers of the installed package:
// a contour of four Gaussian blobs as glass beside an opaque cone. It must stay the same
// scene as the Python one: all of them are compared with tests/baselines/TestGlassContour.png.
#ifndef GlassContourScene_h
#define GlassContourScene_h

#include "vtkRefractionPass.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkConeSource.h>
#include <vtkFlyingEdges3D.h>
#include <vtkGaussianSplatter.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

struct GlassContourScene
{
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkActor> Glass;
  vtkSmartPointer<vtkRefractionPass> Pass;
};

// Fills the renderer of a size x size window (the window itself is the caller's: a plain
// vtkRenderWindow or an EGL one).
inline GlassContourScene BuildGlassContourScene(vtkRenderWindow* window, int size)
{
  vtkNew<vtkPoints> centres;
  const double blobCentres[4][3] = { { -0.45, -0.2, 0.0 }, { 0.4, -0.3, 0.1 },
    { 0.0, 0.45, -0.1 }, { 0.05, 0.0, 0.45 } };
  for (const auto& centre : blobCentres)
  {
    centres->InsertNextPoint(centre);
  }
  vtkNew<vtkPolyData> blobs;
  blobs->SetPoints(centres);
  vtkNew<vtkGaussianSplatter> field;
  field->SetInputData(blobs);
  field->SetSampleDimensions(48, 48, 48);
  field->SetModelBounds(-1.2, 1.2, -1.2, 1.2, -1.2, 1.2);
  field->SetRadius(0.3);
  field->SetExponentFactor(-4.0);
  field->ScalarWarpingOff();
  field->SetAccumulationModeToSum();
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputConnection(field->GetOutputPort());
  contour->SetValue(0, 0.4);
  contour->ComputeNormalsOn();

  GlassContourScene scene;
  vtkNew<vtkPolyDataMapper> glassMapper;
  glassMapper->SetInputConnection(contour->GetOutputPort());
  glassMapper->ScalarVisibilityOff();
  scene.Glass = vtkSmartPointer<vtkActor>::New();
  scene.Glass->SetMapper(glassMapper);
  vtkRefractionPass::MakeGlass(scene.Glass, 1.5);

  vtkNew<vtkConeSource> cone;
  cone->SetResolution(48);
  cone->SetHeight(1.2);
  cone->SetRadius(0.4);
  cone->SetCenter(1.1, -0.2, -0.8);
  cone->SetDirection(0.0, 1.0, 0.0);
  vtkNew<vtkPolyDataMapper> coneMapper;
  coneMapper->SetInputConnection(cone->GetOutputPort());
  vtkNew<vtkActor> coneActor;
  coneActor->SetMapper(coneMapper);
  coneActor->GetProperty()->SetColor(0.9, 0.45, 0.1);

  scene.Pass = vtkSmartPointer<vtkRefractionPass>::New();
  scene.Pass->SetEnvironmentModeToBuiltin(); // the shared baseline shows the built-in sky
  scene.Pass->SetMethod(vtkRefractionPass::DIR);

  scene.Renderer = vtkSmartPointer<vtkRenderer>::New();
  scene.Renderer->SetBackground(0.1, 0.1, 0.12);
  scene.Renderer->AddActor(scene.Glass);
  scene.Renderer->AddActor(coneActor);
  scene.Renderer->SetPass(scene.Pass);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->SetFocalPoint(0.3, 0.0, -0.2);
  camera->SetPosition(0.6, 0.8, 4.2);
  camera->SetViewUp(0.0, 1.0, 0.0);
  scene.Renderer->ResetCameraClippingRange();

  window->SetSize(size, size);
  window->AddRenderer(scene.Renderer);
  return scene;
}

#endif
