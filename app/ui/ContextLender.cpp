#include "ContextLender.h"

#include <QOpenGLContext>
#include <QOpenGLWidget>

namespace phonglab {

ContextLender::ContextLender(QOpenGLWidget *widget)
    : m_widget(widget)
{
    QObject::connect(widget, &QOpenGLWidget::aboutToCompose, widget,
                     [this] { m_composePending = false; });
}

std::optional<LentContext> ContextLender::lend(QThread *borrower, WarmUpDraw *warmer, int samples)
{
    QOpenGLContext *context = m_widget->context();
    if (!context || m_returned || m_composePending)
        return std::nullopt;
    m_widget->doneCurrent(); // a context changes threads only when current nowhere
    m_widget->setUpdatesEnabled(false);
    context->moveToThread(borrower);
    m_returned = std::make_shared<QSemaphore>(0);
    return LentContext{context, warmer, samples, m_returned, {}};
}

bool ContextLender::end(int timeoutMs)
{
    if (!m_returned)
        return true;
    if (!m_returned->tryAcquire(1, timeoutMs))
        return false;
    m_returned.reset();
    m_widget->setUpdatesEnabled(true); // and repaints what was missed
    return true;
}

} // namespace phonglab
