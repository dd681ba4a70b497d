// Each method allocates exactly the render targets it reads, and the pass's byte count
// (GetTextureBytes, what the benchmark's memory column reports) is what the driver allocated.
// The expected bytes per pixel are written out here from the targets' formats (see
// vtkRefractionTargets.h): front G-buffer RGBA32F + DEPTH32F = 20 and the shaded glass colour
// RGBA16F = 8, which every method writes and the composite reads, and the data's colour RGBA8
// = 4 for the methods that tint (all but SSP) when the glass has a colour (it is light blue
// here; white glass needs none); back capture RGBA32F normal and depth + DEPTH32F
// = 20; ISR's d_N R32F = 4; SSP's scene copy RGBA8 = 4; DIR's
// reduction chain RG32F = 8 per texel of each level, each a quarter of the one before on
// each side (blocks of 4 x 4 texels, rounded up); PEEL's K - 1 peeled layers RGBA32F
// and their DEPTH32F = 16 (K - 1) + 4, the layers' depths packed into RGBA32F, one for
// K <= 4, two above, and all K layers stacked for the shading, RGBA32F = 16 K; anti-aliasing's corner depth buffer DEPTH32F = 4; the debug output
// 2 x RGBA32F. In a multisampled window (VTK's default) the glass colour also has its mipmap
// levels 1 and 2 (each side halved, rounded down), which the composite at the window's samples
// reads at the silhouette; a single-sampled window has none.
#include "vtkRefractionPass.h"

#include "rfTestWindow.h"
#include "rf_require.h"

#include <vtkActor.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkNew.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>

#include <cstdio>

namespace
{
unsigned long long ReductionTexels(int width, int height)
{
  unsigned long long texels = 0;
  do
  {
    width = (width + 3) / 4;
    height = (height + 3) / 4;
    texels += static_cast<unsigned long long>(width) * height;
  } while (width > 1 || height > 1);
  return texels;
}
}

