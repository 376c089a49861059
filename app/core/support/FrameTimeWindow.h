#pragma once
#include <QtGlobal>

#include <deque>

namespace phonglab {

// The frame times of the last second: what the status bar reports. A mean
// over a window neither jumps with one slow frame nor, like a running
// average, still carries the first frames' shader compilation long after.
class FrameTimeWindow
{
public:
    static constexpr qint64 kSpanNs = 1'000'000'000; // one second
    // Bounds the memory and the work per frame; above 240 frames a second
    // the window is shorter than a second, which a mean does not notice.
    static constexpr int kMaxFrames = 240;

    // A frame that ended at `atNs` (any monotonic clock) and took `milliseconds`.
    void add(qint64 atNs, double milliseconds);
    // The mean of the frames in the window, 0 with none; the newest frame is
    // always counted, however old.
    double meanMs() const;
    int frames() const { return int(m_frames.size()); }
    // The newest frame's time, 0 with none.
    double latestMs() const { return m_frames.empty() ? 0.0 : m_frames.back().milliseconds; }

private:
    struct Frame {
        qint64 atNs;
        double milliseconds;
    };
    std::deque<Frame> m_frames;
    double m_sumMs = 0.0;
};

} // namespace phonglab
