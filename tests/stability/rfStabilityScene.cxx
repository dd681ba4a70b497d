#include "rfStabilityScene.h"

using namespace rftest;

namespace rfstab
{
// RF_STABILITY_VERBOSE=1 prints the pixels behind the figures (for diagnosis).
bool Verbose()
{
  const char* v = std::getenv("RF_STABILITY_VERBOSE");
  return v && *v && *v != '0';
}

void DumpPixel(const char* what, const Frame& f, int i, const Trace& t, double error)
{
  if (!Verbose())
  {
    return;
  }
  const rf_vec3 p2 = f.P2At(i);
  const rf_vec3 t2 = f.T2At(i);
  std::printf("  %s px (%d,%d) err %.3g deg flag %g/%d  T2 (%.4f %.4f %.4f) ref (%.4f %.4f "
              "%.4f)  P2 (%.4f %.4f %.4f) ref (%.4f %.4f %.4f)\n",
    what, i % f.W, i / f.W, error, f.Flags[i], t.Flag, t2.x, t2.y, t2.z, t.T2.x, t.T2.y, t.T2.z,
    p2.x, p2.y, p2.z, t.P2.x, t.P2.y, t.P2.z);
}

/// `beforeBase`, when given, runs once the scene is set up, before the Base frame.
Run RunScene(const Scene& sc, const std::function<void(Run&)>& beforeBase)
{
  Run run;
  run.R.reset(new Rig(sc.Width, sc.Height));
  run.Actor = rftest::GlassActor(sc.Poly, sc.IOR);
  if (sc.Placement)
  {
    run.Actor->SetUserMatrix(sc.Placement);
  }
  run.R->Renderer->AddActor(run.Actor);
  run.R->LookAt(sc.Eye, sc.Focal, sc.Up, sc.ViewAngle, sc.Near, sc.Far);
  if (beforeBase)
  {
    beforeBase(run);
  }
  run.Base = run.R->Render();
  run.R->UseSmoothEnvironment(true);
  run.Smooth = run.R->Render();
  vtkNew<vtkMatrix4x4> placed;
  if (sc.PerturbIOR)
  {
    vtkRefractionPass::MakeGlass(run.Actor, sc.IOR * (1.0 + kPerturbation));
    rftest::WithoutHighlights(run.Actor);
  }
  else if (sc.Placement)
  {
    // Scale the placed local frame about its origin.
    placed->DeepCopy(sc.Placement);
    for (int r = 0; r < 3; ++r)
    {
      for (int k = 0; k < 3; ++k)
      {
        placed->SetElement(r, k, placed->GetElement(r, k) * (1.0 + kPerturbation));
      }
    }
    run.Actor->SetUserMatrix(placed);
  }
  else
  {
    run.Actor->SetOrigin(sc.PerturbCentre[0], sc.PerturbCentre[1], sc.PerturbCentre[2]);
    run.Actor->SetScale(1.0 + kPerturbation);
  }
  run.Perturbed = run.R->Render();
  vtkRefractionPass::MakeGlass(run.Actor, sc.IOR);
  rftest::WithoutHighlights(run.Actor);
  run.Actor->SetScale(1.0);
  run.Actor->SetUserMatrix(sc.Placement);
  run.R->UseSmoothEnvironment(false);
  return run;
}

SphereMeasure MeasureSphere(Rig& rig, const Frame& f, const SphereScene& sc,
  const std::function<bool(int, const Trace&)>& include)
{
  SphereMeasure m;
  const rf_vec3 c = rig.ToView(sc.Centre);
  const auto rays = rig.PixelRays(f.W, f.H);
  double sum = 0.0;
  for (int i = 0; i < f.W * f.H; ++i)
  {
    const rf_vec3 d = rays[i];
    const Trace t = ThroughSphere(d, c, sc.Radius, sc.IOR);
    const double impact = ImpactParameter(d, c) / sc.Radius;
    if (t.Hit != f.Glass(i))
    {
      m.CoreMismatch += impact < 0.98 ? 1 : 0;
      continue;
    }
    if (!t.Hit || (include && !include(i, t)))
    {
      continue;
    }
    const double e = AngleDegrees(f.T2At(i), t.T2);
    sum += e;
    ++m.Compared;
    if (impact < 0.9)
    {
      if (e > 0.5 * m.MaxInner && e > 1.0)
      {
        DumpPixel("sphere", f, i, t, e);
      }
      m.MaxInner = std::max(m.MaxInner, e);
    }
  }
  m.Mean = m.Compared ? sum / m.Compared : 0.0;
  return m;
}

Run RunSphere(const SphereScene& sc, bool perturbIOR)
{
  Scene scene;
  scene.Poly = sc.Poly ? sc.Poly
                       : rftest::SpherePoly(sc.Centre, sc.Radius, sc.Resolution, sc.DoublePoints);
  scene.IOR = sc.IOR;
  static_cast<View&>(scene) = sc;
  if (sc.FocalAtCentre)
  {
    std::copy(sc.Centre, sc.Centre + 3, scene.Focal);
  }
  scene.PerturbIOR = perturbIOR;
  std::copy(sc.Centre, sc.Centre + 3, scene.PerturbCentre);
  return RunScene(scene);
}

// Continuity is measured under the smooth environment (Rig::UseSmoothEnvironment): the
// built-in pattern's hard edges (ground tiles, the horizon) make the colour jump wherever one
// lies between two lookup directions however close, and near a silhouette the reflection
// sweeps a whole hemisphere across a few pixels, so that happens at many pixels.
void FillCommon(
  Row& row, const Frame& base, const Frame& smooth, const Frame& perturbed, int flagChangeBound)
{
  row.NonFinite = base.NonFinite() + smooth.NonFinite() + perturbed.NonFinite();
  row.GLErrors = base.GLErrors + smooth.GLErrors + perturbed.GLErrors;
  // The environment only colours: T2 must not depend on it.
  const Change same = Compare(base, smooth);
  row.Require(same.T2Degrees <= 1e-4 && same.FlagChanges == 0,
    "T2 depends on the environment (built-in against cube map)");
  const Change ch = Compare(smooth, perturbed);
  row.DeltaT2 = ch.T2Degrees;
  row.DeltaColour = ch.Colour;
  row.FlagChanges = ch.FlagChanges;
  row.FlagChangeBound = flagChangeBound;
  row.DeltaT2Bound = kDeltaT2Bound;
  row.DeltaColourBound = kDeltaColourBound;
  std::printf("%s: %d glass pixels compared under perturbation, %d changed flag\n",
    row.Case.c_str(), ch.GlassPixels, ch.FlagChanges);
}

void FillCommon(Row& row, const Run& run, double error, double errorBound, int flagChangeBound)
{
  row.Error = error;
  row.ErrorBound = errorBound;
  FillCommon(row, run.Base, run.Smooth, run.Perturbed, flagChangeBound);
}

// The closed-form colour a pixel may show: per channel, the range the closed form takes over
// the pixel's footprint (7 x 7 rays from -0.5 to +0.5 px). The error is the distance to that
// range, so an edge of the environment's pattern (or a reflection sweeping across it near a
// silhouette) that the pixel straddles is not an error, and a flat colour must still match.
double FootprintColourError(Rig& rig, const Frame& f, int x, int y,
  const std::function<bool(rf_vec3, rf_vec3&)>& expected)
{
  vtkNew<vtkMatrix4x4> toView;
  toView->DeepCopy(rig.Camera()->GetProjectionTransformMatrix(
    static_cast<double>(f.W) / f.H, -1.0, 1.0));
  toView->Invert();
  const rf_vec3 got = f.RGB(y * f.W + x);
  double lo[3] = { 1e30, 1e30, 1e30 };
  double hi[3] = { -1e30, -1e30, -1e30 };
  bool any = false;
  for (int j = -3; j <= 3; ++j)
  {
    for (int i = -3; i <= 3; ++i)
    {
      const double ndc[4] = { (x + 0.5 + i / 6.0) / f.W * 2.0 - 1.0,
        (y + 0.5 + j / 6.0) / f.H * 2.0 - 1.0, -1.0, 1.0 };
      double v[4];
      toView->MultiplyPoint(ndc, v);
      const rf_vec3 d = rf_vec3_normalize(rf_vec3_make(v[0] / v[3], v[1] / v[3], v[2] / v[3]));
      rf_vec3 want;
      if (!expected(d, want))
      {
        continue;
      }
      any = true;
      const double w[3] = { want.x, want.y, want.z };
      for (int k = 0; k < 3; ++k)
      {
        lo[k] = std::min(lo[k], w[k]);
        hi[k] = std::max(hi[k], w[k]);
      }
    }
  }
  if (!any)
  {
    return 1e30;
  }
  const double g[3] = { got.x, got.y, got.z };
  double e = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    e = std::max({ e, lo[k] - g[k], g[k] - hi[k] });
  }
  return std::isfinite(e) ? e : 1e30;
}

