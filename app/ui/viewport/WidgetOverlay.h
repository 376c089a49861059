#pragma once
#include "render/gl/ImageLayer.h"

#include <QImage>
#include <QList>
#include <QObject>
#include <optional>

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
    // What draw() would put over a frame of `pixels` with nothing painted
    // again, for a frame drawn on another thread (LoanFrame): a null image
    // when no child is shown, nullopt when they must be painted first
    // (which only this thread may do).
    std::optional<QImage> paintedFor(const QSize &pixels) const;
    // GL, on whichever thread holds the context: `image` over the frame.
    void drawPainted(const QImage &image, const QSize &pixels) { m_layer.draw(image, pixels); }
    // GL: frees the texture and program.
    void destroy() { m_layer.destroy(); }

signals:
    // A child changed: the frame must be drawn again.
    void changed();

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    QList<QWidget *> shownChildren() const;

    QWidget *m_view = nullptr;
    QWidget *m_excluded = nullptr;
    ImageLayer m_layer;
    QImage m_image; // the children as last painted
    bool m_dirty = true;
    bool m_painting = false; // their paint events are ours, not changes
};

} // namespace phonglab