int main()
{
  // A non-power-of-two, non-square window: the reduction chain's rounding is part of the sum.
  const int width = 150;
  const int height = 97;
  const unsigned long long pixels = static_cast<unsigned long long>(width) * height;
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.8, 0.9, 1.0);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkNew<vtkRefractionPass> pass;
  renderer->SetPass(pass);
  RF_REQUIRE(vtkRefractionPass::MakeGlass(actor, 1.5), "MakeGlass refused IOR 1.5");
  vtkSmartPointer<vtkRenderWindow> window = rftest::NewRenderWindow(width, height);
  window->SetSize(width, height);
  window->AddRenderer(renderer);

  struct Case
  {
    int Method;
    int DepthRange;
    bool Debug;
    const char* Name;
    unsigned long long Expected;
    int Layers; // PEEL's K (0: the default, 4)
    bool AntiAliasing;
  };
  const unsigned long long glassMipmaps = window->GetMultiSamples() > 0
    ? 8ULL * ((width / 2) * (height / 2) + (width / 4) * (height / 4))
    : 0;
  const unsigned long long front = 32 * pixels + glassMipmaps;
  const unsigned long long frontUntinted = 28 * pixels + glassMipmaps;
  const unsigned long long back = 20 * pixels;
  const unsigned long long reduction = 8 * ReductionTexels(width, height);
  const Case cases[] = {
    { vtkRefractionPass::SIR, vtkRefractionPass::DEPTH_RANGE_REDUCTION, false, "SIR", front },
    { vtkRefractionPass::DIR, vtkRefractionPass::DEPTH_RANGE_REDUCTION, false, "DIR",
      front + back + reduction },
    { vtkRefractionPass::DIR, vtkRefractionPass::DEPTH_RANGE_BOUNDS, false, "DIR, bounds",
      front + back },
    { vtkRefractionPass::ISR, vtkRefractionPass::DEPTH_RANGE_REDUCTION, false, "ISR",
      front + back + 4 * pixels },
    { vtkRefractionPass::SSP, vtkRefractionPass::DEPTH_RANGE_REDUCTION, false, "SSP",
      frontUntinted + 4 * pixels },
    { vtkRefractionPass::PEEL, vtkRefractionPass::DEPTH_RANGE_REDUCTION, false, "PEEL (K = 4)",
      front + 132 * pixels },
    { vtkRefractionPass::PEEL, vtkRefractionPass::DEPTH_RANGE_REDUCTION, false, "PEEL (K = 8)",
      front + 276 * pixels, 8 },
    { vtkRefractionPass::PEEL, vtkRefractionPass::DEPTH_RANGE_REDUCTION, false, "PEEL (K = 2)",
      front + 68 * pixels, 2 },
    { vtkRefractionPass::DIR, vtkRefractionPass::DEPTH_RANGE_REDUCTION, true, "DIR, debug",
      front + back + reduction + 32 * pixels },
    { vtkRefractionPass::DIR, vtkRefractionPass::DEPTH_RANGE_REDUCTION, false, "DIR, AA",
      front + back + reduction + 4 * pixels, 0, true },
    // Back to the cheapest: what SIR no longer needs is released.
    { vtkRefractionPass::SIR, vtkRefractionPass::DEPTH_RANGE_REDUCTION, false, "SIR again", front },
    { vtkRefractionPass::SIR, vtkRefractionPass::DEPTH_RANGE_REDUCTION, false, "SIR, no tint",
      frontUntinted },
  };
  for (const Case& c : cases)
  {
    pass->SetDataColour(c.Expected != frontUntinted);
    pass->SetMethod(c.Method);
    pass->SetPeelLayers(c.Layers > 0 ? c.Layers : 4);
    pass->SetDepthRangeMode(c.DepthRange);
    pass->SetDebugOutput(c.Debug);
    pass->SetAntiAliasing(c.AntiAliasing);
    window->Render();
    const unsigned long long bytes = pass->GetTextureBytes();
    std::printf("%-12s %10llu bytes (%.2f per pixel), expected %llu\n", c.Name, bytes,
      static_cast<double>(bytes) / pixels, c.Expected);
    RF_REQUIRE(pass->GetNumberOfGlassProps() == 1, "%s: the sphere was not drawn as glass", c.Name);
    RF_REQUIRE(bytes == c.Expected, "%s: %llu bytes allocated, %llu expected", c.Name, bytes,
      c.Expected);
  }
  // SH: the front G-buffer, the exit target (RGBA32F) and the coefficient texture (RGBA32F,
  // rows of 4096 texels, one per coefficient and point); another method releases both. The
  // transfer's arrays are made here (zeros; vtkSHTransferFilter is in another module): the
  // pass only needs their shape to draw.
  {
    sphere->Update();
    vtkNew<vtkPolyData> withTransfer;
    withTransfer->DeepCopy(sphere->GetOutput());
    const vtkIdType points = withTransfer->GetNumberOfPoints();
    vtkNew<vtkFloatArray> transfer;
    transfer->SetName("SHTransfer");
    transfer->SetNumberOfComponents(4 * 9); // order 2
    transfer->SetNumberOfTuples(points);
    transfer->Fill(0.0);
    vtkNew<vtkFloatArray> ids;
    ids->SetName("SHVertexId");
    ids->SetNumberOfTuples(points);
    for (vtkIdType i = 0; i < points; ++i)
    {
      ids->SetValue(i, static_cast<float>(i));
    }
    vtkNew<vtkDoubleArray> settings;
    settings->SetName("SHTransferSettings");
    settings->SetNumberOfValues(4);
    settings->SetValue(0, 2.0);
    settings->SetValue(1, 64.0);
    settings->SetValue(2, 4.0);
    settings->SetValue(3, 1.5);
    withTransfer->GetPointData()->AddArray(transfer);
    withTransfer->GetPointData()->AddArray(ids);
    withTransfer->GetFieldData()->AddArray(settings);
    mapper->SetInputData(withTransfer);
    pass->SetDataColour(true);
    pass->SetDebugOutput(false);
    pass->SetMethod(vtkRefractionPass::SH);
    window->Render();
    const unsigned long long rows = (static_cast<unsigned long long>(points) * 9 + 4095) / 4096;
    const unsigned long long expected = front + 16 * pixels + 16ULL * 4096 * rows;
    std::printf("SH           %10llu bytes, expected %llu\n", pass->GetTextureBytes(), expected);
    RF_REQUIRE(pass->GetTextureBytes() == expected, "SH: %llu bytes, %llu expected",
      pass->GetTextureBytes(), expected);
    pass->SetMethod(vtkRefractionPass::SIR);
    window->Render();
    RF_REQUIRE(pass->GetTextureBytes() == front, "SIR after SH holds %llu bytes, %llu expected",
      pass->GetTextureBytes(), front);
    mapper->SetInputConnection(sphere->GetOutputPort());
  }
  // White glass without scalar colours or edges: no colour target, even with DataColour on.
  actor->GetProperty()->SetColor(1.0, 1.0, 1.0);
  pass->SetDataColour(true);
  pass->SetMethod(vtkRefractionPass::SIR);
  window->Render();
  std::printf("SIR, white   %10llu bytes, expected %llu\n", pass->GetTextureBytes(),
    frontUntinted);
  RF_REQUIRE(pass->GetTextureBytes() == frontUntinted, "white glass allocates a colour target");
  return EXIT_SUCCESS;
}
