#include "ThumbnailMenuStyle.h"

namespace phonglab {

ThumbnailMenuStyle::ThumbnailMenuStyle(QObject *parent)
    : QProxyStyle() // the application's style underneath
{
    setParent(parent); // QWidget::setStyle() does not take ownership
}

int ThumbnailMenuStyle::pixelMetric(PixelMetric metric, const QStyleOption *option,
                                    const QWidget *widget) const
{
    if (metric == PM_SmallIconSize)
        return kIconSide;
    return QProxyStyle::pixelMetric(metric, option, widget);
}

} // namespace phonglab
