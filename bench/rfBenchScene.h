// The scenes: each mesh the benchmark measures (with ISR's d_N, and the SH method's transfer
// when a row needs it), the scene mesh's opaque surroundings, the glass set on and off, and
// the camera and window that frame them.
#ifndef rfBenchScene_h
#define rfBenchScene_h

#include "rfBenchOptions.h"

#include <vtkActor.h>
#include <vtkAlgorithm.h>
#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <string>
#include <vector>

class vtkRefractionPass;
class vtkRenderWindow;
class vtkRenderer;

namespace rfbench
{
// The mesh `name` (see --meshes; also nested-inner), with d_N for ISR; nullptr when it
// cannot be made (its message printed).
vtkSmartPointer<vtkAlgorithm> MakeMesh(const std::string& name, const Options& o);

// The scene mesh's checkerboard and axes.
std::vector<vtkSmartPointer<vtkActor>> MakeSurroundings();

// One mesh in the scene: its actor, the opaque actors around it, and what the rows report.
struct Scene
{
  std::string Name;
  vtkSmartPointer<vtkAlgorithm> Mesh;
  vtkSmartPointer<vtkActor> Actor;
  std::vector<vtkSmartPointer<vtkActor>> Surroundings; // the scene mesh's plane and axes
  vtkSmartPointer<vtkActor> Inner; // the nested mesh's inner contour, glass of IOR 1.9
  vtkIdType Triangles = 0;
  double SHSeconds = 0.0; // the SH method's precomputation of the scene's glass
};

// The SH method's precomputation between a mesh and its mapper; adds its seconds to `seconds`.
vtkSmartPointer<vtkAlgorithm> WithSHTransfer(
  vtkAlgorithm* mesh, double ior, const Options& o, double& seconds);

// Makes the scene's glass glass (IOR 1.5, the nested mesh's inner contour 1.9), or clears it.
void SetGlass(const Scene& scene, bool glass);

// Puts the scene in the renderer, framed by the benchmark's camera, at a size.
void Show(vtkRenderWindow* window, vtkRenderer* renderer, vtkRefractionPass* pass,
  const Scene& scene, int size);
}

#endif
