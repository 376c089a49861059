#pragma once
#include "render/gl/LentContext.h"

#include <optional>

class QOpenGLContext;
class QSurface;
class QThread;

namespace phonglab {

// Lends the viewport's context to another thread (release it, move it to
// the borrower's thread; the borrower moves it back), and says whether it is
// out: the viewport draws no frame meanwhile and calls end() before any GL
// work of its own.
class ContextLender
{
public:
    // nullopt when the context is lent already.
    std::optional<LentContext> lend(QOpenGLContext *context, QSurface *surface, QThread *borrower,
                                    WarmUpDraw *warmer, int samples);
    // Waits for the borrower to give the context back (at most timeoutMs;
    // -1: as long as it takes); false if it did not in time.
    bool end(int timeoutMs = -1);
    bool isActive() const { return m_returned != nullptr; }
    // The thread the context is lent to (null when it is not lent).
    QThread *borrower() const { return m_borrower; }

private:
    std::shared_ptr<QSemaphore> m_returned; // set while lent
    QThread *m_borrower = nullptr;
    QOpenGLContext *m_lent = nullptr; // the context while lent
    QThread *m_owner = nullptr;       // the thread it was lent from, and comes back to
};

} // namespace phonglab
