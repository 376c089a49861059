#include "ViewportInput.h"

#include "LightPicking.h"
#include "render/draw/GpuScene.h"

#include <QAction>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QKeyEvent>
#include <QMimeData>
#include <QMouseEvent>
#include <QWheelEvent>
#include <QWidget>
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

ViewportInput::ViewportInput(QWidget *view, GpuScene &scene)
    : QObject(view)
    , m_view(view)
    , m_scene(scene)
{
    view->setFocusPolicy(Qt::StrongFocus); // so R / Home reach the view after a click
    view->setAcceptDrops(true);
    view->installEventFilter(this);
}

bool ViewportInput::eventFilter(QObject *watched, QEvent *event)
{
    if (watched != m_view)
        return false;
    switch (event->type()) {
    case QEvent::MouseButtonPress: return mousePress(static_cast<QMouseEvent *>(event));
    case QEvent::MouseMove:
        if (m_drag == Drag::None)
            return false;
        mouseMove(static_cast<QMouseEvent *>(event));
        return true;
    case QEvent::MouseButtonRelease: mouseRelease(static_cast<QMouseEvent *>(event)); return true;
    case QEvent::Wheel: return wheel(static_cast<QWheelEvent *>(event));
    case QEvent::KeyPress: return keyPress(static_cast<QKeyEvent *>(event));
    case QEvent::DragEnter: {
        // Any local file is welcome: an unsupported one is then explained by
        // the window rather than refused without a word.
        auto *enter = static_cast<QDragEnterEvent *>(event);
        if (!localFiles(enter->mimeData()).isEmpty())
            enter->acceptProposedAction();
        return true;
    }
    case QEvent::Drop: {
        auto *drop = static_cast<QDropEvent *>(event);
        const QStringList paths = localFiles(drop->mimeData());
        if (!paths.isEmpty()) {
            drop->acceptProposedAction();
            emit filesDropped(paths);
        }
        return true;
    }
    default: return false;
    }
}

bool ViewportInput::mousePress(QMouseEvent *event)
{
    emit userActed();
    switch (event->button()) {
    case Qt::LeftButton:
        m_drag = startLightDrag(event->position()) ? Drag::Light : Drag::Orbit;
        break;
    case Qt::RightButton:
    case Qt::MiddleButton: m_drag = Drag::Pan; break;
    default: return false;
    }
    m_lastMousePos = event->position();
    event->accept();
    return true;
}

void ViewportInput::mouseMove(QMouseEvent *event)
{
    event->accept();
    if (m_drag == Drag::Light) {
        dragLight(event->position(), event->modifiers() & Qt::ShiftModifier);
        m_lastMousePos = event->position();
        return;
    }
    const QPointF delta = event->position() - m_lastMousePos;
    m_lastMousePos = event->position();
    OrbitCamera &orbit = m_scene.orbitByUser();
    if (m_drag == Drag::Orbit) {
        // "Grab the object" feel: dragging right turns its front to the right.
        orbit.orbit(-delta.x() * kOrbitDegPerPixel, delta.y() * kOrbitDegPerPixel);
    } else {
        const double viewHeight = std::max(1, m_view->height());
        orbit.pan(delta.x() / viewHeight, delta.y() / viewHeight);
    }
    emit cameraMoved();
}

void ViewportInput::mouseRelease(QMouseEvent *event)
{
    if (event->buttons() == Qt::NoButton) {
        if (m_drag == Drag::Light)
            finishLightDrag(); // the whole drag is one undo step
        m_drag = Drag::None;
    }
    event->accept();
}

bool ViewportInput::wheel(QWheelEvent *event)
{
    emit userActed();
    const double notches = event->angleDelta().y() / kWheelNotch;
    if (notches == 0.0) {
        event->ignore();
        return true;
    }
    m_scene.orbitByUser().zoom(std::pow(kZoomPerWheelNotch, notches));
    emit cameraMoved();
    event->accept();
    return true;
}

// The key map is the actions added to the view (Reset Camera's R and Home,
// Inspect's I): their shortcuts. A key that reaches the view unclaimed (the
// shortcut system only acts for an active window) triggers the action that
// names it, so no key is handled in two places.
bool ViewportInput::keyPress(QKeyEvent *event)
{
    emit userActed();
    const QKeySequence pressed(event->keyCombination());
    for (QAction *action : m_view->actions()) {
        if (action->isEnabled() && action->shortcuts().contains(pressed)) {
            action->trigger();
            event->accept();
            return true;
        }
    }
    return false;
}

bool ViewportInput::startLightDrag(const QPointF &position)
{
    if (!m_scene.options().drawLightMarkers)
        return false; // nothing visible to grab
    m_dragLight = pickLight(m_scene.scene().lights, m_scene.camera(), QSizeF(m_view->size()),
                            position, kLightPickRadiusPx);
    if (m_dragLight < 0)
        return false;
    m_dragStart = m_scene.scene().lights[m_dragLight];
    emit lightPicked(m_dragLight);
    return true;
}

void ViewportInput::dragLight(const QPointF &position, bool alongView)
{
    if (m_dragLight >= int(m_scene.scene().lights.size()))
        return; // the light went (an undo) while it was dragged
    const glm::dvec3 &p = m_scene.scene().lights[m_dragLight].position;
    const Camera &camera = m_scene.camera();
    const QSizeF view(m_view->size());
    m_scene.moveLight(m_dragLight,
                      alongView ? moveAlongView(p, camera, view, position.y() - m_lastMousePos.y())
                                : moveInViewPlane(p, camera, view, position));
    emit lightMoved();
}

void ViewportInput::finishLightDrag()
{
    const int index = m_dragLight;
    m_dragLight = -1;
    const std::vector<PointLight> &lights = m_scene.scene().lights;
    if (index >= 0 && index < int(lights.size()) && !(lights[index] == m_dragStart))
        emit lightDragged(index, m_dragStart, lights[index]);
}

} // namespace phonglab
