// How close to the truth the pass gets for a price: results.md's accuracy section, per mesh at
// the size nearest 512, the default setting and the closest setting that costs at most four
// times plain VTK (the yardstick of issue 26's goals). The README's accuracy table is this
// section of the committed full sweep, remade from its CSV by --from-csv.
#ifndef rfBenchAccuracy_h
#define rfBenchAccuracy_h

#include "rfBenchRow.h"

#include <string>
#include <vector>

namespace rfbench
{
// The most a setting may cost, as its median ratio to plain VTK, to count as real time here.
constexpr double AccuracyBudgetRatio = 4.0;

std::string AccuracySummary(const std::vector<Row>& rows);
}

#endif
