// The Pareto front of error against run time: the rows no other row beats on both (faster or
// as fast, and closer or as close to the supersampled truth), drawn in pareto.png over every
// row and listed in results.md, with where the pass's default setting stands.
#ifndef rfBenchPareto_h
#define rfBenchPareto_h

#include "rfBenchRow.h"

#include <string>
#include <utility>
#include <vector>

class vtkRenderWindow;

namespace rfbench
{
// (cost, error) pairs, lower is better on both.
using CostError = std::pair<double, double>;

// The indices of the points no other point dominates (at most its cost and at most its error,
// less on one of them), in order of cost. Points equal on both are kept, all of them. Points
// with a negative or non-finite cost or error (not measured) take no part.
std::vector<size_t> ParetoFront(const std::vector<CostError>& points);

// The size the plot and the summaries show: the one nearest 512 (the paper's Table 1 size).
int SizeNearest512(const std::vector<Row>& rows);

// The meshes of the rows, in the order they first appear.
std::vector<std::string> Meshes(const std::vector<Row>& rows);

// True for the pass's default setting (vtkRefractionPass as constructed: DIR, 5 steps, the
// depth range by reduction, filtered lookups, no anti-aliasing, no TIR followed).
bool IsDefaultSetting(const Setting& setting);

// results.md's section: for each mesh at the size nearest 512, the rows on the front (ratio to
// plain and PSNR against the supersampled full reference) and whether the default setting is
// on it, or which rows dominate it.
std::string ParetoSummary(const std::vector<Row>& rows);

// Draws pareto.png in the window (its renderers are taken out): every row as a point, one
// colour per family of settings, and the front as a line.
bool WritePareto(vtkRenderWindow* window, const std::string& path, const std::vector<Row>& rows);
}

#endif
