// results.csv: every row, one column per field, written after a run and read back by
// --from-csv to remake the report.
#ifndef rfBenchCsv_h
#define rfBenchCsv_h

#include "rfBenchRow.h"

#include <string>
#include <vector>

namespace rfbench
{
// Writes the rows, each with the renderer's name; false when the file cannot be written.
bool WriteCsv(const std::string& path, const std::vector<Row>& rows, const std::string& renderer);

// Rows back from a results.csv written by WriteCsv, to remake results.md and pareto.png.
bool ReadCsv(const std::string& path, std::vector<Row>& rows, std::string& renderer);
}

#endif
