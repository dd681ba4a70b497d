#include "rfBenchReference.h"

#include "rf_metrics.h"
#include "vtkRefractionPass.h"
#include "vtkRefractionReference.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cstdio>
#include <unistd.h>

namespace rfbench
{
namespace
{
std::vector<float> Floats(vtkImageData* image, const char* name, int components)
{
  vtkDataArray* a = image->GetPointData()->GetArray(name);
  std::vector<float> values(a ? components * a->GetNumberOfTuples() : 0);
  for (vtkIdType i = 0; a && i < a->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < components; ++c)
    {
      values[components * i + c] = static_cast<float>(a->GetComponent(i, c));
    }
  }
  return values;
}

// The reference's ProgressEvent shown on one line (every 10 %), ended when the trace is.
struct ProgressLine
{
  std::string Label;
  int Last = -100;
};

void ShowProgress(vtkObject*, unsigned long, void* client, void* call)
{
  auto* line = static_cast<ProgressLine*>(client);
  const double fraction = *static_cast<double*>(call);
  const int percent = static_cast<int>(100.0 * fraction);
  // On a terminal the line is rewritten in place; in a log only its end is written.
  static const bool terminal = isatty(fileno(stdout)) != 0;
  if (fraction < 1.0 && (!terminal || percent < line->Last + 10))
  {
    return;
  }
  line->Last = percent;
  std::printf("\r  reference %-34s %3d %%%s", line->Label.c_str(), percent,
    fraction >= 1.0 ? "\n" : "");
  std::fflush(stdout);
}
}

bool Trace(vtkRenderer* renderer, vtkRefractionPass* pass, int size, int mode, int samples,
  const std::string& label, Reference& out)
{
  vtkNew<vtkRefractionReference> reference;
  reference->SetMode(mode);
  reference->SetEnvironmentMode(pass->GetEnvironmentMode()); // the pass's environment
  reference->SetThreads(2);
  reference->SetSamplesPerSide(samples);
  ProgressLine line{ label };
  vtkNew<vtkCallbackCommand> progress;
  progress->SetCallback(ShowProgress);
  progress->SetClientData(&line);
  reference->AddObserver(vtkCommand::ProgressEvent, progress);
  if (!reference->Trace(renderer, size, size))
  {
    return false;
  }
  vtkImageData* image = reference->GetOutput();
  out.Colour = Floats(image, "Colour", 3);
  for (float& c : out.Colour)
  {
    c = std::min(std::max(c, 0.0f), 1.0f); // what an 8-bit window can show
  }
  out.Coverage = Floats(image, "Coverage", 1);
  out.P2 = Floats(image, "P2", 3);
  out.T2 = Floats(image, "T2", 3);
  const auto hit = Floats(image, "Hit", 1);
  const auto tir = Floats(image, "TIR", 1);
  out.Hit.resize(hit.size());
  out.Tir.resize(tir.size());
  for (size_t i = 0; i < hit.size(); ++i)
  {
    out.Hit[i] = hit[i] > 0.5f ? 1 : 0;
    out.Tir[i] = i < tir.size() && tir[i] > 0.5f ? 1 : 0;
  }
  out.Seconds = reference->GetTraceSeconds();
  out.Diagonal = reference->GetGlassDiagonal();
  return true;
}

namespace
{
// The pixel subsets a picture is measured on.
struct Masks
{
  std::vector<unsigned char> Glass, Tir, Rest, Rim, Edge;
};

Errors Compare(const std::vector<float>& colour, const Reference& reference, const Masks& m,
  int size)
{
  const std::vector<unsigned char>& mask = m.Glass;
  const size_t n = static_cast<size_t>(size) * size;
  Errors e;
  rf_psnr(colour.data(), reference.Colour.data(), n, 3, mask.data(), &e.Psnr);
  rf_rmse(colour.data(), reference.Colour.data(), n, 3, mask.data(), &e.Rmse);
  rf_ssim(colour.data(), reference.Colour.data(), size, size, 3, mask.data(), &e.Ssim);
  // Left at -1 where there are no such pixels.
  rf_psnr(colour.data(), reference.Colour.data(), n, 3, m.Tir.data(), &e.PsnrTir);
  rf_psnr(colour.data(), reference.Colour.data(), n, 3, m.Rest.data(), &e.PsnrRest);
  rf_psnr(colour.data(), reference.Colour.data(), n, 3, m.Rim.data(), &e.PsnrRim);
  if (!m.Edge.empty())
  {
    rf_psnr(colour.data(), reference.Colour.data(), n, 3, m.Edge.data(), &e.PsnrEdge);
  }
  return e;
}

// Mean over the masked pixels and channels.
double MaskedMean(const std::vector<float>& colour, const std::vector<unsigned char>& mask)
{
  double sum = 0.0;
  long count = 0;
  for (size_t i = 0; i < mask.size() && 3 * i + 2 < colour.size(); ++i)
  {
    if (mask[i])
    {
      sum += colour[3 * i] + colour[3 * i + 1] + colour[3 * i + 2];
      count += 3;
    }
  }
  return count ? sum / count : 0.0;
}
}

