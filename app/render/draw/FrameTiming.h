#pragma once
#include <QString>

#include <cmath>
#include <limits>
#include <vector>

namespace phonglab {

// What timing a run of frames found, in milliseconds.
//
// Wall time is bounded by glFinish: on a software rasterizer (llvmpipe) the
// work happens on driver threads that a GL_TIME_ELAPSED query does not see
// (it reads near zero), so the only honest figure is the time until the
// driver says the frame is done. Where the driver is a real GPU the timer
// query is read as well.
struct FrameTiming {
    double wallMedianMs = 0; // render() + glFinish()
    double wallP90Ms = 0;
    double cpuSubmitMedianMs = 0; // until render() returned: CPU-side submission
    double gpuMedianMs =
        std::numeric_limits<double>::quiet_NaN(); // GL_TIME_ELAPSED; NaN when not trusted
    int frames = 0;
};

// Median and nearest-rank percentile of a sample (copied, sorted).
double medianOf(std::vector<double> values);
double percentileOf(std::vector<double> values, double p);

// True for drivers whose timer queries miss the real work (software
// rasterizers run fragments on their own threads).
bool timerQueryTrusted(const QString &glRenderer);

} // namespace phonglab
