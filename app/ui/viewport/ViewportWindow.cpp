#include "ViewportWindow.h"

#include "ViewportSurface.h"

#include <QCoreApplication>
#include <QWidget>

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

ViewportWindow::ViewportWindow(ViewportSurface *surface, QWidget *view)
    : m_surface(surface)
    , m_view(view)
{
    setSurfaceType(QSurface::OpenGLSurface);
    // Keyboard focus stays with the widgets: the view takes it on a
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
        m_surface->drawFrame();
        return true;
    }
    // A QWindow gets a press before each double click as well: the double
    // click itself would be a second press.
    if (event->type() == QEvent::MouseButtonDblClick)
        return true;
    if (isInput(event->type())) {
        // Sent events are not spontaneous, so Qt gives no click focus for them.
        if (event->type() == QEvent::MouseButtonPress && (m_view->focusPolicy() & Qt::ClickFocus))
            m_view->setFocus(Qt::MouseFocusReason);
        // The window lies exactly over the widget: positions carry over as they are.
        QCoreApplication::sendEvent(m_view, event);
        return true;
    }
    return QWindow::event(event);
}

void ViewportWindow::exposeEvent(QExposeEvent *)
{
    if (isExposed())
        m_surface->drawFrame();
}

} // namespace phonglab
