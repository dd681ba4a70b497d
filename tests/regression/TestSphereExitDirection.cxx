// Analytic check of DIR: a glass sphere seen head-on. Along the horizontal diameter of the
// image, the exit direction T2 and exit point P2 that the pass reports (debug output) are
// compared with the closed form of a ray through a sphere (Snell's law at both interfaces).
#include "rfTestScene.h"

#include <vtkDataArray.h>
#include <vtkMatrix4x4.h>
#include <vtkPointData.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace
{
struct V3
{
  double x, y, z;
};
V3 operator+(V3 a, V3 b) { return { a.x + b.x, a.y + b.y, a.z + b.z }; }
V3 operator-(V3 a, V3 b) { return { a.x - b.x, a.y - b.y, a.z - b.z }; }
V3 operator*(double s, V3 a) { return { s * a.x, s * a.y, s * a.z }; }
double Dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 Unit(V3 a) { return (1.0 / std::sqrt(Dot(a, a))) * a; }

// Snell's law, written out: eta = n_incident / n_transmitted, normal against the ray.
bool Refract(V3 d, V3 n, double eta, V3& t)
{
  const double cosI = -Dot(d, n);
  const double k = 1.0 - eta * eta * (1.0 - cosI * cosI);
  if (k < 0.0)
  {
    return false;
  }
  t = Unit(eta * d + (eta * cosI - std::sqrt(k)) * n);
  return true;
}

// A ray from the eye (view-space origin) along d through a sphere of radius r at c.
bool ThroughSphere(V3 d, V3 c, double r, double ior, V3& p2, V3& t2)
{
  const double b = Dot(d, c);
  const double disc = b * b - (Dot(c, c) - r * r);
  if (disc <= 0.0)
  {
    return false;
  }
  const V3 p1 = (b - std::sqrt(disc)) * d;
  const V3 n1 = (1.0 / r) * (p1 - c);
  V3 t1;
  if (!Refract(d, n1, 1.0 / ior, t1))
  {
    return false;
  }
  // The chord of a sphere along t1 from p1 has length 2 r cos(theta_t).
  p2 = p1 + (2.0 * r * -Dot(t1, n1)) * t1;
  const V3 n2 = (1.0 / r) * (p2 - c);
  return Refract(t1, -1.0 * n2, ior, t2);
}
}

