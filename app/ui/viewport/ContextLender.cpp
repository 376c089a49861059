#include "ContextLender.h"

#include <QOpenGLContext>

namespace phonglab {

std::optional<LentContext> ContextLender::lend(QOpenGLContext *context, QSurface *surface,
                                               QThread *borrower, WarmUpDraw *warmer, int samples)
{
    if (!context || m_returned)
        return std::nullopt;
    if (QOpenGLContext::currentContext() == context)
        context->doneCurrent(); // a context changes threads only when current nowhere
    context->moveToThread(borrower);
    m_returned = std::make_shared<QSemaphore>(0);
    m_borrower = borrower;
    return LentContext{context, surface, warmer, samples, m_returned, {}, {}, {}};
}

bool ContextLender::end(int timeoutMs)
{
    if (!m_returned)
        return true;
    if (!m_returned->tryAcquire(1, timeoutMs))
        return false;
    m_returned.reset();
    m_borrower = nullptr;
    return true;
}

} // namespace phonglab
