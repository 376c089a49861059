#pragma once
#include <functional>

namespace phonglab {

// Runs rowFunction(y) for every row 0..height-1 on all cores, rows handed
// out one at a time from a shared counter (rows differ a lot in cost: empty
// sky against dense foliage). The calling thread works too and is the only
// one that calls progress(rows done / height); returning false stops early
// and makes this return false. When no more threads can be had, fewer do the
// same work. What every per-pixel pass of the reference runs on: each row
// depends on nothing but its own pixels, so the result is the same for any
// number of threads.
bool forEachRowInParallel(int height, const std::function<void(int)> &rowFunction,
                          const std::function<bool(double)> &progress = {});

} // namespace phonglab
