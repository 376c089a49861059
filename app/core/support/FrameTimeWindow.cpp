#include "FrameTimeWindow.h"

namespace phonglab {

void FrameTimeWindow::add(qint64 atNs, double milliseconds)
{
    m_frames.push_back({atNs, milliseconds});
    m_sumMs += milliseconds;
    while (m_frames.size() > 1
           && (m_frames.front().atNs < atNs - kSpanNs || int(m_frames.size()) > kMaxFrames)) {
        m_sumMs -= m_frames.front().milliseconds;
        m_frames.pop_front();
    }
    if (m_frames.size() == 1)
        m_sumMs = m_frames.front().milliseconds; // no drift from the subtractions
}

double FrameTimeWindow::meanMs() const
{
    return m_frames.empty() ? 0.0 : m_sumMs / double(m_frames.size());
}

} // namespace phonglab
