// ISR's per-vertex d_N against closed forms: on a sphere the inward normal runs through the
// centre, so d_N is the diameter; on a slab (a thin box) it is the thickness; on an open
// mesh (a hemisphere's rim ray leaves it) the filter reports 0 rather than garbage. The rays
// are cast in packets of 8 on Threads threads: any thread count gives the same distances (a
// vertex count that is no multiple of 8 or of the threads, so partial packets and uneven runs
// are met), and the C core refuses 0 threads.
#include "../common/rf_require.h"
#include "rf_normal_distance.h"
#include "vtkISRDistanceFilter.h"

#include <vtkCubeSource.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>


int main()
{
  // Sphere of radius 1.5: d_N = 3 at every vertex (up to the polygonal surface: a chord
  // through the centre ends on a facet, at most R (1 - cos(pi/res)) short of the sphere).
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(1.5);
  sphere->SetThetaResolution(96);
  sphere->SetPhiResolution(96);
  vtkNew<vtkISRDistanceFilter> sphereDistances;
  sphereDistances->SetInputConnection(sphere->GetOutputPort());
  sphereDistances->Update();
  vtkDataArray* d = sphereDistances->GetOutput()->GetPointData()->GetArray("ISRNormalDistance");
  RF_REQUIRE(d != nullptr, "no ISRNormalDistance array");
  const double facetGap = 1.5 * (1.0 - std::cos(3.14159265358979 / 96.0));
  double worst = 0.0;
  for (vtkIdType i = 0; i < d->GetNumberOfTuples(); ++i)
  {
    worst = std::max(worst, std::abs(d->GetComponent(i, 0) - 3.0));
  }
  std::printf("sphere R=1.5: max |d_N - 3| = %.2e (facet gap %.2e), %.2f ms\n", worst, facetGap,
    sphereDistances->GetLastComputeSeconds() * 1e3);
  RF_REQUIRE(worst <= facetGap + 1e-5, "d_N is off the diameter by %g", worst);

  // Slab 4 x 4 x 0.3: the vertices of the large faces have normals along z (split normals of
  // vtkCubeSource), so d_N = 0.3 there.
  vtkNew<vtkCubeSource> slab;
  slab->SetXLength(4.0);
  slab->SetYLength(4.0);
  slab->SetZLength(0.3);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(slab->GetOutputPort());
  vtkNew<vtkISRDistanceFilter> slabDistances;
  slabDistances->SetInputConnection(triangles->GetOutputPort());
  slabDistances->Update();
  vtkPolyData* out = slabDistances->GetOutput();
  vtkDataArray* sd = out->GetPointData()->GetArray("ISRNormalDistance");
  vtkDataArray* normals = out->GetPointData()->GetNormals();
  RF_REQUIRE(sd && normals, "slab arrays missing");
  int faceVertices = 0;
  for (vtkIdType i = 0; i < sd->GetNumberOfTuples(); ++i)
  {
    double n[3];
    normals->GetTuple(i, n);
    if (std::abs(std::abs(n[2]) - 1.0) < 1e-9)
    {
      ++faceVertices;
      RF_REQUIRE(std::abs(sd->GetComponent(i, 0) - 0.3) < 1e-5, "slab d_N %g at vertex %lld",
        sd->GetComponent(i, 0), static_cast<long long>(i));
    }
  }
  RF_REQUIRE(faceVertices == 8, "expected 8 vertices on the large faces, found %d", faceVertices);

  // An open hemisphere: rays from the rim region may leave through the opening: 0, finite.
  vtkNew<vtkSphereSource> half;
  half->SetEndPhi(90.0);
  half->SetThetaResolution(32);
  half->SetPhiResolution(16);
  vtkNew<vtkISRDistanceFilter> halfDistances;
  halfDistances->SetInputConnection(half->GetOutputPort());
  halfDistances->Update();
  vtkDataArray* hd = halfDistances->GetOutput()->GetPointData()->GetArray("ISRNormalDistance");
  for (vtkIdType i = 0; i < hd->GetNumberOfTuples(); ++i)
  {
    const double v = hd->GetComponent(i, 0);
    RF_REQUIRE(std::isfinite(v) && v >= 0.0 && v <= 2.0 + 1e-6, "open mesh d_N %g", v);
  }
  std::printf("slab: d_N = 0.3 on all %d face vertices; open mesh: all finite\n", faceVertices);

  // The same distances on 1, 2, 3 and 5 threads.
  vtkNew<vtkSphereSource> odd;
  odd->SetThetaResolution(37);
  odd->SetPhiResolution(23);
  std::vector<float> single;
  for (int threads : { 1, 2, 3, 5 })
  {
    vtkNew<vtkISRDistanceFilter> distances;
    distances->SetThreads(threads);
    distances->SetInputConnection(odd->GetOutputPort());
    distances->Update();
    vtkDataArray* od = distances->GetOutput()->GetPointData()->GetArray("ISRNormalDistance");
    RF_REQUIRE(od && od->GetNumberOfTuples() % 8 != 0, "the point count should leave a partial packet");
    for (vtkIdType i = 0; i < od->GetNumberOfTuples(); ++i)
    {
      const float v = static_cast<float>(od->GetComponent(i, 0));
      if (threads == 1)
      {
        RF_REQUIRE(v > 0.9f && v < 1.01f, "d_N %g at vertex %lld of the unit-diameter sphere",
          v, static_cast<long long>(i));
        single.push_back(v);
      }
      else
      {
        RF_REQUIRE(v == single[static_cast<size_t>(i)], "%d threads: d_N %g at vertex %lld, %g on one",
          threads, v, static_cast<long long>(i), single[static_cast<size_t>(i)]);
      }
    }
  }
  const float point[3] = { 0.f, 0.f, 0.f };
  const float normal[3] = { 0.f, 0.f, 1.f };
  const unsigned triangle[3] = { 0, 0, 0 };
  float distance = -1.f;
  RF_REQUIRE(rf_normal_distances(point, normal, 1, triangle, 1, &distance, 0) ==
      RF_REF_ERR_BAD_OPTION,
    "0 threads accepted");
  std::printf("%zu vertices: the same d_N on 1, 2, 3 and 5 threads; 0 threads refused\n",
    single.size());
  return EXIT_SUCCESS;
}
