#pragma once
#include "BenchResult.h"

#include <vector>

namespace phonglab {

// Indices of the rows no other row beats on both frame time and error
// (RMSE): for each, no other row is at least as fast and at least as
// accurate and strictly better in one. Sorted by frame time.
std::vector<int> paretoFront(const std::vector<BenchRow> &rows);

} // namespace phonglab
