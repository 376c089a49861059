#pragma once
#include <QLabel>

class QStatusBar;

namespace phonglab {

class Viewport;

// The status bar's readout of the viewport's frames: milliseconds per
// frame and triangles drawn, plus a note while the depth range leaves too
// little depth precision (said once in the status bar when it starts, not
// on every frame of an orbit).
class FrameStatsLabel : public QLabel
{
    Q_OBJECT

public:
    FrameStatsLabel(Viewport *viewport, QStatusBar *statusBar);

    void showFrame(double milliseconds, qint64 triangles);

private:
    Viewport *m_viewport;
    QStatusBar *m_statusBar;
    bool m_depthWarningShown = false;
};

} // namespace phonglab
