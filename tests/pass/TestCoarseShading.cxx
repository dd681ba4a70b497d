// Coarse shading (vtkRefractionPass::SetCoarseShading): one ray per 2x2 block where the glass
// is smooth, each pixel's own elsewhere. In VTK's default (multisampled) window, at a size with
// an odd width and height, two glass actors of different indices overlapping (a material edge
// and a depth jump inside the picture), every frame without a message or an OpenGL error:
// - the coarse picture is not the full one (the blocks' rays were used: with the resolve's
//   program broken, every pixel traced, this test fails here) and is close to it on the
//   glass: 36.8 dB when this was written (27.4 before the resolve's contrast test), 25
//   required;
// - the pixels the blocks cannot stand for are traced: at the silhouettes and along the edge
//   between the two actors the coarse picture is close to the full one too (34.0 dB when
//   written; 16.5 dB with every pixel interpolated, which this test then fails);
// - with the data's colour, dispersion and the smoothing of internal reflections the coarse
//   picture stays close to the full one with the same settings;
// - SIR, SSP and PEEL (the methods without a precomputation) the same;
// - with anti-aliasing it is the anti-aliased picture exactly (anti-aliasing wins).
#include "vtkRefractionPass.h"

#include "rfTestRig.h"
#include "rfTestScene.h"

#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <utility>

namespace
{
struct Comparison
{
  double Psnr = 0.0;         // coarse against full, on the glass pixels
  double EdgePsnr = 0.0;     // on the glass pixels next to another material or no glass
  int GlassPixels = 0;
  int EdgePixels = 0;
  int DifferingPixels = 0;   // glass pixels differing by more than 2 of 255
};

double Psnr(double squaredSum, int count)
{
  return count > 0 && squaredSum > 0.0 ? 10.0 * std::log10(count / squaredSum) : 99.0;
}

// Glass: pixels where the glass differs from the background; edge: glass pixels with a
// neighbour (of 8) that is background or whose label (which actor covers it) differs.
Comparison Compare(vtkImageData* full, vtkImageData* coarse, vtkImageData* background,
  vtkImageData* labels)
{
  Comparison c;
  const int* dims = full->GetDimensions();
  auto glassAt = [&](int x, int y) {
    return rftest::PixelDiffers(full, background, x, y, 2.0);
  };
  auto label = [&](int x, int y) { return labels->GetScalarComponentAsDouble(x, y, 0, 0); };
  double sum = 0.0;
  double edgeSum = 0.0;
  for (int y = 1; y + 1 < dims[1]; ++y)
  {
    for (int x = 1; x + 1 < dims[0]; ++x)
    {
      if (!glassAt(x, y))
      {
        continue;
      }
      bool edge = false;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          edge = edge || !glassAt(x + dx, y + dy) || label(x + dx, y + dy) != label(x, y);
      double squared = 0.0;
      bool differs = false;
      for (int k = 0; k < 3; ++k)
      {
        const double d = (full->GetScalarComponentAsDouble(x, y, 0, k) -
                           coarse->GetScalarComponentAsDouble(x, y, 0, k)) /
          255.0;
        squared += d * d / 3.0;
        differs = differs || std::fabs(d) > 2.0 / 255.0;
      }
      sum += squared;
      ++c.GlassPixels;
      c.DifferingPixels += differs ? 1 : 0;
      if (edge)
      {
        edgeSum += squared;
        ++c.EdgePixels;
      }
    }
  }
  c.Psnr = Psnr(sum, c.GlassPixels);
  c.EdgePsnr = Psnr(edgeSum, c.EdgePixels);
  return c;
}
}

