// The statistics of repeated timings, shared by the benchmark (RefractionBenchmark) and the
// viewer's --timing: the median of a block of frames, and the median and extremes over the
// repeats of a measurement. Header only, so that neither program links the other's code.
#ifndef rfSpread_h
#define rfSpread_h

#include <algorithm>
#include <vector>

namespace rftiming
{
// Medians and extremes over the repeats of one measurement.
struct Spread
{
  double Median = -1, Min = -1, Max = -1;
};

// The median of v, -1 when empty.
inline double Median(std::vector<double> v)
{
  if (v.empty())
  {
    return -1.0;
  }
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

// Median, min and max of v (-1 each when empty).
inline Spread SpreadOf(const std::vector<double>& v)
{
  Spread s;
  if (!v.empty())
  {
    s.Median = Median(v);
    s.Min = *std::min_element(v.begin(), v.end());
    s.Max = *std::max_element(v.begin(), v.end());
  }
  return s;
}
}

#endif
