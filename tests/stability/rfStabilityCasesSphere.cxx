// The stability cases of extreme views of a sphere: far/near 1e6, an offset of 1e7, a
// window of 97 x 61, a one-pixel object and window, and the near plane through the glass.
#include "rfStabilityCases.h"
#include "rfStabilityScene.h"

using namespace rftest;

namespace rfstab
{
Row CaseFarNear(const char* name)
{
  SphereScene sc;
  sc.Near = 5e-3;
  sc.Far = 5e3;
  return SphereRow(name, sc, kSphereMax, kSphereMean);
}

Row CaseOffset(const char* name)
{
  SphereScene sc;
  sc.Centre[0] = 1e7;
  sc.Centre[1] = -1e7;
  sc.Centre[2] = 1e7;
  sc.Eye[0] = sc.Centre[0];
  sc.Eye[1] = sc.Centre[1];
  sc.Eye[2] = sc.Centre[2] + 4.0;
  sc.DoublePoints = true; // float points cannot hold a unit sphere at 1e7
  return SphereRow(name, sc, kSphereMax, kSphereMean);
}

Row CaseNonPowerOfTwo(const char* name)
{
  SphereScene sc;
  sc.Width = 97;
  sc.Height = 61;
  return SphereRow(name, sc, kSphereMax, kSphereMean);
}

namespace
{
// Objects that cover one texel of the back capture (a one-pixel object, a 1x1 window): the
// texel holds the depth and the normal of the whole object, so Zmin = Zmax and DIR cannot
// resolve the exit. What it can know is the back normal on the pixel's own straight ray;
// refracting T1 there is the one-texel limit, and the pass must be at that limit.
Row OneTexelCase(const char* name, const char* measure, const SphereScene& sc)
{
  Row row(name, measure, kGeometryPerturbation);
  // Look along -z at the origin, not at the sphere, so the pixel's ray passes off-centre.
  SphereScene offCentre = sc;
  offCentre.FocalAtCentre = false;
  std::fill(offCentre.Focal, offCentre.Focal + 3, 0.0);
  const Run run = RunSphere(offCentre, false);
  Rig* rig = run.R.get();
  const Frame& base = run.Base;
  const rf_vec3 c = rig->ToView(sc.Centre);
  const auto rays = rig->PixelRays(base.W, base.H);
  int covered = 0;
  double worst = 0.0;
  double model = 0.0;
  double modelError = 0.0;
  for (int i = 0; i < base.W * base.H; ++i)
  {
    if (!base.Glass(i))
    {
      continue;
    }
    ++covered;
    const Trace t = ThroughSphere(rays[i], c, sc.Radius, sc.IOR);
    worst = std::max(worst, t.Hit ? AngleDegrees(base.T2At(i), t.T2) : 180.0);
    if (t.Hit)
    {
      const rf_vec3 d = rays[i];
      const double b = rf_vec3_dot(d, c);
      const double disc = b * b - (rf_vec3_dot(c, c) - sc.Radius * sc.Radius);
      const rf_vec3 q = rf_vec3_scale(d, b + std::sqrt(std::max(disc, 0.0)));
      const rf_vec3 n2 = rf_vec3_scale(rf_vec3_sub(q, c), 1.0 / sc.Radius);
      rf_vec3 t1;
      rf_vec3 t2;
      if (rf_refract(d, t.N1, 1.0 / sc.IOR, &t1) == RF_OK &&
        rf_refract_clamped(t1, n2, sc.IOR, &t2) != RF_ERR_DEGENERATE_DIRECTION)
      {
        model = std::max(model, AngleDegrees(t2, t.T2));
        modelError = std::max(modelError, AngleDegrees(base.T2At(i), t2));
      }
    }
  }
  std::printf("%s: %d pixel(s) covered, T2 error max %.3g deg; the one-texel limit is %.3g deg "
              "from the closed form, the pass %.3g deg from that limit\n",
    name, covered, worst, model, modelError);
  row.Require(modelError <= 1.0, "the pass is not at the one-texel limit");
  row.Require(covered == 1, "the object does not cover exactly one pixel");
  // The one-texel limit's own error, plus the tessellation's (a 96-gon sphere).
  FillCommon(row, run, worst, model + 1.0, 0);
  return row;
}
}

Row CaseSinglePixelObject(const char* name)
{
  // A sphere of radius 0.6 px whose centre is 0.25 px off the centre of pixel (32, 32).
  SphereScene sc;
  sc.Width = 64;
  sc.Height = 64;
  const double pixel = 2.0 * std::tan(20.0 * kPi / 180.0) * 4.0 / 64.0; // at distance 4
  sc.Radius = 0.6 * pixel;
  sc.Centre[0] = 0.5 * pixel + 0.25 * pixel;
  sc.Centre[1] = 0.5 * pixel;
  return OneTexelCase(name, "T2 angle vs closed form, the covered pixel (deg)", sc);
}

Row CaseOnePixelWindow(const char* name)
{
  // A 1x1 window whose one ray passes the sphere at 0.4 R (one back texel, one reduction
  // level).
  SphereScene sc;
  sc.Width = 1;
  sc.Height = 1;
  sc.Centre[0] = 0.4;
  return OneTexelCase(name, "T2 angle vs closed form, the pixel (deg)", sc);
}

Row CaseNearPlane(const char* name)
{
  Row row(name,
    "T2 angle vs closed form, unclipped entry, impact < 0.9 R (deg)",
    kGeometryPerturbation);
  // The near plane (distance 1.6) cuts the front cap of a sphere off the view axis (its
  // nearest point at distance 1.5): part of the pixels see through the cut.
  SphereScene sc;
  sc.Centre[0] = 0.9;
  sc.Eye[0] = 0.0;
  sc.Eye[2] = 2.5;
  sc.ViewAngle = 70.0;
  sc.Near = 1.6;
  sc.Far = 10.0;
  sc.FocalAtCentre = false;
  auto run = RunSphere(sc, false);
  int clipped = 0;
  int clippedGlass = 0;
  const Frame& f = run.Base;
  const SphereMeasure m = MeasureSphere(*run.R, f, sc, [&](int i, const Trace& t) {
    if (-t.P1.z < sc.Near * 1.02)
    {
      ++clipped;
      clippedGlass += f.Glass(i) ? 1 : 0;
      return false;
    }
    return true;
  });
  std::printf("near_plane_crossing: %d pixels, T2 error max %.3g deg (mean %.3g); %d pixels "
              "enter in front of the near plane (%d drawn as glass, finite)\n",
    m.Compared, m.MaxInner, m.Mean, clipped, clippedGlass);
  row.Require(clipped > 100, "the near plane does not cut the sphere");
  FillCommon(row, run, m.MaxInner, kSphereMax, 2);
  return row;
}
}
