#include "FrameStatsLabel.h"
#include "core/support/Language.h"

#include "Viewport.h"
#include "core/view/DepthRange.h"

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
    connect(viewport, &Viewport::frameRendered, this, &FrameStatsLabel::showFrame);
}

void FrameStatsLabel::showFrame(double meanMsOfLastSecond, qint64 triangles)
{
    // A new triangle count or a depth warning that comes or goes shows at
    // once: only the milliseconds may lag.
    const std::optional<QString> depth = depthPrecisionWarning(m_viewport->drawing().depthRange());
    if (!m_pace.isDue(triangles, depth.has_value() != m_depthWarningShown))
        return;
    m_pace.shown(triangles);
    setText(tr("draw %1 ms · %2 triangles%3")
                .arg(sentenceNumber(meanMsOfLastSecond, 'f', 2))
                .arg(QLocale().toString(triangles))
                .arg(depth ? tr(" · low depth precision") : QString()));
    const QString explained =
        tr("Draw time per frame: from the frame's first OpenGL call to glFinish, the scene and "
           "anything drawn over it (presenting the frame is not included); the mean of the %n "
           "frame(s) of the last "
           "second.",
           nullptr, m_viewport->frames().frameTimes().frames());
    setToolTip(depth ? explained + QStringLiteral("\n\n") + *depth : explained);
    if (depth && !m_depthWarningShown)
        m_statusBar->showMessage(*depth, kDepthWarningTimeoutMs);
    m_depthWarningShown = depth.has_value();
}

} // namespace phonglab
