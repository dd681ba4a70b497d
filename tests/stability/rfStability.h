// The stability suite's closed forms (a ray through a sphere, through a box), the
// continuity measure between two frames, and one line of the stability table. The scenes
// render through the shared probe rig (tests/common/rfTestRig.h).
#ifndef rfStability_h
#define rfStability_h

#include "rfTestRig.h"

#include "rf_optics.h"
#include "rf_vec3.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace rfstab
{
using rftest::Frame;

//------------------------------------------------------------------------------
// Closed forms. The eye is the view-space origin; `ior` is the glass's index (outside is 1).
// The exit follows the pass's default policy, TIR_CLAMP (rf_refract_clamped), and a ray that
// is totally reflected on entry (ior < 1, a bubble) leaves along the mirror direction.
struct Trace
{
  bool Hit = false;
  int Flag = 0; // as the debug output: 1 through, 2 TIR at the exit, 3 TIR at the entry
  rf_vec3 P1 = { 0, 0, 0 };
  rf_vec3 N1 = { 0, 0, 0 }; // unit, facing the eye
  rf_vec3 P2 = { 0, 0, 0 };
  rf_vec3 T2 = { 0, 0, 0 };
  int EntryFace = -1; // for boxes: 2 * axis + side
  int ExitFace = -1;
};

inline double AngleDegrees(rf_vec3 a, rf_vec3 b)
{
  const rf_vec3 ua = rf_vec3_normalize(a);
  const rf_vec3 ub = rf_vec3_normalize(b);
  if (rf_vec3_length(ua) == 0.0 || rf_vec3_length(ub) == 0.0)
  {
    return 180.0;
  }
  // atan2 of |a x b| and a.b stays accurate for tiny angles, unlike acos.
  return std::atan2(rf_vec3_length(rf_vec3_cross(ua, ub)), rf_vec3_dot(ua, ub)) * 180.0 /
    3.14159265358979323846;
}

/// Refraction into the glass at t.P1 with the outward normal t.N1. On TIR (ior < 1) the
/// trace ends there: flag 3, leaving along the mirror direction; returns false.
inline bool Enter(rf_vec3 d, Trace& t, double ior, rf_vec3& t1)
{
  if (rf_refract(d, t.N1, 1.0 / ior, &t1) == RF_OK)
  {
    return true;
  }
  t.Flag = 3;
  t.P2 = t.P1;
  t.T2 = rf_reflect(d, t.N1);
  return false;
}

/// The distance from the centre c to the line of sight along the unit direction d.
inline double ImpactParameter(rf_vec3 d, rf_vec3 c)
{
  const double along = rf_vec3_dot(d, c);
  return std::sqrt(std::max(0.0, rf_vec3_dot(c, c) - along * along));
}

/// The ray along the unit direction d through a sphere (view-space centre c, radius r).
inline Trace ThroughSphere(rf_vec3 d, rf_vec3 c, double r, double ior)
{
  Trace t;
  const double b = rf_vec3_dot(d, c);
  const double disc = b * b - (rf_vec3_dot(c, c) - r * r);
  if (disc <= 0.0 || b - std::sqrt(disc) <= 0.0)
  {
    return t;
  }
  t.Hit = true;
  t.P1 = rf_vec3_scale(d, b - std::sqrt(disc));
  t.N1 = rf_vec3_scale(rf_vec3_sub(t.P1, c), 1.0 / r);
  rf_vec3 t1;
  if (!Enter(d, t, ior, t1))
  {
    return t;
  }
  // The chord of a sphere along t1 from P1 has length 2 r cos(theta_t).
  t.P2 = rf_vec3_add(t.P1, rf_vec3_scale(t1, 2.0 * r * -rf_vec3_dot(t1, t.N1)));
  const rf_vec3 n2 = rf_vec3_scale(rf_vec3_sub(t.P2, c), 1.0 / r);
  t.Flag = rf_refract_clamped(t1, n2, ior, &t.T2) == RF_TIR ? 2 : 1;
  return t;
}

/// A box: view-space centre, orthonormal axes and half sizes.
struct Box
{
  rf_vec3 C;
  rf_vec3 Axis[3];
  double Half[3];
};

inline Trace ThroughBox(rf_vec3 d, const Box& box, double ior)
{
  Trace t;
  // Slabs in the box's frame: the eye is at -C.
  double o[3];
  double dir[3];
  double tNear = -1e300;
  double tFar = 1e300;
  int nearFace = -1;
  int farFace = -1;
  for (int k = 0; k < 3; ++k)
  {
    o[k] = -rf_vec3_dot(box.C, box.Axis[k]);
    dir[k] = rf_vec3_dot(d, box.Axis[k]);
    if (std::fabs(dir[k]) < 1e-300)
    {
      if (std::fabs(o[k]) > box.Half[k])
      {
        return t;
      }
      continue;
    }
    double t0 = (-box.Half[k] - o[k]) / dir[k];
    double t1 = (box.Half[k] - o[k]) / dir[k];
    int f0 = 2 * k;
    int f1 = 2 * k + 1;
    if (t0 > t1)
    {
      std::swap(t0, t1);
      std::swap(f0, f1);
    }
    if (t0 > tNear)
    {
      tNear = t0;
      nearFace = f0;
    }
    if (t1 < tFar)
    {
      tFar = t1;
      farFace = f1;
    }
  }
  if (!(tNear < tFar) || tNear <= 0.0 || nearFace < 0)
  {
    return t;
  }
  (void)farFace;
  auto outward = [&box](int face) {
    return rf_vec3_scale(box.Axis[face / 2], (face % 2) ? 1.0 : -1.0);
  };
  t.Hit = true;
  t.EntryFace = nearFace;
  t.P1 = rf_vec3_scale(d, tNear);
  t.N1 = outward(nearFace);
  rf_vec3 t1;
  if (!Enter(d, t, ior, t1))
  {
    return t;
  }
  // Exit: the nearest slab plane ahead of P1 along t1, from inside.
  double best = 1e300;
  int exitFace = -1;
  for (int k = 0; k < 3; ++k)
  {
    const double pk = rf_vec3_dot(rf_vec3_sub(t.P1, box.C), box.Axis[k]);
    const double dk = rf_vec3_dot(t1, box.Axis[k]);
    if (std::fabs(dk) < 1e-300)
    {
      continue;
    }
    const int face = dk > 0.0 ? 2 * k + 1 : 2 * k;
    const double s = ((dk > 0.0 ? box.Half[k] : -box.Half[k]) - pk) / dk;
    if (s > 1e-12 && s < best)
    {
      best = s;
      exitFace = face;
    }
  }
  t.ExitFace = exitFace;
  t.P2 = rf_vec3_add(t.P1, rf_vec3_scale(t1, best));
  t.Flag = rf_refract_clamped(t1, outward(exitFace), ior, &t.T2) == RF_TIR ? 2 : 1;
  return t;
}

//------------------------------------------------------------------------------
// Continuity between two frames of the same scene, the second with a perturbed input.
struct Change
{
  double T2Degrees = 0.0; // largest change of T2 over pixels that are glass with the same flag
  double Colour = 0.0;    // largest change of a colour channel over those pixels
  int FlagChanges = 0;    // pixels whose flag (coverage or TIR) differs
  int GlassPixels = 0;
};

inline Change Compare(const Frame& a, const Frame& b)
{
  Change c;
  const int n = a.W * a.H;
  for (int i = 0; i < n && b.W * b.H == n; ++i)
  {
    if (!a.Glass(i) && !b.Glass(i))
    {
      continue;
    }
    if (a.Flags[i] != b.Flags[i])
    {
      ++c.FlagChanges;
      continue;
    }
    ++c.GlassPixels;
    c.T2Degrees = std::max(c.T2Degrees, AngleDegrees(a.T2At(i), b.T2At(i)));
    for (int k = 0; k < 3; ++k)
    {
      const double d = std::fabs(static_cast<double>(a.Colour[4 * i + k]) - b.Colour[4 * i + k]);
      if (d > 0.005 && std::getenv("RF_STABILITY_VERBOSE"))
      {
        std::printf("  dColour px (%d,%d) %.3g: (%.4f %.4f %.4f) -> (%.4f %.4f %.4f), T2 "
                    "(%.5f %.5f %.5f) -> (%.5f %.5f %.5f)\n",
          i % a.W, i / a.W, d, a.RGB(i).x, a.RGB(i).y, a.RGB(i).z, b.RGB(i).x, b.RGB(i).y,
          b.RGB(i).z, a.T2At(i).x, a.T2At(i).y, a.T2At(i).z, b.T2At(i).x, b.T2At(i).y,
          b.T2At(i).z);
      }
      c.Colour = std::max(c.Colour, std::isfinite(d) ? d : 1e30);
    }
  }
  return c;
}

//------------------------------------------------------------------------------
// One line of the stability table.
struct Row
{
  std::string Case;
  std::string Measure; // what the error is, with its unit
  double Error = 0.0;
  double ErrorBound = 0.0;
  int NonFinite = 0;
  int GLErrors = 0;
  std::string Perturbation;
  double DeltaT2 = 0.0;
  double DeltaT2Bound = 0.0;
  double DeltaColour = 0.0;
  double DeltaColourBound = 0.0;
  int FlagChanges = 0;
  int FlagChangeBound = 0;
  std::vector<std::string> Failures;

  Row() = default;
  Row(const char* name, const char* measure, const char* perturbation)
    : Case(name)
    , Measure(measure)
    , Perturbation(perturbation)
  {
  }
  bool Passed() const { return this->Failures.empty(); }
  void Require(bool ok, const std::string& what)
  {
    if (!ok)
    {
      this->Failures.push_back(what);
    }
  }
  /// Checks the common assertions; call after filling the figures.
  void Judge()
  {
    this->Require(this->NonFinite == 0, "NaN/Inf in the output");
    this->Require(this->GLErrors == 0, "OpenGL error after the pass");
    this->Require(this->Error <= this->ErrorBound, "error above its bound");
    this->Require(this->DeltaT2 <= this->DeltaT2Bound, "T2 change under perturbation above bound");
    this->Require(
      this->DeltaColour <= this->DeltaColourBound, "colour change under perturbation above bound");
    this->Require(this->FlagChanges <= this->FlagChangeBound, "too many pixels changed flag");
  }
};
}

#endif
