#pragma once
#include <QImage>

class QWidget;

namespace phonglab {

// `window` as it is on screen, views included: QWidget::grab() paints the
// widgets only, and a Viewport's frame lives in a native window of its own,
// so each visible view's frame (Viewport::grabFramebuffer) is painted in at
// its place. For screenshots and test artifacts.
QImage windowImage(QWidget &window);

} // namespace phonglab
