// The SH method (vtkRefractionPass::SH, Genevaux et al.): glass whose exit directions were
// precomputed per vertex (vtkSHTransferFilter). Cases:
//   sphere_exit  a glass ball (IOR 1.5) seen head-on: the exit direction T2 along the image's
//                diameter (the debug output) against the closed form of a ray through a
//                sphere, and against the full reference's picture (PSNR), beside DIR
//   cube_tir     a glass cube of index 1.6 turned so that many rays are totally reflected:
//                SH follows them in its precomputation; against the full reference on the
//                totally reflected pixels it must beat DIR with the paper's clamp
//   stale        the ball's points moved after the precomputation: the pass says so and
//                draws DIR (the same picture as DIR), and a mesh without a transfer likewise
//   regression   the ball as a VTK regression image (-V baseline -T folder)
#include "vtkRefractionPass.h"
#include "vtkRefractionReference.h"
#include "vtkSHTransferFilter.h"
#include "rf_metrics.h"

#include "rfReferenceScene.h"
#include "rfTestBaseline.h"
#include "rfTestRig.h"
#include "rfTestScene.h"
#include "rf_require.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkLinearSubdivisionFilter.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
const int kSize = 160;

using Scene = rftest::ReferenceScene;

// The glass mesh through the precomputation, as an actor.
vtkSmartPointer<vtkActor> SHActor(vtkAlgorithmOutput* port, double ior, int order)
{
  vtkNew<vtkSHTransferFilter> transfer;
  transfer->SetInputConnection(port);
  transfer->SetIndexOfRefraction(ior);
  transfer->SetOrder(order);
  transfer->SetDirections(512);
  transfer->SetCacheDirectory("");
  transfer->Update();
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->DeepCopy(transfer->GetOutput());
  auto actor = rftest::ActorFor(poly);
  vtkRefractionPass::MakeGlass(actor, ior);
  std::printf("precomputed %lld points at order %d in %.2f s\n",
    static_cast<long long>(poly->GetNumberOfPoints()), order, transfer->GetLastComputeSeconds());
  return actor;
}

vtkSmartPointer<vtkAlgorithm> Ball()
{
  auto sphere = vtkSmartPointer<vtkSphereSource>::New();
  sphere->SetRadius(1.0);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(24);
  return sphere;
}

