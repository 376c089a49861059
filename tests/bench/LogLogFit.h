#pragma once
#include <cmath>
#include <cstddef>
#include <vector>

namespace phonglab::bench {

// Least-squares slope of log(y) on log(x), over the points from `first` on
// (the large end, where fixed costs no longer hide the growth): 1 is linear.
inline double logLogSlope(const std::vector<double> &x, const std::vector<double> &y,
                          std::size_t first = 0)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double n = double(x.size() - first);
    for (std::size_t i = first; i < x.size(); ++i) {
        const double lx = std::log(x[i]), ly = std::log(y[i]);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

// The first index of the largest three points (all of them when fewer).
inline std::size_t largestThree(const std::vector<double> &x)
{
    return x.size() > 3 ? x.size() - 3 : 0;
}

} // namespace phonglab::bench
