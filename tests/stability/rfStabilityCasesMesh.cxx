// The stability cases of awkward meshes: degenerate triangles and zero normals, an open
// mesh, and a topology change between two frames.
#include "rfStabilityCases.h"
#include "rfStabilityScene.h"
#include "rfTestIsosurface.h"

#include "vtkMetaballsSource.h"

#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataConnectivityFilter.h>
#include <vtkPolyDataMapper.h>

using namespace rftest;

namespace rfstab
{
Row CaseDegenerate(const char* name)
{
  // A sphere with a band of zero-length normals (whole triangles with only zero normals) and
  // extra zero-area triangles: repeated vertices and collinear ones.
  const double centre[3] = { 0.0, 0.0, 0.0 };
  auto poly = SpherePoly(centre, 1.0, 96, false);
  vtkDataArray* normals = poly->GetPointData()->GetNormals();
  int zeroed = 0;
  for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i)
  {
    double p[3];
    poly->GetPoint(i, p);
    if (p[1] > 0.2 && p[1] < 0.45)
    {
      normals->SetTuple3(i, 0.0, 0.0, 0.0);
      ++zeroed;
    }
  }
  vtkCellArray* polys = poly->GetPolys();
  const vtkIdType cells = polys->GetNumberOfCells();
  vtkPoints* points = poly->GetPoints();
  for (vtkIdType c = 0; c < cells; c += 7)
  {
    vtkIdType n;
    const vtkIdType* ids;
    polys->GetCellAtId(c, n, ids);
    // Away from the zero normals: a sliver (float rounding keeps "collinear" points from being
    // exactly so) covering a pixel with zero normals has no defined orientation at all.
    double probe[3];
    normals->GetTuple(ids[0], probe);
    bool valid = probe[0] != 0.0 || probe[1] != 0.0 || probe[2] != 0.0;
    normals->GetTuple(ids[1], probe);
    valid = valid && (probe[0] != 0.0 || probe[1] != 0.0 || probe[2] != 0.0);
    normals->GetTuple(ids[2], probe);
    valid = valid && (probe[0] != 0.0 || probe[1] != 0.0 || probe[2] != 0.0);
    if (!valid)
    {
      continue;
    }
    double a[3];
    double b[3];
    points->GetPoint(ids[0], a);
    points->GetPoint(ids[1], b);
    const vtkIdType mid =
      points->InsertNextPoint(0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2]));
    double na[3];
    normals->GetTuple(ids[0], na);
    normals->InsertNextTuple(na);
    const vtkIdType collinear[3] = { ids[0], mid, ids[1] };
    const vtkIdType repeated[3] = { ids[0], ids[0], ids[2] };
    polys->InsertNextCell(3, collinear);
    polys->InsertNextCell(3, repeated);
  }
  poly->Modified();
  std::printf("degenerate: %d zero normals, %lld zero-area triangles added\n", zeroed,
    static_cast<long long>(polys->GetNumberOfCells() - cells));
  SphereScene sc;
  sc.Poly = poly;
  sc.Resolution = 96;
  // Where the normals are zero the face normal stands in: the facets of a 96-gon (3.75 deg)
  // bend T2 by up to about twice the smooth sphere's error in that band.
  return SphereRow(name, sc, 3.0, kSphereMean,
    "T2 angle vs closed form, impact < 0.9 R (deg)");
}

Row CaseOpenMesh(const char* name)
{
  Row row(name,
    "T2 angle vs V (a single open sheet), inside silhouette (deg)",
    kGeometryPerturbation);
  // The upper half of a sphere, open at its equator, seen from above: every ray crosses one
  // surface, the back capture holds that same surface, and the pass must act as a thin sheet.
  SphereScene sc;
  sc.Poly = rftest::SpherePoly(sc.Centre, sc.Radius, sc.Resolution, false, 90.0);
  const Run run = RunSphere(sc, false);
  const Frame& base = run.Base;
  const auto rays = run.R->PixelRays(base.W, base.H);
  double worst = 0.0;
  int count = 0;
  for (int i = 0; i < base.W * base.H; ++i)
  {
    if (base.Glass(i) && InsideSilhouette(base, i))
    {
      ++count;
      worst = std::max(worst, AngleDegrees(base.T2At(i), rays[i]));
    }
  }
  std::printf("open_mesh: %d pixels, T2 vs V max %.3g deg\n", count, worst);
  row.Require(count > 1000, "too few glass pixels");
  // The exit normal is the entry normal read back from the capture.
  FillCommon(row, run, worst, 0.1, 0);
  return row;
}

namespace
{
vtkSmartPointer<vtkPolyData> Metaballs(double time)
{
  vtkNew<vtkMetaballsSource> blobs;
  auto surface = rftest::IsosurfaceOf(blobs.Get());
  surface->UpdateTimeStep(time);
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->DeepCopy(surface->GetOutput());
  return poly;
}

int Regions(vtkPolyData* poly)
{
  vtkNew<vtkPolyDataConnectivityFilter> connectivity;
  connectivity->SetInputData(poly);
  connectivity->SetExtractionModeToAllRegions();
  connectivity->Update();
  return connectivity->GetNumberOfExtractedRegions();
}
}

Row CaseTopologyChange(const char* name)
{
  Row row(name, "T2 angle vs a fresh pass on the new mesh (deg)", kGeometryPerturbation);
  // Metaballs contoured at two times with different numbers of blobs: the same actor gets the
  // new mesh between two frames and must give what a fresh pass gives on it.
  auto before = Metaballs(0.0);
  auto after = before;
  int regionsBefore = Regions(before);
  int regionsAfter = regionsBefore;
  for (double t = 0.05; t < 1.0 && regionsAfter == regionsBefore; t += 0.05)
  {
    after = Metaballs(t);
    regionsAfter = Regions(after);
  }
  std::printf("topology_change: %lld points in %d blob(s), then %lld points in %d blob(s)\n",
    static_cast<long long>(before->GetNumberOfPoints()), regionsBefore,
    static_cast<long long>(after->GetNumberOfPoints()), regionsAfter);
  Scene scene;
  scene.Poly = before;
  scene.Eye[2] = 3.5;
  // The first frame shows the old mesh; then the same actor's mapper gets the new one.
  Frame first;
  const Run run = RunScene(scene, [&first, &after](Run& r) {
    first = r.R->Render();
    vtkPolyDataMapper::SafeDownCast(r.Actor->GetMapper())->SetInputData(after);
  });
  const Frame& second = run.Base;
  const Frame& smooth = run.Smooth;
  const Frame& perturbed = run.Perturbed;

  scene.Poly = after;
  const Frame reference = RunScene(scene).Base;
  const Change ch = Compare(second, reference);
  std::printf("topology_change: against a fresh pass: T2 max %.3g deg, colour max %.3g, %d "
              "pixels differ in flag\n",
    ch.T2Degrees, ch.Colour, ch.FlagChanges);
  row.Error = ch.T2Degrees;
  row.ErrorBound = 1e-4; // the same input must give the same output
  row.Require(regionsAfter != regionsBefore, "the topology did not change");
  row.Require(ch.FlagChanges == 0 && ch.Colour <= 1e-6, "differs from a fresh pass");
  row.Require(Compare(first, second).GlassPixels > 0, "nothing drawn");
  row.NonFinite = first.NonFinite();
  FillCommon(row, second, smooth, perturbed, 2);
  row.NonFinite += first.NonFinite() + reference.NonFinite();
  row.GLErrors += first.GLErrors;
  return row;
}
}
