#pragma once
#include "render/LentContext.h"

#include <optional>

class QOpenGLWidget;
class QThread;

namespace phonglab {

// Lends a QOpenGLWidget's context to another thread, the way QOpenGLWidget
// documents drawing off the GUI thread (move the context, make it current
// there, move it back), and keeps the widget from touching the context
// meanwhile: updates are disabled (after any paint event QOpenGLWidget makes
// its context current to resolve multisampling, whatever paintEvent does),
// and a frame painted but not yet composed blocks lending (composing flushes
// it with the context current). The widget calls end() before any GL work.
class ContextLender
{
public:
    explicit ContextLender(QOpenGLWidget *widget);

    // nullopt when the context cannot be lent right now.
    std::optional<LentContext> lend(QThread *borrower, WarmUpDraw *warmer, int samples);
    // Waits for the borrower to give the context back (at most timeoutMs;
    // -1: as long as it takes); false if it did not in time.
    bool end(int timeoutMs = -1);
    bool isActive() const { return m_returned != nullptr; }
    // From the widget's paintGL(): a frame now waits to be composed.
    void framePainted() { m_composePending = true; }

private:
    QOpenGLWidget *m_widget = nullptr;
    std::shared_ptr<QSemaphore> m_returned; // set while lent
    bool m_composePending = false;
};

} // namespace phonglab
