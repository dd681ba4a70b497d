// The benchmark's Pareto front (bench/rfBenchPareto.h) on points whose front is known: a
// point beaten on both axes, one beaten on one axis and tied on the other, two equal points
// (both kept), points not measured (left out); and the summary's verdict on the default
// setting, dominated on one mesh and on the front on another, with the row of the pass without
// glass (the fastest, error 0) kept out of the front, and a verdict inside the timing's noise
// said to be so; with the rim's PSNR as a third axis, a default dominated on the two axes but
// closer on the rim is on the front, and rows without rim figures are judged on two axes. The plot of those rows (argument: the PNG to write), whose cone has a front
// of one row: drawn as a mark, without VTK's error about a line through one point (ctest fails
// the test on any error output).
#include "rfBenchPareto.h"

#include "rfTestWindow.h"
#include "rf_require.h"

#include <vtksys/SystemTools.hxx>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace
{
rfbench::Row MakeRow(const std::string& mesh, const rfbench::Setting& setting, double ratio,
  double rmse)
{
  rfbench::Row row;
  row.Mesh = mesh;
  row.Size = 512;
  row.Config = setting;
  row.Ratio.Median = ratio;
  row.FullSS.Rmse = rmse;
  row.FullSS.Psnr = -20.0 * std::log10(rmse);
  return row;
}

// DIR 5 with the exit's reflection followed (the pass's default), with or without
// anti-aliasing.
rfbench::Setting Dir(bool antiAliasing)
{
  rfbench::Setting s;
  s.Method = "DIR";
  s.ExitReflection = true;
  s.AntiAliasing = antiAliasing;
  return s;
}

rfbench::Setting Named(const char* method)
{
  rfbench::Setting s;
  s.Method = method;
  return s;
}
}

int main(int argc, char* argv[])
{
  RF_REQUIRE(argc == 2, "usage: TestParetoFront PLOT.png");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<rfbench::CostError> points = {
    { 1.0, 0.3 },  // 0: front
    { 2.0, 0.1 },  // 1: front
    { 2.0, 0.2 },  // 2: same cost as 1, more error
    { 3.0, 0.1 },  // 3: same error as 1, more cost
    { 0.5, 0.5 },  // 4: front, the fastest
    { 2.0, 0.1 },  // 5: equal to 1: front too
    { -1.0, 0.0 }, // 6: not measured
    { 0.1, nan },  // 7: not measured
    { 4.0, 0.4 },  // 8: beaten by 0 and 1 on both
  };
  const std::vector<size_t> front = rfbench::ParetoFront(points);
  const std::vector<size_t> expected = { 4, 0, 1, 5 };
  RF_REQUIRE(front == expected, "front of %zu points, expected 4, 0, 1, 5", front.size());
  RF_REQUIRE(rfbench::ParetoFront({}).empty(), "a front without points");

  RF_REQUIRE(rfbench::IsDefaultSetting(Dir(false)), "DIR 5 exit is the default");
  RF_REQUIRE(!rfbench::IsDefaultSetting(Dir(true)), "DIR 5 AA exit is not the default");
  rfbench::Setting twoInterfaces = Dir(false);
  twoInterfaces.ExitReflection = false;
  RF_REQUIRE(!rfbench::IsDefaultSetting(twoInterfaces), "DIR 5 without exit is not the default");
  rfbench::Setting steps3 = Dir(false);
  steps3.Steps = 3;
  RF_REQUIRE(!rfbench::IsDefaultSetting(steps3), "DIR 3 is not the default");

  std::vector<rfbench::Row> rows = {
    MakeRow("ball", Named("none"), 0.9, 0.0),
    MakeRow("ball", Dir(false), 2.0, 0.1),
    MakeRow("ball", Dir(true), 1.5, 0.05),
    MakeRow("ball", Named("SIR"), 1.0, 0.3),
    MakeRow("ring", Dir(false), 2.0, 0.1),
    MakeRow("ring", Named("PEEL"), 10.0, 0.05),
    MakeRow("cone", Dir(false), 2.0, 0.1),
    MakeRow("cone", Dir(true), 1.8, 0.09),
    MakeRow("disc", Dir(false), 2.0, 0.1),
    MakeRow("disc", Dir(true), 1.5, 0.05),
  };
  rows[6].Ratio.Min = 1.7; // the default's repeats reach below the dominating row's slowest
  rows[7].Ratio.Max = 1.9;
  rows[6].FullSS.PsnrRim = 18.0; // the cone's: DIR 5 AA exit as close on the rim too
  rows[7].FullSS.PsnrRim = 18.0;
  rows[8].FullSS.PsnrRim = 20.0; // the disc's: the default closer on the rim
  rows[9].FullSS.PsnrRim = 16.0;
  const std::string summary = rfbench::ParetoSummary(rows);
  std::printf("%s", summary.c_str());
  RF_REQUIRE(summary.find("| ball | SIR 1.00x / 10.5 dB, DIR 5 AA exit 1.50x / 26.0 dB | dominated by "
                          "DIR 5 AA exit 1.50x / 26.0 dB; with the rim's PSNR as a third axis, "
                          "dominated by DIR 5 AA exit |") != std::string::npos,
    "the ball's line");
  RF_REQUIRE(summary.find("| ring | DIR 5 exit 2.00x / 20.0 dB, PEEL 0 10.00x / 26.0 dB | on the "
                          "front; with the rim's PSNR as a third axis, on the front |") !=
      std::string::npos,
    "the ring's line");
  RF_REQUIRE(summary.find("| cone | DIR 5 AA exit 1.80x / 20.9 dB | dominated by DIR 5 AA exit 1.80x / 20.9 "
                          "dB (the ratios' spreads overlap); with the rim's PSNR as a third "
                          "axis, dominated by DIR 5 AA exit |") != std::string::npos,
    "the cone's line");
  RF_REQUIRE(summary.find("| disc | DIR 5 AA exit 1.50x / 26.0 dB | dominated by DIR 5 AA exit 1.50x / "
                          "26.0 dB; with the rim's PSNR as a third axis, on the front |") !=
      std::string::npos,
    "the disc's line");

  vtksys::SystemTools::RemoveFile(argv[1]);
  vtkSmartPointer<vtkRenderWindow> window = rftest::NewRenderWindow(64, 64);
  RF_REQUIRE(rfbench::WritePareto(window, argv[1], rows), "the plot written");
  RF_REQUIRE(vtksys::SystemTools::FileExists(argv[1], true), "%s exists", argv[1]);
  return EXIT_SUCCESS;
}
