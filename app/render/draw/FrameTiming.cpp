#include "FrameTiming.h"

#include <algorithm>

namespace phonglab {

double percentileOf(std::vector<double> values, double p)
{
    if (values.empty())
        return std::numeric_limits<double>::quiet_NaN();
    std::sort(values.begin(), values.end());
    const double rank = std::clamp(p, 0.0, 1.0) * double(values.size() - 1);
    return values[std::size_t(std::lround(rank))];
}

double medianOf(std::vector<double> values)
{
    if (values.empty())
        return std::numeric_limits<double>::quiet_NaN();
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

bool timerQueryTrusted(const QString &glRenderer)
{
    const QString r = glRenderer.toLower();
    return !(r.contains(QLatin1String("llvmpipe")) || r.contains(QLatin1String("softpipe"))
             || r.contains(QLatin1String("swiftshader")) || r.contains(QLatin1String("software")));
}

} // namespace phonglab
