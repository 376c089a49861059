#include "WindowImage.h"

#include "ui/viewport/Viewport.h"

#include <QPainter>
#include <QPixmap>

namespace phonglab {

QImage windowImage(QWidget &window)
{
    QImage image = window.grab().toImage();
    QPainter painter(&image);
    for (Viewport *view : window.findChildren<Viewport *>()) {
        if (!view->isVisible())
            continue;
        const QImage frame = view->grabFramebuffer();
        if (!frame.isNull())
            painter.drawImage(QRect(view->mapTo(&window, QPoint(0, 0)), view->size()), frame);
    }
    return image;
}

} // namespace phonglab
