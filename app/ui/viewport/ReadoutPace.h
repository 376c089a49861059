#pragma once
#include <QtGlobal>

#include <chrono>
#include <functional>

namespace phonglab {

// How often a readout of the viewport's frames (draw time, triangles) is
// written again. It changes at most twice a second, so that it can be read,
// and a new triangle count (another scene, a new detail level) or another
// change that matters shows at once. Writing a label on every frame costs a
// layout pass of its dock and a repaint of the window's widgets: a tenth of
// a frame on llvmpipe, which shows in the frame time itself.
class ReadoutPace
{
public:
    static constexpr int kIntervalMs = 500;
    // Milliseconds on a monotonic clock; a test passes its own and moves it
    // on instead of waiting.
    using Clock = std::function<qint64()>;

    // Whether a readout showing `triangles` is to be written now; `changed`
    // is any other change the caller shows at once.
    bool isDue(qint64 triangles, bool changed = false) const
    {
        return m_shownAtMs < 0 || m_clock() - m_shownAtMs >= kIntervalMs
            || triangles != m_shownTriangles || changed;
    }
    void shown(qint64 triangles)
    {
        m_shownAtMs = m_clock();
        m_shownTriangles = triangles;
    }
    // The next isDue() is true (the readout was out of sight and may be stale).
    void forget() { m_shownAtMs = -1; }
    void setClock(Clock clock) { m_clock = std::move(clock); }

private:
    static qint64 steadyMs()
    {
        return std::chrono::duration_cast<std::chrono::milliseconds>(
                   std::chrono::steady_clock::now().time_since_epoch())
            .count();
    }

    Clock m_clock = &ReadoutPace::steadyMs;
    qint64 m_shownAtMs = -1; // none written yet
    qint64 m_shownTriangles = -1;
};

} // namespace phonglab