// Pixels whose 8 neighbours are glass too: the silhouette ring is rasterized from the
// tessellation, not from the closed form's surface.
bool InsideSilhouette(const Frame& f, int i)
{
  const int x = i % f.W;
  const int y = i / f.W;
  for (int j = -1; j <= 1; ++j)
  {
    for (int k = -1; k <= 1; ++k)
    {
      const int xx = x + k;
      const int yy = y + j;
      if (xx < 0 || yy < 0 || xx >= f.W || yy >= f.H || !f.Glass(yy * f.W + xx))
      {
        return false;
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
Row SphereRow(const char* name, const SphereScene& sc, double bound, double meanBound,
  const char* measure, int flagBound)
{
  Row row(name, measure, kGeometryPerturbation);
  auto run = RunSphere(sc, false);
  const SphereMeasure m = MeasureSphere(*run.R, run.Base, sc);
  std::printf("%s: %d pixels, T2 error inside 0.9 R max %.3g deg, mean %.3g deg; %d coverage "
              "mismatches inside 0.98 R\n",
    name, m.Compared, m.MaxInner, m.Mean, m.CoreMismatch);
  row.Require(m.Mean <= meanBound, "mean T2 error above its bound");
  row.Require(m.CoreMismatch <= 2, "the glass does not cover the sphere's silhouette");
  FillCommon(row, run, m.MaxInner, bound, flagBound);
  return row;
}
}
