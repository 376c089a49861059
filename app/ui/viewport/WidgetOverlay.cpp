#include "WidgetOverlay.h"

#include <QChildEvent>
#include <QPainter>
#include <QWidget>

namespace phonglab {

WidgetOverlay::WidgetOverlay(QWidget *view, QWidget *excluded)
    : QObject(view)
    , m_view(view)
    , m_excluded(excluded)
{
    view->installEventFilter(this); // to watch children as they are added
    for (QObject *child : view->children())
        if (child->isWidgetType() && child != excluded)
            child->installEventFilter(this);
}

bool WidgetOverlay::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_view) {
        if (event->type() == QEvent::ChildAdded) {
            QObject *child = static_cast<QChildEvent *>(event)->child();
            if (child->isWidgetType() && child != m_excluded)
                child->installEventFilter(this);
        }
        return false;
    }
    switch (event->type()) {
    case QEvent::Paint:
        if (m_painting)
            break;
        [[fallthrough]];
    case QEvent::Show:
    case QEvent::Hide:
    case QEvent::Move:
    case QEvent::Resize:
        m_dirty = true;
        emit changed();
        break;
    default: break;
    }
    return false;
}

QList<QWidget *> WidgetOverlay::shownChildren() const
{
    QList<QWidget *> shown;
    for (QWidget *child : m_view->findChildren<QWidget *>(Qt::FindDirectChildrenOnly))
        if (child != m_excluded && child->isVisible())
            shown << child;
    return shown;
}

std::optional<QImage> WidgetOverlay::paintedFor(const QSize &pixels) const
{
    if (shownChildren().isEmpty())
        return QImage();
    if (m_dirty || m_image.size() != pixels)
        return std::nullopt;
    return m_image;
}

// The children as QPainter draws them (premultiplied).
void WidgetOverlay::draw(const QSize &pixels)
{
    const QList<QWidget *> shown = shownChildren();
    if (shown.isEmpty())
        return;
    if (m_dirty || m_image.size() != pixels) {
        QImage image(pixels, QImage::Format_RGBA8888_Premultiplied);
        image.setDevicePixelRatio(m_view->devicePixelRatioF());
        image.fill(Qt::transparent);
        m_painting = true;
        {
            QPainter painter(&image);
            for (QWidget *child : shown)
                child->render(&painter, child->pos(), QRegion(), QWidget::DrawChildren);
        }
        m_painting = false;
        m_image = image;
        m_dirty = false;
    }
    m_layer.draw(m_image, pixels);
}

} // namespace phonglab
