#pragma once
#include "core/scene/PointLight.h"

#include <QObject>
#include <QPointF>
#include <QStringList>

class QWidget;
class QMouseEvent;
class QWheelEvent;
class QKeyEvent;

namespace phonglab {

class GpuScene;

// What the mouse, the keys and drops do in the viewport: left drag orbits
// (or moves the light marker under the press), right or middle drag pans,
// the wheel zooms, keys trigger the view's actions, dropped local files are
// passed on. Watches the view widget's events (an event filter on it) and
// moves the camera and lights of its GpuScene; says so with its signals.
class ViewportInput : public QObject
{
    Q_OBJECT

public:
    ViewportInput(QWidget *view, GpuScene &scene);

signals:
    // A click, a wheel turn or a key in the view (held frames resume).
    void userActed();
    void cameraMoved();
    // A marker drag moved a light (the scene's parameters changed).
    void lightMoved();
    void lightPicked(int index);
    // A marker drag ended: one finished move of light `index` (for undo).
    void lightDragged(int index, const phonglab::PointLight &before,
                      const phonglab::PointLight &after);
    void filesDropped(const QStringList &paths);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    enum class Drag {
        None,
        Orbit,
        Pan,
        Light
    };

    bool mousePress(QMouseEvent *event);
    void mouseMove(QMouseEvent *event);
    void mouseRelease(QMouseEvent *event);
    bool wheel(QWheelEvent *event);
    bool keyPress(QKeyEvent *event);
    bool startLightDrag(const QPointF &position);
    void dragLight(const QPointF &position, bool alongView);
    void finishLightDrag();

    QWidget *m_view = nullptr;
    GpuScene &m_scene;
    Drag m_drag = Drag::None;
    QPointF m_lastMousePos;
    int m_dragLight = -1;   // the light a Drag::Light moves
    PointLight m_dragStart; // ... as it was when the drag began
};

} // namespace phonglab
