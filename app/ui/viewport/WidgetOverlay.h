#pragma once
#include "render/ImageLayer.h"

#include <QImage>
#include <QObject>

class QWidget;

namespace phonglab {

// The view's child widgets (the check's pictures, the detail label) drawn
// over each frame in GL: the frame goes straight to its own window, so Qt
// no longer composes widgets over it. Watches the children so that a change
// to one (painted, shown, moved) asks for a new frame; paints them again
// only then.
class WidgetOverlay : public QObject
{
    Q_OBJECT

public:
    // `excluded`: the child that is not drawn (the frame window's container).
    WidgetOverlay(QWidget *view, QWidget *excluded);

    // GL, with the frame's framebuffer bound: the visible children over it.
    void draw(const QSize &pixels);
    // GL: frees the texture and program.
    void destroy() { m_layer.destroy(); }

signals:
    // A child changed: the frame must be drawn again.
    void changed();

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    QWidget *m_view = nullptr;
    QWidget *m_excluded = nullptr;
    ImageLayer m_layer;
    QImage m_image; // the children as last painted
    bool m_dirty = true;
    bool m_painting = false; // their paint events are ours, not changes
};

} // namespace phonglab
