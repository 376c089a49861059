// Viewport's input: orbit, pan and zoom, dragging light markers, keys and
// dropped files (the rest of the class is in Viewport.cpp).
#include "Viewport.h"

#include "LightPicking.h"

#include <QAction>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QKeyEvent>
#include <QMimeData>
#include <QMouseEvent>
#include <QWheelEvent>
#include <cmath>

namespace phonglab {

namespace {

constexpr double kOrbitDegPerPixel = 0.4;
constexpr double kZoomPerWheelNotch = 0.85; // distance factor for one notch towards the scene
constexpr double kWheelNotch = 120.0;       // QWheelEvent::angleDelta() units per notch
constexpr double kLightPickRadiusPx = 8.0;  // how near a click must be to a marker

// The local files among dropped URLs; anything else (web links) is not ours.
QStringList localFiles(const QMimeData *data)
{
    QStringList paths;
    if (!data || !data->hasUrls())
        return paths;
    for (const QUrl &url : data->urls())
        if (url.isLocalFile())
            paths << url.toLocalFile();
    return paths;
}

} // namespace

bool Viewport::startLightDrag(const QPointF &position)
{
    if (!m_options.drawLightMarkers)
        return false; // nothing visible to grab
    m_dragLight =
        pickLight(m_scene.lights, m_orbit.camera(), QSizeF(size()), position, kLightPickRadiusPx);
    if (m_dragLight < 0)
        return false;
    m_dragStart = m_scene.lights[m_dragLight];
    setSelectedLight(m_dragLight);
    emit lightPicked(m_dragLight);
    return true;
}

void Viewport::dragLight(const QPointF &position, bool alongView)
{
    glm::dvec3 &p = m_scene.lights[m_dragLight].position;
    p = alongView
        ? moveAlongView(p, m_orbit.camera(), QSizeF(size()), position.y() - m_lastMousePos.y())
        : moveInViewPlane(p, m_orbit.camera(), QSizeF(size()), position);
    m_parametersDirty = true;
    requestFrame();
    emit sceneParametersChanged();
}

void Viewport::finishLightDrag()
{
    const int index = m_dragLight;
    m_dragLight = -1;
    if (index >= 0 && index < int(m_scene.lights.size()) && !(m_scene.lights[index] == m_dragStart))
        emit lightDragged(index, m_dragStart, m_scene.lights[index]);
}

void Viewport::mousePressEvent(QMouseEvent *event)
{
    resumeFrames();
    switch (event->button()) {
    case Qt::LeftButton:
        m_drag = startLightDrag(event->position()) ? Drag::Light : Drag::Orbit;
        break;
    case Qt::RightButton:
    case Qt::MiddleButton: m_drag = Drag::Pan; break;
    default: QWidget::mousePressEvent(event); return;
    }
    m_lastMousePos = event->position();
    event->accept();
}

void Viewport::mouseMoveEvent(QMouseEvent *event)
{
    if (m_drag == Drag::None) {
        QWidget::mouseMoveEvent(event);
        return;
    }
    if (m_drag == Drag::Light) {
        dragLight(event->position(), event->modifiers() & Qt::ShiftModifier);
        m_lastMousePos = event->position();
        event->accept();
        return;
    }
    const QPointF delta = event->position() - m_lastMousePos;
    m_lastMousePos = event->position();
    m_cameraFramed = false; // the camera is the user's now: a resize leaves it
    if (m_drag == Drag::Orbit) {
        // "Grab the object" feel: dragging right turns its front to the right.
        m_orbit.orbit(-delta.x() * kOrbitDegPerPixel, delta.y() * kOrbitDegPerPixel);
    } else {
        const double viewHeight = std::max(1, height());
        m_orbit.pan(delta.x() / viewHeight, delta.y() / viewHeight);
    }
    cameraMoved();
    event->accept();
}

void Viewport::mouseReleaseEvent(QMouseEvent *event)
{
    if (event->buttons() == Qt::NoButton) {
        if (m_drag == Drag::Light)
            finishLightDrag(); // the whole drag is one undo step
        m_drag = Drag::None;
    }
    event->accept();
}

void Viewport::wheelEvent(QWheelEvent *event)
{
    resumeFrames();
    const double notches = event->angleDelta().y() / kWheelNotch;
    if (notches == 0.0) {
        event->ignore();
        return;
    }
    m_cameraFramed = false;
    m_orbit.zoom(std::pow(kZoomPerWheelNotch, notches));
    cameraMoved();
    event->accept();
}

// The key map is the actions added to this view (Reset Camera's R and Home,
// Inspect's I): their shortcuts. A key that reaches the view unclaimed (the
// shortcut system only acts for an active window) triggers the action that
// names it, so no key is handled in two places.
void Viewport::keyPressEvent(QKeyEvent *event)
{
    resumeFrames();
    const QKeySequence pressed(event->keyCombination());
    for (QAction *action : actions()) {
        if (action->isEnabled() && action->shortcuts().contains(pressed)) {
            action->trigger();
            event->accept();
            return;
        }
    }
    QWidget::keyPressEvent(event);
}

void Viewport::dragEnterEvent(QDragEnterEvent *event)
{
    // Any local file is welcome: an unsupported one is then explained by the
    // window rather than refused without a word.
    if (!localFiles(event->mimeData()).isEmpty())
        event->acceptProposedAction();
}

void Viewport::dropEvent(QDropEvent *event)
{
    const QStringList paths = localFiles(event->mimeData());
    if (paths.isEmpty())
        return;
    event->acceptProposedAction();
    emit filesDropped(paths);
}

} // namespace phonglab
