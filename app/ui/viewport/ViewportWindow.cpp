#include "ViewportWindow.h"

#include "Viewport.h"

#include <QCoreApplication>

namespace phonglab {

namespace {

bool isInput(QEvent::Type type)
{
    switch (type) {
    case QEvent::MouseButtonPress:
    case QEvent::MouseButtonRelease:
    case QEvent::MouseMove:
    case QEvent::Wheel:
    case QEvent::KeyPress:
    case QEvent::KeyRelease:
    case QEvent::DragEnter:
    case QEvent::DragMove:
    case QEvent::DragLeave:
    case QEvent::Drop: return true;
    default: return false;
    }
}

} // namespace

ViewportWindow::ViewportWindow(Viewport *viewport)
    : m_viewport(viewport)
{
    setSurfaceType(QSurface::OpenGLSurface);
    // Keyboard focus stays with the widgets: the Viewport takes it on a
    // click (below), and keys and shortcuts go the way of any widget's.
    setFlag(Qt::WindowDoesNotAcceptFocus);
}

void ViewportWindow::requestFrame()
{
    if (m_framePending)
        return;
    m_framePending = true;
    // A posted event rather than QWindow::requestUpdate(), whose platform
    // timer waits 5 ms on X11 before every frame.
    QCoreApplication::postEvent(this, new QEvent(QEvent::UpdateRequest), Qt::LowEventPriority);
}

bool ViewportWindow::event(QEvent *event)
{
    if (event->type() == QEvent::UpdateRequest) {
        m_framePending = false;
        m_viewport->drawFrame();
        return true;
    }
    // A QWindow gets a press before each double click as well: the double
    // click itself would be a second press.
    if (event->type() == QEvent::MouseButtonDblClick)
        return true;
    if (isInput(event->type())) {
        // Sent events are not spontaneous, so Qt gives no click focus for them.
        if (event->type() == QEvent::MouseButtonPress
            && (m_viewport->focusPolicy() & Qt::ClickFocus))
            m_viewport->setFocus(Qt::MouseFocusReason);
        // The window lies exactly over the widget: positions carry over as they are.
        QCoreApplication::sendEvent(m_viewport, event);
        return true;
    }
    return QWindow::event(event);
}

void ViewportWindow::exposeEvent(QExposeEvent *)
{
    if (isExposed())
        m_viewport->drawFrame();
}

} // namespace phonglab