// Errors on the pixels where both the pass and the reference (its pixel centre) see glass;
// TIR pixels are those where the two-interface reference's ray is totally reflected at the
// exit, rim pixels those the supersampled full reference's sub-samples cover in part. Edge
// pixels: every pixel those sub-samples cover in part, glass at either centre or not.
void Measure(Row& row, const std::vector<float>& colour, const std::vector<float>& pointColour,
  vtkImageData* debug, const Truth& truth, int size)
{
  const size_t n = static_cast<size_t>(size) * size;
  const Reference& two = truth.Two;
  const auto flags = Floats(debug, "Flags", 1);
  const auto t2 = Floats(debug, "T2", 3);
  const auto p2 = Floats(debug, "P2", 3);
  const std::vector<float>& coverage = truth.FullSS.Coverage;
  Masks m;
  std::vector<unsigned char>& mask = m.Glass;
  mask.assign(n, 0);
  m.Tir.assign(n, 0);
  m.Rest.assign(n, 0);
  m.Rim.assign(n, 0);
  if (truth.SolidBackground)
  {
    m.Edge.assign(n, 0);
    for (size_t i = 0; i < n && i < coverage.size(); ++i)
    {
      m.Edge[i] = coverage[i] > 0.0f && coverage[i] < 1.0f ? 1 : 0;
    }
  }
  std::vector<unsigned char> tir(n, 0);
  long count = 0, tirCount = 0;
  for (size_t i = 0; i < n; ++i)
  {
    const bool glass = i < flags.size() && flags[i] > 0.5f;
    mask[i] = glass && two.Hit[i] ? 1 : 0;
    tir[i] = glass && flags[i] > 1.5f ? 1 : 0;
    m.Tir[i] = mask[i] && two.Tir[i] ? 1 : 0;
    m.Rest[i] = mask[i] && !two.Tir[i] ? 1 : 0;
    m.Rim[i] = mask[i] && i < coverage.size() && coverage[i] > 0.0f && coverage[i] < 1.0f;
    count += mask[i];
    tirCount += m.Tir[i];
  }
  row.Pixels = count;
  row.TirPixels = tirCount;
  if (count == 0)
  {
    return;
  }
  row.Two = Compare(pointColour, truth.Two, m, size);
  row.Full = Compare(pointColour, truth.Full, m, size);
  row.TwoSS = Compare(colour, truth.TwoSS, m, size);
  row.FullSS = Compare(colour, truth.FullSS, m, size);
  const double truthMean = MaskedMean(truth.FullSS.Colour, mask);
  row.BrightnessFullSS = truthMean > 0.0 ? MaskedMean(colour, mask) / truthMean : -1.0;
  if (!truth.FullDoubleSS.Colour.empty())
  {
    // On the glass the truth sees, whatever the pass draws: its rim and its TIR pixels too.
    std::vector<unsigned char> truthRim(n, 0);
    std::vector<unsigned char> truthTir(n, 0);
    for (size_t i = 0; i < n; ++i)
    {
      truthRim[i] = two.Hit[i] && i < coverage.size() && coverage[i] > 0.0f && coverage[i] < 1.0f;
      truthTir[i] = two.Hit[i] && two.Tir[i];
    }
    const float* single = truth.FullSS.Colour.data();
    const float* doubled = truth.FullDoubleSS.Colour.data();
    rf_psnr(single, doubled, n, 3, two.Hit.data(), &row.PsnrSSConvergence);
    rf_psnr(single, doubled, n, 3, truthRim.data(), &row.PsnrSSConvergenceRim);
    rf_psnr(single, doubled, n, 3, truthTir.data(), &row.PsnrSSConvergenceTir);
  }
  rf_psnr(truth.TwoSS.Colour.data(), truth.FullSS.Colour.data(), n, 3, mask.data(),
    &row.PsnrModelFullSS);
  row.OneRay = Compare(truth.Full.Colour, truth.FullSS, m, size);
  if (!truth.FullHalfSS.Colour.empty())
  {
    row.FewRays = Compare(truth.FullHalfSS.Colour, truth.FullSS, m, size);
  }
  rf_error_stats angle{};
  if (rf_angular_error(t2.data(), two.T2.data(), n, mask.data(), &angle) == RF_OK)
  {
    row.AngMean = angle.mean;
    row.AngP95 = angle.p95;
    row.AngMax = angle.max;
  }
  rf_error_stats position{};
  if (rf_position_error(p2.data(), two.P2.data(), n, mask.data(), two.Diagonal, &position) ==
    RF_OK)
  {
    row.P2Mean = position.mean;
    row.P2Max = position.max;
  }
  rf_flag_share(tir.data(), n, mask.data(), &row.TirShare);
  rf_flag_share(two.Tir.data(), n, mask.data(), &row.RefTirShare);
}
}
