#pragma once
#include <QImage>
#include <QRgb>

#include <cstdlib>

namespace phonglab::test {

// Whether two colours differ by more than `tolerance` 8-bit steps in any channel.
inline bool differsFrom(QRgb a, QRgb b, int tolerance)
{
    return std::abs(qRed(a) - qRed(b)) > tolerance || std::abs(qGreen(a) - qGreen(b)) > tolerance
        || std::abs(qBlue(a) - qBlue(b)) > tolerance;
}

// Pixels of two frames that differ by more than 2 steps (every pixel when the
// sizes differ): "did the picture change", for UI tests that compare frames.
inline qint64 differingPixels(const QImage &a, const QImage &b)
{
    const QImage x = a.convertToFormat(QImage::Format_RGB32);
    const QImage y = b.convertToFormat(QImage::Format_RGB32);
    if (x.size() != y.size())
        return qint64(x.width()) * x.height();
    qint64 count = 0;
    for (int row = 0; row < x.height(); ++row)
        for (int col = 0; col < x.width(); ++col)
            count += differsFrom(x.pixel(col, row), y.pixel(col, row), 2);
    return count;
}

} // namespace phonglab::test
