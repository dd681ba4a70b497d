// What the tests that hold the pass against the reference tracer share (layers, sh): a glass
// scene over the built-in environment and a black background, seen from (0, 0, 8) toward the
// origin with a 30-degree view angle; the reference traced of it as it stands; PSNR of a
// picture against a reference's colours on a mask of pixels; the glass cube of the total
// internal reflection tests and its totally reflected pixels. Header-only: the reference
// library is linked by the tests that include it.
#ifndef rfReferenceScene_h
#define rfReferenceScene_h

#include "rfTestScene.h"
#include "rf_metrics.h"
#include "vtkRefractionPass.h"
#include "vtkRefractionReference.h"

#include <vtkAlgorithm.h>
#include <vtkCamera.h>
#include <vtkCubeSource.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
#include <vector>

namespace rftest
{
struct ReferenceScene
{
  int Size = 160;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRefractionPass> Pass;
  vtkSmartPointer<vtkRenderWindow> Window;

  explicit ReferenceScene(int size = 160)
    : Size(size)
  {
    this->Renderer->SetPass(this->Pass);
    this->Pass->SetEnvironmentModeToBuiltin();
    // The pictures are held against the reference's one ray per pixel (Trace's default), so
    // the pass too looks the environment up along one direction per pixel; a test against a
    // supersampled reference turns the filtered lookups (the pass's default) back on.
    this->Pass->FilteredLookupsOff();
    this->Renderer->SetBackground(0.0, 0.0, 0.0);
    this->Window = MakeWindow(this->Renderer, size, size);
  }
  void Look()
  {
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(0.0, 0.0, 8.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetViewAngle(30.0);
    this->Renderer->ResetCameraClippingRange();
  }
  vtkSmartPointer<vtkImageData> Render()
  {
    this->Look();
    this->Window->Render();
    return Grab(this->Window);
  }
  /// The reference's picture of the scene as it stands (mode: vtkRefractionReference's),
  /// averaged over samplesPerSide x samplesPerSide rays per pixel.
  vtkSmartPointer<vtkImageData> Trace(int mode, int samplesPerSide = 1)
  {
    this->Look();
    vtkNew<vtkRefractionReference> reference;
    reference->SetMode(mode);
    reference->SetSamplesPerSide(samplesPerSide);
    reference->SetEnvironmentMode(this->Pass->GetEnvironmentMode());
    if (!reference->Trace(this->Renderer, this->Size, this->Size))
    {
      return nullptr;
    }
    auto output = vtkSmartPointer<vtkImageData>::New();
    output->DeepCopy(reference->GetOutput());
    return output;
  }
};

/// The pixels set in a mask.
inline size_t Count(const std::vector<unsigned char>& mask)
{
  size_t n = 0;
  for (unsigned char m : mask)
  {
    n += m;
  }
  return n;
}

/// The glass of the total-internal-reflection tests: a cube of side 1.4, triangulated. Turned
/// by RotateX(35) and RotateY(40) and of index 1.6, about 3100 of its pixels at 160 x 160
/// reflect totally at the exit.
inline vtkSmartPointer<vtkAlgorithm> TIRCube()
{
  vtkNew<vtkCubeSource> cube;
  cube->SetXLength(1.4);
  cube->SetYLength(1.4);
  cube->SetZLength(1.4);
  auto triangles = vtkSmartPointer<vtkTriangleFilter>::New();
  triangles->SetInputConnection(cube->GetOutputPort());
  return triangles;
}

/// The pixels whose two-interface reference ray meets the glass and is totally reflected at
/// its exit (the reference's "Hit" and "TIR" arrays); empty when the arrays are missing.
inline std::vector<unsigned char> TotallyReflected(vtkImageData* twoInterface)
{
  vtkDataArray* tir = twoInterface ? twoInterface->GetPointData()->GetArray("TIR") : nullptr;
  vtkDataArray* hit = twoInterface ? twoInterface->GetPointData()->GetArray("Hit") : nullptr;
  if (!tir || !hit)
  {
    return {};
  }
  std::vector<unsigned char> reflected(static_cast<size_t>(tir->GetNumberOfTuples()));
  for (size_t i = 0; i < reflected.size(); ++i)
  {
    reflected[i] = hit->GetComponent(static_cast<vtkIdType>(i), 0) > 0.5 &&
      tir->GetComponent(static_cast<vtkIdType>(i), 0) > 0.5;
  }
  return reflected;
}

/// PSNR of a picture of the pass against a reference's colours (clamped to [0, 1], what an
/// 8-bit window shows) on the pixels of `mask`; -1 where it cannot be measured.
inline double PSNROnMask(
  vtkImageData* picture, vtkImageData* reference, const std::vector<unsigned char>& mask)
{
  vtkDataArray* colour = reference ? reference->GetPointData()->GetArray("Colour") : nullptr;
  if (!colour)
  {
    return -1.0;
  }
  std::vector<float> truth(3 * mask.size());
  for (size_t i = 0; i < mask.size(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      truth[3 * i + c] = static_cast<float>(
        std::min(1.0, std::max(0.0, colour->GetComponent(static_cast<vtkIdType>(i), c))));
    }
  }
  const std::vector<float> measured = ToColour(picture);
  double psnr = -1.0;
  return rf_psnr(measured.data(), truth.data(), mask.size(), 3, mask.data(), &psnr) == RF_OK
    ? psnr
    : -1.0;
}

/// The pixels (index y * width + x) the reference sees glass in, with all eight neighbours
/// glass too: away from the silhouette, which a multisampled window blends with the background
/// where the reference's pixel centre sees glass alone.
inline std::vector<vtkIdType> InteriorHitPixels(vtkImageData* reference)
{
  vtkDataArray* hit = reference->GetPointData()->GetArray("Hit");
  int dims[3];
  reference->GetDimensions(dims);
  const int width = dims[0];
  const int height = dims[1];
  auto isHit = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < width && y < height &&
      hit->GetComponent(static_cast<vtkIdType>(y) * width + x, 0) > 0.5;
  };
  std::vector<vtkIdType> pixels;
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      bool inside = true;
      for (int k = 0; k < 9; ++k)
      {
        inside = inside && isHit(x + k % 3 - 1, y + k / 3 - 1);
      }
      if (inside)
      {
        pixels.push_back(static_cast<vtkIdType>(y) * width + x);
      }
    }
  }
  return pixels;
}
}

#endif