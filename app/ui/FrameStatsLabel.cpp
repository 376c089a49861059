#include "FrameStatsLabel.h"

#include "Viewport.h"
#include "core/DepthRange.h"

#include <QLocale>
#include <QStatusBar>

namespace phonglab {

namespace {
constexpr int kDepthWarningTimeoutMs = 15000;
} // namespace

FrameStatsLabel::FrameStatsLabel(Viewport *viewport, QStatusBar *statusBar)
    : QLabel(statusBar)
    , m_viewport(viewport)
    , m_statusBar(statusBar)
{
    m_throttle.setSingleShot(true);
    m_throttle.setInterval(kUpdateIntervalMs);
    connect(&m_throttle, &QTimer::timeout, this, &FrameStatsLabel::showLatest);
    connect(viewport, &Viewport::frameRendered, this, &FrameStatsLabel::showFrame);
}

// The first frame shows at once; later ones wait for the interval to end,
// and the last frame of a burst is always shown.
void FrameStatsLabel::showFrame(double milliseconds, qint64 triangles)
{
    m_latestMs = milliseconds;
    m_latestTriangles = triangles;
    if (m_throttle.isActive())
        return;
    showLatest();
    m_throttle.start();
}

void FrameStatsLabel::showLatest()
{
    const std::optional<QString> depth = depthPrecisionWarning(m_viewport->depthRange());
    const QString text = tr("draw %1 ms · %2 triangles%3")
                             .arg(m_latestMs, 0, 'f', 2)
                             .arg(QLocale().toString(m_latestTriangles))
                             .arg(depth ? tr(" · low depth precision") : QString());
    if (text != this->text())
        setText(text);
    const QString explained =
        tr("Draw time per frame: from the frame's first OpenGL call to glFinish, the scene only "
           "(composing the window is not included); the mean of the %n frame(s) of the last "
           "second.",
           nullptr, m_viewport->frameTimes().frames());
    setToolTip(depth ? explained + QStringLiteral("\n\n") + *depth : explained);
    if (depth && !m_depthWarningShown)
        m_statusBar->showMessage(*depth, kDepthWarningTimeoutMs);
    m_depthWarningShown = depth.has_value();
}

} // namespace phonglab
