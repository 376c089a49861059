#pragma once
#include <QElapsedTimer>
#include <QtGlobal>

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

    // Whether a readout showing `triangles` is to be written now; `changed`
    // is any other change the caller shows at once.
    bool isDue(qint64 triangles, bool changed = false) const
    {
        return !m_sinceShown.isValid() || m_sinceShown.elapsed() >= kIntervalMs
            || triangles != m_shownTriangles || changed;
    }
    void shown(qint64 triangles)
    {
        m_sinceShown.start();
        m_shownTriangles = triangles;
    }
    // The next isDue() is true (the readout was out of sight and may be stale).
    void forget() { m_sinceShown.invalidate(); }

private:
    QElapsedTimer m_sinceShown; // invalid until a readout is written
    qint64 m_shownTriangles = -1;
};

} // namespace phonglab
