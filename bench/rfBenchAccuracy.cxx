#include "rfBenchAccuracy.h"

#include "rfBenchPareto.h"
#include "rfBenchReport.h"

#include <cstdio>

namespace rfbench
{
namespace
{
// ratio / whole glass / rim / TIR pixels / brightness, against the supersampled full reference.
std::string Figures(const Row& r)
{
  char text[160];
  std::snprintf(text, sizeof(text), "%.2fx / %s / %s / %s / %.3f", r.Ratio.Median,
    Db(r.FullSS.Psnr).c_str(), Db(r.FullSS.PsnrRim).c_str(), Db(r.FullSS.PsnrTir).c_str(),
    r.BrightnessFullSS);
  return text;
}
}

std::string AccuracySummary(const std::vector<Row>& rows)
{
  const int size = SizeNearest512(rows);
  char budget[16];
  std::snprintf(budget, sizeof(budget), "%g", AccuracyBudgetRatio);
  std::string out = "## Accuracy (" + std::to_string(size) + "x" + std::to_string(size) +
    ")\n\nPer mesh, the pass's default setting (`DIR 5 exit`) and, of the settings that cost at most " +
    budget + " times plain VTK (median ratio), the one closest to the supersampled full "
    "reference; each as ratio / PSNR on the glass / on the rim / on TIR pixels (dB, against "
    "`full SS`) / brightness (1: as bright as the truth).\n\n"
    "| mesh | default | closest within " + budget + "x | setting |\n|---|---|---|---|\n";
  for (const std::string& mesh : Meshes(rows))
  {
    const Row* standard = nullptr;
    const Row* closest = nullptr;
    for (const Row& r : rows)
    {
      if (r.Mesh != mesh || r.Size != size || r.Config.Method == "none" || r.Config.NoScene)
        continue;
      if (IsDefaultSetting(r.Config))
        standard = &r;
      if (r.Ratio.Median > 0.0 && r.Ratio.Median <= AccuracyBudgetRatio && r.FullSS.Psnr >= 0.0 &&
        (!closest || r.FullSS.Psnr > closest->FullSS.Psnr))
        closest = &r;
    }
    out += "| " + mesh + " | " + (standard ? Figures(*standard) : std::string("-")) + " | " +
      (closest ? Figures(*closest) : std::string("-")) + " | " +
      (closest ? closest->Config.Label() : std::string("-")) + " |\n";
  }
  return out + "\n";
}
}
