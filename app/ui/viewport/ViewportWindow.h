#pragma once
#include <QWindow>

namespace phonglab {

class Viewport;

// The native window the viewport's frames go to (inside the Viewport widget,
// through QWidget::createWindowContainer). Presenting here with swapBuffers
// skips what a QOpenGLWidget pays per frame: the resolve into a texture and
// Qt's recomposition of the whole main window through OpenGL
// (docs/performance.md). It only draws when asked and passes every input
// event on to the Viewport, so the widget keeps handling the mouse, keys and
// drops as any widget does.
class ViewportWindow : public QWindow
{
    Q_OBJECT

public:
    explicit ViewportWindow(Viewport *viewport);

    // A frame at the next turn of the event loop; several requests before
    // it make one frame (as QWidget::update).
    void requestFrame();

protected:
    bool event(QEvent *event) override;
    void exposeEvent(QExposeEvent *event) override;

private:
    Viewport *m_viewport = nullptr;
    bool m_framePending = false;
};

} // namespace phonglab
