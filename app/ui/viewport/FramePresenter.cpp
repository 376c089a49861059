#include "FramePresenter.h"

#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QWindow>

namespace phonglab {

FramePresenter::FramePresenter(QObject *parent)
    : QObject(parent)
{
    m_thread.setObjectName(QStringLiteral("phonglab frame presenter"));
    m_worker.moveToThread(&m_thread);
    m_thread.start();
}

FramePresenter::~FramePresenter()
{
    m_thread.quit();
    m_thread.wait();
}

void FramePresenter::present(quint64 loan, LentContext lent, QThread *owner,
                             std::chrono::steady_clock::time_point started)
{
    QMetaObject::invokeMethod(
        &m_worker,
        [this, loan, lent = std::move(lent), owner, started] {
            QOpenGLContext *context = lent.context;
            const bool ok = context->makeCurrent(lent.surface);
            double drawMs = 0;
            std::chrono::steady_clock::time_point swapped;
            if (ok) {
                context->functions()->glFinish(); // the frame's draw ends here
                drawMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now()
                                                                   - started)
                             .count();
                context->swapBuffers(lent.surface);
                swapped = std::chrono::steady_clock::now();
                context->doneCurrent();
            }
            context->moveToThread(owner);
            lent.returned->release();
            emit presented(loan, drawMs, swapped.time_since_epoch().count(), ok);
        },
        Qt::QueuedConnection);
}

} // namespace phonglab
