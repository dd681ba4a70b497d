// What the stability cases share: the bounds, the one scene set-up of every case (a glass
// actor in the probe rig, rendered as is, under the smooth environment and perturbed), the
// sphere scenes with their closed-form measure, and the checks every row gets (FillCommon).
#ifndef rfStabilityScene_h
#define rfStabilityScene_h

#include "rfStability.h"

#include <vtkMatrix4x4.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <functional>
#include <memory>

namespace rfstab
{
using rftest::Rig;

constexpr double kPerturbation = 1e-6;
constexpr const char* kGeometryPerturbation = "geometry x (1 + 1e-6)";
constexpr const char* kIORPerturbation = "IOR x (1 + 1e-6)";
constexpr double kPi = 3.14159265358979323846;

// Bounds shared by the cases; each case states why where it differs.
// Continuity: a 1e-6 relative change may move the conservative search's decisions for a few
// pixels (a candidate exactly on the stored depth), which moves P2 by one search step and T2 by
// the difference of the back normals there; the bounds allow that and nothing larger.
constexpr double kDeltaT2Bound = 0.5; // degrees
// Under the smooth environment (colours change by at most ~2 per radian of direction), so the
// colour bound is the T2 bound's image.
constexpr double kDeltaColourBound = 0.02;

//------------------------------------------------------------------------------
// The one scene set-up of every case: one glass actor (its data, optionally placed by a user
// matrix) in the probe rig, seen by one camera. RunScene renders it three times: under the
// built-in environment (Base: what the errors are measured on), under the smooth environment
// (Smooth), and under the smooth environment with the input perturbed by a relative 1e-6
// (Perturbed: continuity), then undoes the perturbation.
// The camera and window every case starts from; each case changes what its scene needs.
struct View
{
  double Eye[3] = { 0.0, 0.0, 4.0 };
  double Focal[3] = { 0.0, 0.0, 0.0 };
  double Up[3] = { 0.0, 1.0, 0.0 };
  double ViewAngle = 40.0;
  double Near = 1.0;
  double Far = 10.0;
  int Width = 96;
  int Height = 96;
};

struct Scene : View
{
  vtkSmartPointer<vtkPolyData> Poly;
  vtkSmartPointer<vtkMatrix4x4> Placement; // user matrix; none: the data's own coordinates
  double IOR = 1.5;
  bool PerturbIOR = false;                    // else the geometry is scaled by 1 + 1e-6 ...
  double PerturbCentre[3] = { 0.0, 0.0, 0.0 }; // ... about this point (without a placement)
};

struct Run
{
  std::unique_ptr<Rig> R;
  vtkSmartPointer<vtkActor> Actor;
  Frame Base;
  Frame Smooth;
  Frame Perturbed;
};

/// `beforeBase`, when given, runs once the scene is set up, before the Base frame.
Run RunScene(const Scene& sc, const std::function<void(Run&)>& beforeBase = nullptr);

//------------------------------------------------------------------------------
// Sphere scenes: the closed form is the ray through a sphere (rfstab::ThroughSphere).
struct SphereScene : View
{
  double Centre[3] = { 0.0, 0.0, 0.0 };
  double Radius = 1.0;
  int Resolution = 96;
  double IOR = 1.5;
  bool DoublePoints = false;
  bool FocalAtCentre = true; // else the camera looks at Focal
  vtkSmartPointer<vtkPolyData> Poly; // replaces the sphere source's output when set
};

struct SphereMeasure
{
  double MaxInner = 0.0; // largest T2 angular error (deg) where the impact parameter < 0.9 R
  double Mean = 0.0;     // mean T2 angular error over all pixels both call glass
  int Compared = 0;
  int CoreMismatch = 0; // pixels inside 0.98 R that the pass does not draw as glass, or v.v.
};

/// T2's error against the closed form on the pixels `include` accepts (all when not given).
SphereMeasure MeasureSphere(Rig& rig, const Frame& f, const SphereScene& sc,
  const std::function<bool(int, const Trace&)>& include = nullptr);

/// RunScene on the sphere scene; perturbs the IOR, else the geometry.
Run RunSphere(const SphereScene& sc, bool perturbIOR);

/// The sphere cases' row: T2 against the closed form inside 0.9 R, and continuity.
Row SphereRow(const char* name, const SphereScene& sc, double bound, double meanBound,
  const char* measure = "T2 angle vs closed form, impact < 0.9 R (deg)", int flagBound = 2);

// The sphere cases' bound, as the analytic test (regression.sphere_exit_direction), at 96 px:
// 1.34-1.43 deg with the paper's search alone, 0.29-0.69 with the secant refinement.
constexpr double kSphereMax = 1.5;
constexpr double kSphereMean = 1.0;

/// RF_STABILITY_VERBOSE=1 prints the pixels behind the figures (for diagnosis).
bool Verbose();

/// Prints one pixel against its closed form when Verbose().
void DumpPixel(const char* what, const Frame& f, int i, const Trace& t, double error);

/// What every row checks: finite values, GL errors, T2 independent of the environment, and
/// the continuity bounds between the smooth and the perturbed frames.
void FillCommon(
  Row& row, const Frame& base, const Frame& smooth, const Frame& perturbed, int flagChangeBound);

/// FillCommon on a run's three frames, with the case's own error and bound.
void FillCommon(Row& row, const Run& run, double error, double errorBound, int flagChangeBound);

/// The distance of pixel (x, y)'s colour to the range `expected` takes over its footprint.
double FootprintColourError(Rig& rig, const Frame& f, int x, int y,
  const std::function<bool(rf_vec3, rf_vec3&)>& expected);

/// Pixels whose 8 neighbours are glass too.
bool InsideSilhouette(const Frame& f, int i);
}

#endif
