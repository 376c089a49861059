#pragma once
#include <QImage>
#include <qpa/qplatformbackingstore.h>

namespace phonglab::headless {

// Widgets paint into an image that is never shown: enough for a widget that
// is drawn into a picture (QWidget::grab) on the headless platform.
class HeadlessBackingStore : public QPlatformBackingStore
{
public:
    using QPlatformBackingStore::QPlatformBackingStore;

    QPaintDevice *paintDevice() override { return &m_image; }
    void resize(const QSize &size, const QRegion &) override
    {
        if (m_image.size() != size)
            m_image = QImage(size, QImage::Format_ARGB32_Premultiplied);
    }
    void flush(QWindow *, const QRegion &, const QPoint &) override { }
    QImage toImage() const override { return m_image; }

private:
    QImage m_image;
};

} // namespace phonglab::headless
