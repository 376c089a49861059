#include "QtImages.h"

#include <algorithm>

namespace phonglab {

RgbImage toRgbImage(const QImage &image)
{
    if (image.isNull())
        return {};
    const QImage rgb = image.format() == QImage::Format_RGB888
        ? image
        : image.convertToFormat(QImage::Format_RGB888);
    RgbImage out(rgb.width(), rgb.height());
    const std::size_t rowBytes = 3 * std::size_t(out.width);
    // QImage pads rows to 4 bytes; RgbImage's rows are packed.
    for (int y = 0; y < out.height; ++y)
        std::copy_n(rgb.constScanLine(y), rowBytes, out.pixel(0, y));
    return out;
}

QImage toQImage(const RgbImage &image)
{
    if (image.isNull())
        return {};
    QImage out(image.width, image.height, QImage::Format_RGB888);
    const std::size_t rowBytes = 3 * std::size_t(image.width);
    for (int y = 0; y < image.height; ++y)
        std::copy_n(image.pixel(0, y), rowBytes, out.scanLine(y));
    return out;
}

} // namespace phonglab