int SphereExit(int argc, char* argv[], bool regression)
{
  Scene scene;
  auto ball = Ball();
  auto actor = SHActor(ball->GetOutputPort(), 1.5, 8);
  scene.Renderer->AddActor(actor);
  scene.Pass->SetMethod(vtkRefractionPass::SH);
  vtkNew<rftest::MessageLog> log;
  vtkOutputWindow::SetInstance(log);
  auto sh = scene.Render();
  vtkOutputWindow::SetInstance(nullptr);
  RF_REQUIRE(log->Count("warning") == 0 && log->Count("error") == 0,
    "the pass reported messages on a fitting transfer");
  if (regression)
  {
    return rftest::CompareWithBaseline(argc, argv, scene.Window, 0.15);
  }
  scene.Pass->DebugOutputOn();
  scene.Render();
  vtkImageData* debug = scene.Pass->GetDebugImage();
  vtkDataArray* t2 = debug->GetPointData()->GetArray("T2");
  vtkDataArray* p1Flags = debug->GetPointData()->GetArray("Flags");
  scene.Pass->DebugOutputOff();
  // Along the row through the centre: the closed form of the ball's exit direction.
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  double worst = 0.0;
  double sum = 0.0;
  int samples = 0;
  const double tanHalf = std::tan(0.5 * camera->GetViewAngle() * 3.14159265358979 / 180.0);
  for (int x = 0; x < kSize; ++x)
  {
    const vtkIdType i = static_cast<vtkIdType>(kSize / 2) * kSize + x;
    if (!(p1Flags->GetComponent(i, 0) > 0.5))
    {
      continue;
    }
    // The view ray through the pixel centre, the ball of radius 1 at distance 8.
    const double ndc = (x + 0.5) / kSize * 2.0 - 1.0;
    double V[3] = { ndc * tanHalf, ((kSize / 2) + 0.5) / kSize * 2.0 - 1.0, -1.0 };
    V[1] *= tanHalf;
    vtkMath::Normalize(V);
    const double O[3] = { 0.0, 0.0, 8.0 };
    const double b = vtkMath::Dot(O, V);
    const double c = vtkMath::Dot(O, O) - 1.0;
    if (b * b - c <= 0.0)
    {
      continue;
    }
    const double t = -b - std::sqrt(b * b - c);
    double P[3] = { O[0] + t * V[0], O[1] + t * V[1], O[2] + t * V[2] };
    const double impact = std::sqrt(1.0 - std::pow(vtkMath::Dot(P, V), 2.0));
    if (impact > 0.9)
    {
      continue;
    }
    // Refract in and out with Snell's law (view space = world space translated: the camera
    // looks down -z from +8, so directions agree).
    auto refract = [](const double I[3], const double N[3], double eta, double T[3]) {
      const double cosi = -vtkMath::Dot(I, N);
      const double k = 1.0 - eta * eta * (1.0 - cosi * cosi);
      for (int a = 0; a < 3; ++a)
      {
        T[a] = eta * I[a] + (eta * cosi - std::sqrt(k)) * N[a];
      }
    };
    double T1[3];
    refract(V, P, 1.0 / 1.5, T1);
    const double chord = -2.0 * vtkMath::Dot(P, T1);
    const double P2[3] = { P[0] + chord * T1[0], P[1] + chord * T1[1], P[2] + chord * T1[2] };
    const double inward[3] = { -P2[0], -P2[1], -P2[2] };
    double T2[3];
    refract(T1, inward, 1.5, T2);
    double measured[3] = { t2->GetComponent(i, 0), t2->GetComponent(i, 1), t2->GetComponent(i, 2) };
    vtkMath::Normalize(measured);
    const double angle =
      std::acos(std::min(1.0, std::max(-1.0, vtkMath::Dot(measured, T2)))) * 180.0 / 3.14159265358979;
    worst = std::max(worst, angle);
    sum += angle;
    ++samples;
  }
  RF_REQUIRE(samples > 40, "too few pixels on the diameter: %d", samples);
  auto full = scene.Trace(vtkRefractionReference::FULL);
  RF_REQUIRE(full, "the reference failed");
  vtkDataArray* hit = full->GetPointData()->GetArray("Hit");
  std::vector<unsigned char> glass(static_cast<size_t>(kSize) * kSize);
  for (size_t i = 0; i < glass.size(); ++i)
  {
    glass[i] = hit->GetComponent(static_cast<vtkIdType>(i), 0) > 0.5;
  }
  scene.Pass->SetMethod(vtkRefractionPass::DIR);
  auto dir = scene.Render();
  const double psnrSH = rftest::PSNROnMask(sh, full, glass);
  const double psnrDIR = rftest::PSNROnMask(dir, full, glass);
  std::printf("sphere_exit: %d pixels of the diameter (impact < 0.9): exit direction against the "
              "closed form mean %.3f, largest %.3f deg; PSNR against the full reference: SH %.2f "
              "dB, DIR %.2f dB\n",
    samples, sum / samples, worst, psnrSH, psnrDIR);
  // Measured on llvmpipe (order 8, 512 directions, a 48 x 24 ball, SHSmoothing 5): mean 0.94,
  // largest 2.55 degrees (unsmoothed 2.20 and 5.55; the C test of the projection reads 1.09
  // and 2.34); SH 18.78 dB (unsmoothed 17.79), DIR 27.15 dB. On
  // a ball the two interfaces DIR searches are all there is, and SH's per-vertex functions,
  // interpolated across triangles, are the coarser picture.
  RF_REQUIRE(sum / samples < 1.5, "mean exit error %.3f deg", sum / samples);
  RF_REQUIRE(psnrSH > 15.0, "SH is %.2f dB from the reference", psnrSH);
  return EXIT_SUCCESS;
}