int main()
{
  rftest::MessageLog* log = rftest::InstallLog();
  const int width = 211;
  const int height = 157;
  vtkSmartPointer<vtkActor> left = rftest::MakeSphere(0.55, 64);
  vtkSmartPointer<vtkActor> right = rftest::MakeSphere(0.45, 64);
  left->SetPosition(-0.3, 0.0, 0.0);
  right->SetPosition(0.35, 0.05, 0.3);
  RF_REQUIRE(vtkRefractionPass::MakeGlass(left, 1.5), "MakeGlass refused IOR 1.5");
  RF_REQUIRE(vtkRefractionPass::MakeGlass(right, 1.33), "MakeGlass refused IOR 1.33");
  rftest::WithoutHighlights(left);
  rftest::WithoutHighlights(right);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(left);
  renderer->AddActor(right);
  renderer->SetBackground(0.1, 0.1, 0.12);
  vtkSmartPointer<vtkRenderWindow> window = rftest::MakeWindow(renderer, width, height);
  rftest::LookAtOrigin(renderer, 3.2, 10.0);

  // Which actor covers each pixel: plain VTK, the two actors flat red and flat green.
  for (vtkActor* actor : { left.Get(), right.Get() })
  {
    actor->GetProperty()->SetLighting(false);
  }
  left->GetProperty()->SetColor(1.0, 0.0, 0.0);
  right->GetProperty()->SetColor(0.0, 1.0, 0.0);
  window->Render();
  vtkSmartPointer<vtkImageData> labels = rftest::Grab(window);
  for (vtkActor* actor : { left.Get(), right.Get() })
  {
    actor->GetProperty()->SetLighting(true);
    actor->GetProperty()->SetColor(1.0, 1.0, 1.0);
  }

  vtkNew<vtkRefractionPass> pass;
  pass->SetEnvironmentModeToBuiltin();
  renderer->SetPass(pass);
  left->SetVisibility(false);
  right->SetVisibility(false);
  window->Render();
  vtkSmartPointer<vtkImageData> background = rftest::Grab(window);
  left->SetVisibility(true);
  right->SetVisibility(true);

  auto render = [&](bool coarse) {
    pass->SetCoarseShading(coarse);
    window->Render();
    window->Render(); // a second frame: nothing may be left from the first
    return rftest::Grab(window);
  };
  struct Case
  {
    const char* Name;
    std::function<void(bool)> Set; // on, or back to the default
    double MinPsnr;
  };
  const Case cases[] = {
    { "default", [](bool) {}, 25.0 },
    { "data colour",
      [&](bool on) {
        left->GetProperty()->SetColor(1.0, on ? 0.6 : 1.0, on ? 0.3 : 1.0);
      },
      25.0 },
    { "dispersion",
      [&](bool on) {
        if (on)
        {
          vtkRefractionPass::SetDispersion(left, 1.47, 1.5, 1.55);
        }
        else
        {
          vtkRefractionPass::ClearDispersion(left);
        }
      },
      25.0 },
    { "smooth internal reflections",
      [&](bool on) { pass->SetSmoothInternalReflections(on); }, 25.0 },
  };
  for (const Case& c : cases)
  {
    c.Set(true);
    vtkSmartPointer<vtkImageData> full = render(false);
    vtkSmartPointer<vtkImageData> coarse = render(true);
    c.Set(false);
    const Comparison result = Compare(full, coarse, background, labels);
    std::printf("%s: %d glass pixels, %d differ by more than 2 of 255; coarse against full "
                "%.1f dB on the glass, %.1f dB on its %d edge pixels\n",
      c.Name, result.GlassPixels, result.DifferingPixels, result.Psnr, result.EdgePsnr,
      result.EdgePixels);
    RF_REQUIRE(result.GlassPixels > width * height / 5, "%s: only %d glass pixels", c.Name,
      result.GlassPixels);
    RF_REQUIRE(result.DifferingPixels > result.GlassPixels / 100,
      "%s: the coarse picture is the full one (%d pixels differ): no block's ray was used",
      c.Name, result.DifferingPixels);
    RF_REQUIRE(result.Psnr >= c.MinPsnr, "%s: coarse against full %.1f dB < %.1f", c.Name,
      result.Psnr, c.MinPsnr);
    RF_REQUIRE(result.EdgePsnr >= c.MinPsnr,
      "%s: on the edges coarse against full %.1f dB < %.1f: pixels the blocks cannot stand "
      "for were not traced",
      c.Name, result.EdgePsnr, c.MinPsnr);
  }

  // The other methods whose shading needs no precomputation run the same stage.
  const std::pair<int, const char*> methods[] = { { vtkRefractionPass::SIR, "SIR" },
    { vtkRefractionPass::SSP, "SSP" }, { vtkRefractionPass::PEEL, "PEEL" } };
  for (const auto& method : methods)
  {
    pass->SetMethod(method.first);
    vtkSmartPointer<vtkImageData> full = render(false);
    vtkSmartPointer<vtkImageData> coarse = render(true);
    const Comparison result = Compare(full, coarse, background, labels);
    std::printf("%s: %d of %d glass pixels differ; coarse against full %.1f dB on the "
                "glass, %.1f dB on the edges\n",
      method.second, result.DifferingPixels, result.GlassPixels, result.Psnr, result.EdgePsnr);
    RF_REQUIRE(result.DifferingPixels > result.GlassPixels / 100 && result.Psnr >= 25.0 &&
        result.EdgePsnr >= 25.0,
      "%s: coarse against full %.1f dB, edges %.1f dB, %d pixels differ", method.second,
      result.Psnr, result.EdgePsnr, result.DifferingPixels);
  }
  pass->SetMethod(vtkRefractionPass::DIR);

  pass->SetAntiAliasing(true);
  vtkSmartPointer<vtkImageData> antiAliased = render(false);
  vtkSmartPointer<vtkImageData> both = render(true);
  const int differing = rftest::DifferingPixels(antiAliased, both, 0);
  std::printf("anti-aliasing with coarse shading: %d pixels differ from anti-aliasing alone\n",
    differing);
  RF_REQUIRE(differing == 0, "anti-aliasing with coarse shading: %d pixels differ", differing);

  const int messages = log->Count("error") + log->Count("warning");
  RF_REQUIRE(messages == 0, "%d errors or warnings", messages);
  return EXIT_SUCCESS;
}
