#include "rfBenchReport.h"

#include "rfBenchAccuracy.h"
#include "rfBenchPareto.h"
#include "rfBenchTiming.h"
#include "vtkRefractionPass.h"

#include <vtkContextView.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <utility>

namespace rfbench
{
namespace
{
const char* const kRunLinePrefix = "Renderer: ";
}

std::string RunLine(
  const std::string& renderer, const std::string& windowPath, const std::string& run)
{
  return kRunLinePrefix + renderer + " (" + windowPath + "). " + run;
}

std::string ReadRunLine(const std::string& path)
{
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line))
  {
    if (line.rfind(kRunLinePrefix, 0) == 0)
    {
      return line;
    }
  }
  return "";
}

std::string Db(double v)
{
  char text[32];
  std::snprintf(text, sizeof(text), v < 0 ? "-" : "%.1f", v);
  return text;
}

bool WriteMarkdown(
  const std::string& path, const std::vector<Row>& rows, const std::string& runLine)
{
  std::ofstream f(path);
  char line[1024];
  f << "# Error against run time\n\n" << runLine << "\n\n"
    << "How to read it. Every row (a setting on a mesh at a size) was timed together with a "
       "plain VTK render of the same mesh right after it, repeated in one shuffled order; "
       "`ms` and `ratio` (glass frame time over that plain render) are medians over the "
       "repeats with [min-max] beside them; each repeat is itself the median of the timed "
       "frames after 5 warm-up frames. Errors are on glass pixels only (where the pass and "
       "the reference's pixel centre both see glass), against the Embree reference: `two` is "
       "the two-interface reference (the approximation's own error), `full` the Whitted "
       "reference (depth 8, Fresnel splits, TIR), `full SS` the full reference averaged over "
       "N x N rays per pixel (the anti-aliased truth a camera sees); `model vs full SS` is the "
       "two-interface reference, supersampled too, against `full SS` on the same pixels: the "
       "best a two-interface method can read there. `two` and `full` hold one ray per pixel, so "
       "the picture held against them looks the environment up along one direction per ray "
       "(SetFilteredLookups(false)); `full SS` is held against the picture as the row draws "
       "it (`point`: a row drawn so too). `AA`: the pass's anti-aliasing "
       "(vtkRefractionPass::SetAntiAliasing); `coarse`: one ray per 2x2 block where the glass is "
       "smooth (SetCoarseShading); `TIR 2`: two total internal reflections followed "
       "(SetTIRBounces). `TIR` / `rest`: PSNR "
       "against `full SS` on the pixels where the two-interface reference's ray is totally "
       "reflected at the exit, and on the others (`-`: none); `rim`: on the silhouette's glass "
       "pixels (those `full SS` covers only in part, of the glass pixels above); `edge`: on every "
       "pixel `full SS` covers only in part, whatever either centre sees (the whole silhouette, "
       "its background side included; `-` over a gradient background); `brightness`: the mean colour over `full SS`'s "
       "on the glass pixels (1: as bright as the truth). Stage times are the pass's GL "
       "timer queries, over frames of their own after the timed frames (the timed frames run "
       "without them: their queries make llvmpipe finish each stage before the next), stage k = vtkRefractionPass's TIMED_* enumerator k (";
  for (int stage = 0; stage < vtkRefractionPass::TIMED_STAGE_COUNT; ++stage)
  {
    f << (stage ? ", " : "") << stage << " " << vtkRefractionPass::GetStageName(stage);
  }
  f << "); on llvmpipe they include work queued before "
        "the stage; -1 marks a stage the method does not run. `B/px` is "
        "vtkRefractionPass::GetTextureBytes() over the pixels.\n\n";
  // How converged the truth is (--convergence): one figure per mesh and size.
  std::map<std::pair<std::string, int>, const Row*> convergence;
  for (const Row& r : rows)
  {
    if (r.PsnrSSConvergence > 0.0)
      convergence[{ r.Mesh, r.Size }] = &r;
  }
  if (!convergence.empty())
  {
    f << "## The truth's convergence\n\n`full SS` against the full reference traced at twice its "
         "rays per pixel side, on the glass the reference sees, on its rim (the pixels `full "
         "SS` covers in part) and on its TIR pixels (PSNR; 40 dB or more: the figures above "
         "measure the method, not the truth's own noise; a part that reads less bounds what "
         "any method can be shown to reach there).\n\n"
         "| mesh | size | glass | rim | TIR |\n|---|---|---|---|---|\n";
    for (const auto& entry : convergence)
    {
      const Row& r = *entry.second;
      f << "| " << entry.first.first << " | " << entry.first.second << " | "
        << Db(r.PsnrSSConvergence) << " dB | " << Db(r.PsnrSSConvergenceRim) << " | "
        << Db(r.PsnrSSConvergenceTir) << " |\n";
    }
    f << "\n";
  }
  // What sampling once per pixel costs (the full reference at one ray per pixel centre against
  // `full SS`), on the default row's glass pixels: one figure set per mesh and size.
  std::map<std::pair<std::string, int>, const Row*> oneRay;
  for (const Row& r : rows)
  {
    if (r.OneRay.Psnr > 0.0 && IsDefaultSetting(r.Config))
      oneRay[{ r.Mesh, r.Size }] = &r;
  }
  if (!oneRay.empty())
  {
    int few = 0;
    for (const auto& entry : oneRay)
      few = std::max(few, entry.second->FewRaysSide);
    f << "## One ray per pixel, traced exactly\n\nThe full reference at one ray through each "
         "pixel's centre against `full SS`, on the default setting's glass pixels and their "
         "parts (PSNR): what sampling a pixel once costs whatever the refraction does. A "
         "method that samples a pixel once and follows the path exactly reads this; one that "
         "filters or samples more can read better; where a row reads near it, the error left "
         "is sampling, not missing interfaces or bounces.";
    if (few > 0)
    {
      f << " `" << few << "x" << few << "`: the same at " << few << " x " << few
        << " rays per pixel (what following every path exactly at a multisampled window's "
           "few samples a pixel would read; the window's own sample positions differ).";
    }
    f << "\n\n| mesh | size | glass | rim | TIR | rest |"
      << (few > 0 ? " glass (" + std::to_string(few) + "x" + std::to_string(few) + ") | rim (" +
              std::to_string(few) + "x" + std::to_string(few) + ") |"
                  : std::string())
      << "\n|---|---|---|---|---|---|" << (few > 0 ? "---|---|" : "") << "\n";
    for (const auto& entry : oneRay)
    {
      const Errors& e = entry.second->OneRay;
      std::snprintf(line, sizeof(line), "| %s | %d | %s | %s | %s | %s |",
        entry.first.first.c_str(), entry.first.second, Db(e.Psnr).c_str(),
        Db(e.PsnrRim).c_str(), Db(e.PsnrTir).c_str(), Db(e.PsnrRest).c_str());
      f << line;
      if (few > 0)
      {
        const Errors& fewRays = entry.second->FewRays;
        f << " " << Db(fewRays.Psnr) << " | " << Db(fewRays.PsnrRim) << " |";
      }
      f << "\n";
    }
    f << "\n";
  }
  // Table 1 of the paper: fps per model at 512x512 (or the size nearest it).
  std::map<std::string, std::map<std::string, const Row*>> table;
  int tableSize = 0;
  for (const Row& r : rows)
  {
    if (tableSize == 0 || std::abs(r.Size - 512) < std::abs(tableSize - 512))
      tableSize = r.Size;
  }
  f << "## Table 1 analogue (" << tableSize << "x" << tableSize
    << ", fps from the median CPU frame time; RT in seconds, 2 threads)\n\n"
    << "| model | triangles | pixels | DIR | ISR | SIR | SSP | plain VTK | RT (two-interface) | "
       "RT (full) | RT (full, SS) |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Row& r : rows)
  {
    if (r.Size != tableSize || r.Config.Method == "none" || r.Config.NoScene)
      continue;
    // DIR's column is the default setting (the other DIR rows, anti-aliased or following
    // reflections among them, would overwrite it in the order of the rows).
    if (r.Config.Method == "DIR" && !IsDefaultSetting(r.Config))
      continue;
    table[r.Mesh][r.Config.Method] = &r;
  }
  for (auto& entry : table)
  {
    auto fps = [&](const char* m) {
      auto it = entry.second.find(m);
      return it == entry.second.end()
        ? std::string("-")
        : std::to_string(static_cast<int>(1000.0 / it->second->CpuMs.Median + 0.5));
    };
    const Row* any = entry.second.begin()->second;
    std::snprintf(line, sizeof(line),
      "| %s | %lld | %ld | %s | %s | %s | %s | %d | %.2f s | %.2f s | %.2f s |\n",
      entry.first.c_str(), static_cast<long long>(any->Triangles), any->Pixels,
      fps("DIR").c_str(), fps("ISR").c_str(), fps("SIR").c_str(), fps("SSP").c_str(),
      static_cast<int>(1000.0 / any->PlainCpuMs.Median + 0.5), any->RefTwoMs / 1000.0,
      any->RefFullMs / 1000.0, any->RefFullSSMs / 1000.0);
    f << line;
  }
  f << "\n" << AccuracySummary(rows) << ParetoSummary(rows);
  f << "## All rows\n\n| mesh | size | method | ms [min-max] | ratio [min-max] | stage ms | "
       "pre ms | B/px | PSNR two | PSNR full | PSNR full SS | model vs full SS | SSIM full SS | TIR / "
       "rest (full SS) | rim / edge (full SS) | brightness | TIR / rest (two) | T2 deg mean/p95 | TIR "
       "px |\n"
    << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Row& r : rows)
  {
    std::string stages;
    for (size_t s = 0; s < r.StageMs.size(); ++s)
    {
      char stage[32];
      std::snprintf(stage, sizeof(stage), "%s%.2f", s ? "/" : "", r.StageMs[s]);
      stages += stage;
    }
    std::snprintf(line, sizeof(line),
      "| %s | %d | %s | %.2f [%.2f-%.2f] | %.2f [%.2f-%.2f] | %s | %.1f | %.0f | %s | %s | %s | "
      "%s | %.3f | %s / %s | %s / %s | %.3f | %s / %s | %.2f/%.2f | %ld |\n",
      r.Mesh.c_str(), r.Size, r.Config.Label().c_str(), r.CpuMs.Median, r.CpuMs.Min,
      r.CpuMs.Max, r.Ratio.Median, r.Ratio.Min, r.Ratio.Max, stages.c_str(), r.PrecomputeMs,
      r.BytesPerPixel, Db(r.Two.Psnr).c_str(), Db(r.Full.Psnr).c_str(),
      Db(r.FullSS.Psnr).c_str(), Db(r.PsnrModelFullSS).c_str(), r.FullSS.Ssim,
      Db(r.FullSS.PsnrTir).c_str(), Db(r.FullSS.PsnrRest).c_str(), Db(r.FullSS.PsnrRim).c_str(),
      Db(r.FullSS.PsnrEdge).c_str(), r.BrightnessFullSS, Db(r.Two.PsnrTir).c_str(), Db(r.Two.PsnrRest).c_str(), r.AngMean,
      r.AngP95, r.TirPixels);
    f << line;
  }
  // The noise that remains: the same plain render timed in every job of a mesh and size.
  f << "\n## Noise\n\nThe plain render does the same work in every job of a mesh and size, so "
       "its spread over the run is the machine's noise; a glass row's ratio spread over its "
       "repeats is what a single ratio may be off by.\n\n"
       "| mesh | size | plain ms median [min-max] over rows | widest ratio spread (max/min) |\n"
       "|---|---|---|---|\n";
  std::map<std::pair<std::string, int>, std::vector<const Row*>> groups;
  for (const Row& r : rows)
    groups[{ r.Mesh, r.Size }].push_back(&r);
  for (const auto& g : groups)
  {
    std::vector<double> plain;
    double lo = 1e300, hi = 0, widest = 1.0;
    for (const Row* r : g.second)
    {
      plain.push_back(r->PlainCpuMs.Median);
      lo = std::min(lo, r->PlainCpuMs.Min);
      hi = std::max(hi, r->PlainCpuMs.Max);
      if (r->Ratio.Min > 0)
        widest = std::max(widest, r->Ratio.Max / r->Ratio.Min);
    }
    std::snprintf(line, sizeof(line), "| %s | %d | %.2f [%.2f-%.2f] | %.2f |\n",
      g.first.first.c_str(), g.first.second, Median(plain), lo, hi, widest);
    f << line;
  }
  f.flush();
  return static_cast<bool>(f);
}

void ShowChartView(vtkRenderWindow* window, vtkContextView* view)
{
  while (window->GetRenderers()->GetFirstRenderer())
  {
    window->RemoveRenderer(window->GetRenderers()->GetFirstRenderer());
  }
  view->SetRenderWindow(window);
}

bool WriteChartPng(vtkRenderWindow* window, vtkContextView* view, const std::string& path)
{
  view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName(path.c_str());
  writer->Write();
  return writer->GetErrorCode() == 0;
}
}