int main(int, char*[])
{
  const int size = 200;
  const double ior = 1.5;
  const double distance = 4.0;
  vtkNew<vtkRenderer> renderer;
  auto sphere = rftest::MakeSphere(1.0, 256);
  vtkRefractionPass::MakeGlass(sphere, ior);
  renderer->AddActor(sphere);
  vtkNew<vtkRefractionPass> glass;
  glass->DebugOutputOn();
  renderer->SetPass(glass);
  auto window = rftest::MakeWindow(renderer, size, size);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 0.0, distance);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(40.0);
  camera->SetClippingRange(1.0, 10.0);
  window->Render();

  vtkImageData* debug = glass->GetDebugImage();
  RF_REQUIRE(debug != nullptr, "no debug image");
  vtkDataArray* t2Array = debug->GetPointData()->GetArray("T2");
  vtkDataArray* p2Array = debug->GetPointData()->GetArray("P2");
  vtkDataArray* flags = debug->GetPointData()->GetArray("Flags");
  RF_REQUIRE(t2Array && p2Array && flags, "debug arrays missing");

  vtkNew<vtkMatrix4x4> toView;
  toView->DeepCopy(camera->GetProjectionTransformMatrix(1.0, -1.0, 1.0));
  toView->Invert();
  const V3 centre = { 0.0, 0.0, -distance };
  std::vector<double> angles;
  double worstInner = 0.0;
  double worstP2 = 0.0;
  int coverageMismatch = 0;
  const int row = size / 2;
  for (int i = 0; i < size; ++i)
  {
    const double ndc[4] = { (i + 0.5) / size * 2.0 - 1.0, (row + 0.5) / size * 2.0 - 1.0, -1.0,
      1.0 };
    double view[4];
    toView->MultiplyPoint(ndc, view);
    const V3 d = Unit({ view[0] / view[3], view[1] / view[3], view[2] / view[3] });
    V3 p2;
    V3 t2;
    const bool hit = ThroughSphere(d, centre, 1.0, ior, p2, t2);
    const vtkIdType id = static_cast<vtkIdType>(row) * size + i;
    const bool glassPixel = flags->GetComponent(id, 0) > 0.5;
    // The impact parameter: distance of the ray from the sphere's centre.
    const double along = Dot(d, centre);
    const double impact = std::sqrt(std::max(0.0, Dot(centre, centre) - along * along));
    if (hit != glassPixel)
    {
      // The tessellated silhouette may differ from the true one by a pixel.
      coverageMismatch += impact < 0.98 ? 100 : 1;
      continue;
    }
    if (!hit)
    {
      continue;
    }
    double measured[3];
    t2Array->GetTuple(id, measured);
    const V3 m = Unit({ measured[0], measured[1], measured[2] });
    const double angle =
      std::acos(std::max(-1.0, std::min(1.0, Dot(m, t2)))) * 180.0 / 3.14159265358979;
    angles.push_back(angle);
    if (impact < 0.9)
    {
      worstInner = std::max(worstInner, angle);
      double q[3];
      p2Array->GetTuple(id, q);
      const V3 e = V3{ q[0], q[1], q[2] } - p2;
      worstP2 = std::max(worstP2, std::sqrt(Dot(e, e)));
    }
  }
  RF_REQUIRE(angles.size() > 100, "too few glass pixels on the diameter: %zu", angles.size());
  std::sort(angles.begin(), angles.end());
  double mean = 0.0;
  for (double a : angles)
  {
    mean += a;
  }
  mean /= angles.size();
  const double p95 = angles[static_cast<size_t>(0.95 * (angles.size() - 1))];
  std::printf("sphere n=%.2f, %zu pixels on the diameter, %d CBS steps: T2 angular error mean "
              "%.3f deg, p95 %.3f deg, max %.3f deg; inside 0.9 R: max %.3f deg, P2 error max "
              "%.4f (radius 1); coverage mismatches %d\n",
    ior, angles.size(), glass->GetSearchSteps(), mean, p95, angles.back(), worstInner, worstP2,
    coverageMismatch);
  // Tolerances (stated in docs/tests.md), about 3x what llvmpipe measures (mean 0.028 deg, 0.061
  // deg inside 0.9 R, P2 0.039): the search with its secant step on a 256-sided polygonal
  // sphere read from a 200 px texture. The paper's search alone (no secant) misses them.
  RF_REQUIRE(coverageMismatch < 100, "glass pixels do not match the sphere's silhouette");
  RF_REQUIRE(mean < 0.1, "mean angular error %.3f deg", mean);
  RF_REQUIRE(worstInner < 0.2, "angular error %.3f deg inside 0.9 R", worstInner);
  RF_REQUIRE(worstP2 < 0.08, "P2 error %.4f inside 0.9 R", worstP2);

  // The same measure tells SIR (no second interface) apart: T2 is then T1, far off.
  glass->SetMethod(vtkRefractionPass::SIR);
  window->Render();
  RF_REQUIRE(glass->GetDebugImage(), "no debug image with SIR");
  t2Array = glass->GetDebugImage()->GetPointData()->GetArray("T2");
  double sirMean = 0.0;
  int sirCount = 0;
  for (int i = 0; i < size; ++i)
  {
    const vtkIdType id = static_cast<vtkIdType>(row) * size + i;
    if (glass->GetDebugImage()->GetPointData()->GetArray("Flags")->GetComponent(id, 0) < 0.5)
    {
      continue;
    }
    const double ndc[4] = { (i + 0.5) / size * 2.0 - 1.0, (row + 0.5) / size * 2.0 - 1.0, -1.0,
      1.0 };
    double view[4];
    toView->MultiplyPoint(ndc, view);
    const V3 d = Unit({ view[0] / view[3], view[1] / view[3], view[2] / view[3] });
    V3 p2;
    V3 t2;
    if (!ThroughSphere(d, centre, 1.0, ior, p2, t2))
    {
      continue;
    }
    double measured[3];
    t2Array->GetTuple(id, measured);
    const V3 m = Unit({ measured[0], measured[1], measured[2] });
    sirMean += std::acos(std::max(-1.0, std::min(1.0, Dot(m, t2)))) * 180.0 / 3.14159265358979;
    ++sirCount;
  }
  sirMean /= std::max(sirCount, 1);
  std::printf("SIR on the same pixels: T2 angular error mean %.3f deg\n", sirMean);
  RF_REQUIRE(sirMean > 5.0, "the check does not tell SIR from DIR (SIR mean %.3f deg)", sirMean);
  return EXIT_SUCCESS;
}
