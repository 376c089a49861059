#include "ContextLender.h"

#include <QOpenGLContext>
#include <QThread>

#include <cassert>

namespace phonglab {

std::optional<LentContext> ContextLender::lend(QOpenGLContext *context, QSurface *surface,
                                               QThread *borrower, WarmUpDraw *warmer, int samples)
{
    if (!context || m_returned)
        return std::nullopt;
    // Only the thread a context lives in may lend it.
    assert(context->thread() == QThread::currentThread());
    if (QOpenGLContext::currentContext() == context)
        context->doneCurrent(); // a context changes threads only when current nowhere
    m_owner = QThread::currentThread();
    m_lent = context;
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
    // The borrower moves the context back before it says it is done.
    assert(m_lent->thread() == m_owner);
    m_returned.reset();
    m_borrower = nullptr;
    m_lent = nullptr;
    return true;
}

} // namespace phonglab
