#pragma once
#include <QLabel>
#include <QTimer>

class QStatusBar;

namespace phonglab {

class Viewport;

// The status bar's readout of the viewport's frames: the draw time (mean of
// the last second's frames, see Viewport::frameRendered) and triangles
// drawn, plus a note while the depth range leaves too little depth
// precision (said once in the status bar when it starts, not on every frame
// of an orbit). It changes at most twice a second: any change of a label
// recomposes the whole window, OpenGL view included, which on a software
// renderer costs more than a frame.
class FrameStatsLabel : public QLabel
{
    Q_OBJECT

public:
    static constexpr int kUpdateIntervalMs = 500;

    FrameStatsLabel(Viewport *viewport, QStatusBar *statusBar);

    void showFrame(double milliseconds, qint64 triangles);

private:
    void showLatest();

    Viewport *m_viewport = nullptr;
    QStatusBar *m_statusBar = nullptr;
    QTimer m_throttle;
    double m_latestMs = 0.0;
    qint64 m_latestTriangles = 0;
    bool m_depthWarningShown = false;
};

} // namespace phonglab