int CubeTIR()
{
  Scene scene;
  // Per-vertex functions need vertices across the faces, not only at the corners.
  vtkNew<vtkLinearSubdivisionFilter> finer;
  finer->SetInputConnection(rftest::TIRCube()->GetOutputPort());
  finer->SetNumberOfSubdivisions(4);
  auto actor = SHActor(finer->GetOutputPort(), 1.6, 8);
  actor->RotateX(35.0);
  actor->RotateY(40.0);
  scene.Renderer->AddActor(actor);
  scene.Pass->SetMethod(vtkRefractionPass::SH);
  // Unsmoothed: the weights' filter blurs the jumps a cube's exits make (13.43 dB with it).
  scene.Pass->SetSHSmoothing(0.0);
  auto sh = scene.Render();
  scene.Pass->SetMethod(vtkRefractionPass::DIR);
  auto clamped = scene.Render();
  scene.Pass->SetTIRBounces(2);
  auto followed = scene.Render();
  auto two = scene.Trace(vtkRefractionReference::TWO_INTERFACE);
  auto full = scene.Trace(vtkRefractionReference::FULL);
  RF_REQUIRE(two && full, "the reference failed");
  const std::vector<unsigned char> reflected = rftest::TotallyReflected(two);
  RF_REQUIRE(!reflected.empty(), "missing reference arrays");
  const size_t count = rftest::Count(reflected);
  const double psnrSH = rftest::PSNROnMask(sh, full, reflected);
  const double psnrClamp = rftest::PSNROnMask(clamped, full, reflected);
  const double psnrFollowed = rftest::PSNROnMask(followed, full, reflected);
  std::printf("cube_tir: %zu totally reflected pixels; PSNR against the full reference: SH %.2f "
              "dB, DIR with the clamp %.2f dB, DIR with two reflections followed %.2f dB\n",
    count, psnrSH, psnrClamp, psnrFollowed);
  // Measured on llvmpipe (order 8, 512 directions, the cube's faces cut into 256 triangles
  // each): SH 13.68 dB, the clamp 12.80, two reflections followed 21.67. SH follows the
  // reflections in its precomputation but at a vertex the exit direction jumps where the path
  // changes the face it leaves by, which order 8 smears (the paper's own weakness at sharp
  // features): it gains a little over the clamp and stays well below DIR that follows them.
  RF_REQUIRE(count > 1000, "too few totally reflected pixels: %zu", count);
  RF_REQUIRE(psnrSH > psnrClamp + 0.5, "SH gains %.2f dB over the clamp", psnrSH - psnrClamp);
  return EXIT_SUCCESS;
}

int Stale()
{
  Scene scene;
  auto ball = Ball();
  auto actor = SHActor(ball->GetOutputPort(), 1.5, 4);
  scene.Renderer->AddActor(actor);
  scene.Pass->SetMethod(vtkRefractionPass::DIR);
  auto dir = scene.Render();
  vtkNew<rftest::MessageLog> log;
  vtkOutputWindow::SetInstance(log);
  scene.Pass->SetMethod(vtkRefractionPass::SH);
  auto fitting = scene.Render();
  const int warningsFitting = log->Count("warning");
  // Move the points in place: the transfer no longer belongs to them.
  vtkPolyData* poly = vtkPolyData::SafeDownCast(actor->GetMapper()->GetInputDataObject(0, 0));
  vtkPoints* points = poly->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    points->SetPoint(i, p[0], p[1], 1.02 * p[2]);
  }
  points->Modified();
  poly->Modified();
  auto stale = scene.Render();
  const int warningsStale = log->Count("warning", { "stale" });
  scene.Render(); // said once, not every frame
  const int warningsAgain = log->Count("warning", { "stale" });
  // A mesh without a transfer.
  scene.Renderer->RemoveActor(actor);
  auto plain = rftest::MakeSphere(1.0, 48);
  vtkRefractionPass::MakeGlass(plain, 1.5);
  scene.Renderer->AddActor(plain);
  scene.Render();
  const int warningsMissing = log->Count("warning", { "no SH transfer" });
  vtkOutputWindow::SetInstance(nullptr);
  scene.Pass->SetMethod(vtkRefractionPass::DIR);
  scene.Renderer->RemoveActor(plain);
  scene.Renderer->AddActor(actor);
  auto dirStale = scene.Render();
  const int differs = rftest::MaxChannelDifference(stale, dirStale);
  std::printf("stale: warnings with a fitting transfer %d, stale %d (after another frame %d), "
              "missing %d; the stale frame against DIR's: largest difference %d; the fitting "
              "SH frame differs from DIR's by up to %d\n",
    warningsFitting, warningsStale, warningsAgain, warningsMissing, differs,
    rftest::MaxChannelDifference(fitting, dir));
  RF_REQUIRE(warningsFitting == 0, "warnings on a fitting transfer");
  RF_REQUIRE(warningsStale == 1 && warningsAgain == 1, "the stale transfer is not said once");
  RF_REQUIRE(warningsMissing == 1, "the missing transfer is not said");
  RF_REQUIRE(differs == 0, "the stale frame is not DIR's (difference %d)", differs);
  RF_REQUIRE(rftest::MaxChannelDifference(fitting, dir) > 10, "SH draws DIR's picture");
  return EXIT_SUCCESS;
}
}

int main(int argc, char* argv[])
{
  const std::string name = argc > 1 ? argv[1] : "";
  if (name == "sphere_exit")
  {
    return SphereExit(argc, argv, false);
  }
  if (name == "regression")
  {
    return SphereExit(argc, argv, true);
  }
  if (name == "stale")
  {
    return Stale();
  }
  if (name == "cube_tir")
  {
    return CubeTIR();
  }
  std::fprintf(stderr, "usage: TestGlassSH sphere_exit|cube_tir|stale|regression [-V baseline -T dir]\n");
  return EXIT_FAILURE;
}
