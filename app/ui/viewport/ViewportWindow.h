#pragma once
#include <QWindow>

class QWidget;

namespace phonglab {

class ViewportSurface;

// The native window the viewport's frames go to (made by ViewportSurface,
// inside the Viewport widget through QWidget::createWindowContainer).
// Presenting here with swapBuffers skips what a QOpenGLWidget pays per
// frame: the resolve into a texture and Qt's recomposition of the whole main
// window through OpenGL (docs/performance.md). It only draws when asked and passes every input
// event on to the view widget, so that keeps handling the mouse, keys and
// drops as any widget does.
class ViewportWindow : public QWindow
{
    Q_OBJECT

public:
    ViewportWindow(ViewportSurface *surface, QWidget *view);

    // A frame at the next turn of the event loop; several requests before
    // it make one frame (as QWidget::update).
    void requestFrame();
    bool isFramePending() const { return m_framePending; }

protected:
    bool event(QEvent *event) override;
    void exposeEvent(QExposeEvent *event) override;

private:
    ViewportSurface *m_surface = nullptr; // draws the frames
    QWidget *m_view = nullptr;            // gets the input
    bool m_framePending = false;
};

} // namespace phonglab
