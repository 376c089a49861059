#pragma once
#include "HeadlessPlatform.h"

#include <QRect>
#include <qpa/qplatformscreen.h>

namespace phonglab::headless {

// The one screen of the headless platform: nothing is shown on it, but Qt
// needs a screen for fonts, DPI and widgets that are drawn into images (the
// bench's charts).
class HeadlessScreen : public QPlatformScreen
{
public:
    QRect geometry() const override { return {0, 0, 1920, 1080}; }
    int depth() const override { return 32; }
    QImage::Format format() const override { return QImage::Format_ARGB32_Premultiplied; }
    QDpi logicalDpi() const override { return {96, 96}; }
    QDpi logicalBaseDpi() const override { return {96, 96}; }
    QString name() const override { return QLatin1String(kHeadlessPlatformName); }
};

} // namespace phonglab::headless
