#include "DocumentView.h"

#include <QImage>
#include <QTextDocument>

namespace phonglab {

DocumentView::DocumentView(QWidget *parent)
    : QTextBrowser(parent)
{
}

QVariant DocumentView::loadResource(int type, const QUrl &name)
{
    const QVariant loaded = QTextBrowser::loadResource(type, name);
    if (type != QTextDocument::ImageResource)
        return loaded;
    // A file comes back as its bytes; the document would decode it at full size.
    QImage image = loaded.userType() == QMetaType::QImage ? loaded.value<QImage>()
                                                          : QImage::fromData(loaded.toByteArray());
    const qreal ratio = devicePixelRatioF(); // sharp on a high-density screen
    const int widest = qRound(kMaxImageWidth * ratio);
    if (image.isNull() || image.width() <= widest)
        return loaded;
    image = image.scaledToWidth(widest, Qt::SmoothTransformation);
    image.setDevicePixelRatio(ratio);
    return image;
}

} // namespace phonglab
