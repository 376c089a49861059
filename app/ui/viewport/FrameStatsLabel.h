#pragma once
#include "ReadoutPace.h"

#include <QLabel>

class QStatusBar;

namespace phonglab {

class Viewport;

// The status bar's readout of the viewport's frames: the draw time (mean of
// the last second's frames, see Viewport::frameRendered) and triangles
// drawn, plus a note while the depth range leaves too little depth
// precision (said once in the status bar when it starts, not on every frame
// of an orbit). It changes at the pace of ReadoutPace, and only while a frame
// is being drawn, so that it adds no repaint of its own in the middle of a
// shader's build; the depth warning coming or going shows at once.
class FrameStatsLabel : public QLabel
{
    Q_OBJECT

public:
    FrameStatsLabel(Viewport *viewport, QStatusBar *statusBar);

    void showFrame(double meanMsOfLastSecond, qint64 triangles);
    void setReadoutClock(ReadoutPace::Clock clock) { m_pace.setClock(std::move(clock)); }

private:
    Viewport *m_viewport = nullptr;
    QStatusBar *m_statusBar = nullptr;
    ReadoutPace m_pace;
    bool m_depthWarningShown = false;
};

} // namespace phonglab
