// The stability cases on boxes, against the ray through a convex box: a flat slab (Zmin =
// Zmax), a grazing view and T1 parallel to the image plane.
#include "rfStabilityCases.h"
#include "rfStabilityScene.h"

using namespace rftest;

namespace rfstab
{
namespace
{
// Box scenes: the closed form is the ray through a convex box (rfstab::ThroughBox), exact for
// flat faces. Compared on pixels whose ray and whose 8 neighbours' rays enter and leave by the
// same faces (the pass's normals are filtered across face edges).
struct BoxScene : View
{
  double Centre[3] = { 0.0, 0.0, 0.0 };
  double Axis[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  double Length[3] = { 1.0, 1.0, 1.0 };
  double IOR = 1.5;
};

Box ViewBox(Rig& rig, const BoxScene& sc)
{
  Box b;
  b.C = rig.ToView(sc.Centre);
  for (int k = 0; k < 3; ++k)
  {
    b.Axis[k] = rf_vec3_normalize(rig.DirToView(sc.Axis[k]));
    b.Half[k] = 0.5 * sc.Length[k];
  }
  return b;
}

Run RunBox(const BoxScene& sc)
{
  Scene scene;
  scene.Poly = rftest::BoxPoly(sc.Length);
  scene.Placement = vtkSmartPointer<vtkMatrix4x4>::New();
  for (int r = 0; r < 3; ++r)
  {
    for (int k = 0; k < 3; ++k)
    {
      scene.Placement->SetElement(r, k, sc.Axis[k][r]);
    }
    scene.Placement->SetElement(r, 3, sc.Centre[r]);
  }
  scene.IOR = sc.IOR;
  static_cast<View&>(scene) = sc;
  return RunScene(scene);
}

struct BoxMeasure
{
  double Max = 0.0;
  double Mean = 0.0;
  int Compared = 0;
};

BoxMeasure MeasureBox(Rig& rig, const Frame& f, const BoxScene& sc,
  const std::function<bool(const Trace&, rf_vec3)>& include = nullptr)
{
  BoxMeasure m;
  const Box box = ViewBox(rig, sc);
  const auto rays = rig.PixelRays(f.W, f.H);
  std::vector<Trace> traces(rays.size());
  for (size_t i = 0; i < rays.size(); ++i)
  {
    traces[i] = ThroughBox(rays[i], box, sc.IOR);
  }
  double sum = 0.0;
  for (int y = 1; y + 1 < f.H; ++y)
  {
    for (int x = 1; x + 1 < f.W; ++x)
    {
      const int i = y * f.W + x;
      const Trace& t = traces[i];
      if (!t.Hit || !f.Glass(i))
      {
        continue;
      }
      bool uniform = true;
      for (int j = -1; j <= 1 && uniform; ++j)
      {
        for (int k = -1; k <= 1 && uniform; ++k)
        {
          const Trace& u = traces[(y + j) * f.W + x + k];
          uniform = u.Hit && u.EntryFace == t.EntryFace && u.ExitFace == t.ExitFace &&
            u.Flag == t.Flag && f.Glass((y + j) * f.W + x + k);
        }
      }
      if (!uniform || (include && !include(t, rays[i])))
      {
        continue;
      }
      const double e = AngleDegrees(f.T2At(i), t.T2);
      if (e > 0.5 * m.Max && e > 0.2)
      {
        DumpPixel("box", f, i, t, e);
      }
      m.Max = std::max(m.Max, e);
      sum += e;
      ++m.Compared;
    }
  }
  m.Mean = m.Compared ? sum / m.Compared : 0.0;
  return m;
}
}

Row CaseFlatSlab(const char* name)
{
  Row row(name, "T2 angle vs closed form (slab: T2 = V), interior (deg)", kGeometryPerturbation);
  BoxScene sc;
  sc.Length[0] = 2.0;
  sc.Length[1] = 2.0;
  sc.Length[2] = 0.3;
  auto run = RunBox(sc);
  const BoxMeasure m = MeasureBox(*run.R, run.Base, sc);
  std::printf("flat_slab: %d interior pixels, T2 error max %.3g deg, mean %.3g deg\n", m.Compared,
    m.Max, m.Mean);
  row.Require(m.Compared > 1000, "too few interior pixels");
  // Flat faces: the exact back normal is in the texture; what remains is float rounding
  // (0.06 deg with half-float normals).
  FillCommon(row, run, m.Max, 0.1, 0);
  return row;
}

Row CaseGrazing(const char* name)
{
  Row row(name, "T2 angle vs closed form, abs(N.V) < 0.1, interior (deg)", kGeometryPerturbation);
  // A long slab seen almost edge-on: its top face is met at 84-89.6 degrees of incidence.
  BoxScene sc;
  sc.Length[0] = 3.0;
  sc.Length[1] = 0.4;
  sc.Length[2] = 8.0;
  sc.Eye[1] = 0.23;
  sc.Eye[2] = 6.0;
  sc.Focal[1] = 0.2;
  sc.Focal[2] = -1.0;
  sc.ViewAngle = 8.0;
  sc.Near = 1.0;
  sc.Far = 20.0;
  sc.Width = 96;
  sc.Height = 96;
  auto run = RunBox(sc);
  double smallest = 1.0;
  const BoxMeasure m = MeasureBox(*run.R, run.Base, sc, [&smallest](const Trace& t, rf_vec3 d) {
    const double c = std::fabs(rf_vec3_dot(t.N1, d));
    if (t.EntryFace == 3 && c < 0.1)
    {
      smallest = std::min(smallest, c);
      return true;
    }
    return false;
  });
  std::printf("grazing_view: %d interior top-face pixels, |N.V| down to %.4f; T2 error max %.3g "
              "deg, mean %.3g deg\n",
    m.Compared, smallest, m.Max, m.Mean);
  row.Require(m.Compared > 200, "too few grazing pixels");
  row.Require(smallest < 0.02, "the view is not grazing");
  // Parallel top and bottom faces: T2 = V exactly when the exit is the bottom face.
  FillCommon(row, run, m.Max, 0.1, 2);
  return row;
}

Row CaseT1ParallelToImage(const char* name)
{
  Row row(name, "T2 angle vs closed form, abs(T1.z) < 0.05, interior (deg)", kGeometryPerturbation);
  // A slab far off-axis (156 degree view angle) whose front face refracts the central ray to
  // T1 = (1, 0, 0): T1.z crosses 0 over the slab, S and E of eq. 3-4 go to infinity.
  const double psiV = 65.26 * kPi / 180.0;
  const double psiN = 125.26 * kPi / 180.0; // direction of -N, from -z toward +x
  BoxScene sc;
  const double v[3] = { std::sin(psiV), 0.0, -std::cos(psiV) };
  const double inward[3] = { std::sin(psiN), 0.0, -std::cos(psiN) };
  for (int i = 0; i < 3; ++i)
  {
    sc.Centre[i] = 3.0 * v[i];
    sc.Axis[0][i] = -inward[i]; // thickness along the outward front normal
  }
  sc.Axis[1][0] = 0.0;
  sc.Axis[1][1] = 1.0;
  sc.Axis[1][2] = 0.0;
  sc.Axis[2][0] = sc.Axis[0][1] * 0.0 - sc.Axis[0][2] * 1.0; // axis0 x axis1
  sc.Axis[2][1] = 0.0;
  sc.Axis[2][2] = sc.Axis[0][0] * 1.0;
  sc.Length[0] = 0.3;
  sc.Length[1] = 1.0;
  sc.Length[2] = 1.0;
  sc.Eye[0] = sc.Eye[1] = sc.Eye[2] = 0.0;
  sc.Focal[0] = 0.0;
  sc.Focal[1] = 0.0;
  sc.Focal[2] = -1.0;
  sc.ViewAngle = 156.0;
  sc.Near = 0.5;
  sc.Far = 10.0;
  auto run = RunBox(sc);
  int nearZero = 0;
  double smallest = 1.0;
  const BoxMeasure m =
    MeasureBox(*run.R, run.Base, sc, [&](const Trace& t, rf_vec3 d) {
      rf_vec3 t1;
      if (t.EntryFace != 1 || rf_refract(d, t.N1, 1.0 / sc.IOR, &t1) != RF_OK)
      {
        return false;
      }
      if (std::fabs(t1.z) < 0.05)
      {
        ++nearZero;
        smallest = std::min(smallest, std::fabs(t1.z));
        return true;
      }
      return false;
    });
  std::printf("t1z_parallel: %d interior pixels with |T1.z| < 0.05 (down to %.2g); T2 error max "
              "%.3g deg, mean %.3g deg\n",
    m.Compared, smallest, m.Max, m.Mean);
  row.Require(m.Compared > 20, "too few pixels with T1.z near 0");
  row.Require(smallest < 0.005, "T1.z does not come near 0");
  // Parallel faces: T2 = V. Where T1 runs parallel to the image plane the exit is taken behind
  // the entry point; on this slab that is the same back face.
  FillCommon(row, run, m.Max, 0.1, 2);
  return row;
}
}
