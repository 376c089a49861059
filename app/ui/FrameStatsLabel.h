#pragma once
#include <QElapsedTimer>
#include <QLabel>

class QStatusBar;

namespace phonglab {

class Viewport;

// The status bar's readout of the viewport's frames: the draw time (mean of
// the last second's frames, see Viewport::frameRendered) and triangles
// drawn, plus a note while the depth range leaves too little depth
// precision (said once in the status bar when it starts, not on every frame
// of an orbit). It changes at most twice a second, so that it can be read,
// and only while a frame is being drawn, so that it adds no repaint of its
// own in the middle of a shader's build (when the view was a QOpenGLWidget,
// every label change recomposed the whole window through OpenGL). A new
// triangle count (another scene, a new level) and the depth warning coming
// or going show at once.
class FrameStatsLabel : public QLabel
{
    Q_OBJECT

public:
    static constexpr int kUpdateIntervalMs = 500;

    FrameStatsLabel(Viewport *viewport, QStatusBar *statusBar);

    void showFrame(double milliseconds, qint64 triangles);

private:
    Viewport *m_viewport = nullptr;
    QStatusBar *m_statusBar = nullptr;
    QElapsedTimer m_sinceShown; // invalid until the first frame is shown
    qint64 m_shownTriangles = -1;
    bool m_depthWarningShown = false;
};

} // namespace phonglab
