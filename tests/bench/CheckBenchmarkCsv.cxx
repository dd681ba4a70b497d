// Checks a benchmark CSV: every figure finite, and DIR's PSNR against the two-interface
// reference on the sphere above a measured threshold; every row timed at least 3 times with
// its median inside its min/max; the supersampled reference in its own columns, and DIR's
// error against it larger than against the one-sample reference (both share the aliasing
// that the supersampled truth does not have); on the silhouette's pixels (rim) DIR's error
// larger than over the whole glass, and the glass as bright as the truth within 3%. With
// `convergence` (a run with --convergence): the truth's convergence on every measured row, its
// rim's below its whole glass's.
//   CheckBenchmarkCsv results.csv MIN_DIR_SPHERE_PSNR [convergence]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
std::vector<std::string> Fields(const std::string& line)
{
  std::vector<std::string> fields;
  std::string field;
  bool quoted = false;
  for (char c : line)
  {
    if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted)
    {
      fields.push_back(field);
      field.clear();
    }
    else
      field += c;
  }
  fields.push_back(field);
  return fields;
}
}

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::fprintf(stderr, "usage: CheckBenchmarkCsv results.csv MIN_PSNR\n");
    return 2;
  }
  const double minimum = std::atof(argv[2]);
  std::ifstream in(argv[1]);
  std::string line;
  if (!in || !std::getline(in, line))
  {
    std::fprintf(stderr, "cannot read %s\n", argv[1]);
    return 1;
  }
  const auto header = Fields(line);
  auto column = [&](const char* name) {
    for (size_t i = 0; i < header.size(); ++i)
      if (header[i] == name)
        return static_cast<int>(i);
    return -1;
  };
  const int repeats = column("repeats"), ratio = column("cpu_ratio"),
            ratioMin = column("cpu_ratio_min"), ratioMax = column("cpu_ratio_max"),
            psnrFullSS = column("psnr_full_ss"), psnrFull = column("psnr_full"),
            psnrRim = column("psnr_full_ss_rim"), brightness = column("brightness_full_ss"),
            psnrEdge = column("psnr_full_ss_edge");
  if (repeats < 0 || ratio < 0 || ratioMin < 0 || ratioMax < 0 || psnrFullSS < 0 || psnrFull < 0 ||
    psnrRim < 0 || brightness < 0 || psnrEdge < 0)
  {
    std::fprintf(stderr, "missing repeat, spread or supersampled-reference columns\n");
    return 1;
  }
  const int mesh = column("mesh"), method = column("method"), steps = column("steps"),
            range = column("depth_range"), adaptive = column("adaptive"),
            psnr = column("psnr_two"), back = column("back_surface"), secant = column("secant");
  if (mesh < 0 || method < 0 || psnr < 0 || steps < 0 || range < 0 || adaptive < 0 || back < 0 ||
    secant < 0)
  {
    std::fprintf(stderr, "missing columns\n");
    return 1;
  }
  int rows = 0;
  int failures = 0;
  int sawDir = 0;
  int sawConvergence = 0;
  const int convergence = column("ref_ss_convergence_psnr");
  const int convergenceRim = column("ref_ss_convergence_psnr_rim");
  while (std::getline(in, line))
  {
    const auto f = Fields(line);
    ++rows;
    if (f.size() != header.size())
    {
      std::fprintf(stderr, "row %d has %zu fields, header %zu\n", rows, f.size(), header.size());
      ++failures;
      continue;
    }
    for (size_t i = 0; i < f.size(); ++i)
    {
      if (static_cast<int>(i) == mesh || static_cast<int>(i) == method ||
        static_cast<int>(i) == range || static_cast<int>(i) == back || header[i] == "renderer")
        continue;
      char* end = nullptr;
      const double v = std::strtod(f[i].c_str(), &end);
      if (end == f[i].c_str() || !std::isfinite(v))
      {
        std::fprintf(stderr, "row %d: %s = '%s' is not a finite number\n", rows, header[i].c_str(),
          f[i].c_str());
        ++failures;
      }
    }
    const double r = std::atof(f[ratio].c_str());
    if (std::atoi(f[repeats].c_str()) < 3 || !(std::atof(f[ratioMin].c_str()) <= r) ||
      !(r <= std::atof(f[ratioMax].c_str())) || !(r > 0.0))
    {
      std::fprintf(stderr, "row %d: fewer than 3 repeats, or the median ratio %g outside "
                           "[%s, %s]\n", rows, r, f[ratioMin].c_str(), f[ratioMax].c_str());
      ++failures;
    }
    // With --convergence, the truth's convergence on its rim too: every glass has a rim, and
    // the rim is where the truth converges last (a figure above the whole glass's, or none,
    // means the rim mask found no pixels or the wrong ones).
    if (convergence >= 0 && std::atof(f[convergence].c_str()) > 0.0)
    {
      const double whole = std::atof(f[convergence].c_str());
      const double rimConvergence = convergenceRim >= 0 ? std::atof(f[convergenceRim].c_str()) : -1;
      if (!(rimConvergence > 0.0 && rimConvergence < whole))
      {
        std::fprintf(stderr, "row %d: the truth's convergence on the rim (%g dB) is missing or "
                             "not below the whole glass's (%g dB)\n", rows, rimConvergence, whole);
        ++failures;
      }
      ++sawConvergence;
    }
    if (f[mesh] == "sphere" && f[method] == "DIR" && f[steps] == "5" && f[range] == "reduction" &&
      f[adaptive] == "0" && f[back] == "furthest" && f[secant] == "1")
    {
      ++sawDir;
      const double value = std::atof(f[psnr].c_str());
      std::printf("DIR (5 steps) on the sphere: PSNR %.2f dB against the two-interface reference "
                  "(minimum %.2f)\n", value, minimum);
      if (!(value >= minimum))
        ++failures;
      const double full = std::atof(f[psnrFull].c_str());
      const double fullSS = std::atof(f[psnrFullSS].c_str());
      std::printf("  against the full reference %.2f dB, supersampled %.2f dB\n", full, fullSS);
      if (!(fullSS < full))
      {
        std::fprintf(stderr, "DIR reads no worse against the supersampled truth than against "
                             "the one-sample reference: the supersampling had no effect\n");
        ++failures;
      }
      const double rim = std::atof(f[psnrRim].c_str());
      const double bright = std::atof(f[brightness].c_str());
      const double edge = std::atof(f[psnrEdge].c_str());
      std::printf("  on the rim %.2f dB, the whole silhouette %.2f dB; brightness %.4f of the "
                  "truth's\n",
        rim, edge, bright);
      // The whole silhouette holds the rim's glass pixels and the background side, where a
      // single-sampled picture shows the background against a truth part glass: a figure, and
      // not the rim's (a mask that found only the rim's pixels would read the same).
      if (!(edge > 0.0 && edge != rim))
      {
        std::fprintf(stderr, "no figure for the whole silhouette, or the same as the rim's\n");
        ++failures;
      }
      if (!(rim > 0.0 && rim < fullSS))
      {
        std::fprintf(stderr, "the rim's error is not above the whole glass's: no rim pixels, or "
                             "the rim mask is wrong\n");
        ++failures;
      }
      if (!(std::fabs(bright - 1.0) <= 0.03))
      {
        std::fprintf(stderr, "DIR's glass is not as bright as the truth's within 3%%\n");
        ++failures;
      }
    }
  }
  if (sawDir != 1)
  {
    std::fprintf(stderr, "expected one DIR (5 steps, default settings) sphere row, found %d\n", sawDir);
    ++failures;
  }
  if (argc > 3 && std::string(argv[3]) == "convergence" && sawConvergence == 0)
  {
    std::fprintf(stderr, "no row holds the truth's convergence\n");
    ++failures;
  }
  std::printf("%d rows checked (%d with the truth's convergence), %d problems\n", rows,
    sawConvergence, failures);
  return failures == 0 && rows > 0 ? 0 : 1;
}
