// The isosurface the demo and the tests draw: a sampled field source (vtkMetaballsSource,
// vtkWaveEquationSource) on a 40^3 grid, contoured at the source's own iso value with
// normals. Header only: the caller includes and links the source's library.
#ifndef rfTestIsosurface_h
#define rfTestIsosurface_h

#include <vtkFlyingEdges3D.h>
#include <vtkSmartPointer.h>

namespace rftest
{
template <typename FieldSource>
vtkSmartPointer<vtkFlyingEdges3D> IsosurfaceOf(FieldSource* source)
{
  source->SetSampleDimensions(40);
  auto surface = vtkSmartPointer<vtkFlyingEdges3D>::New();
  surface->SetInputConnection(source->GetOutputPort());
  surface->SetValue(0, source->GetIsoValue());
  surface->ComputeNormalsOn();
  return surface;
}
}

#endif
