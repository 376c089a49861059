#pragma once
#include "core/support/RgbImage.h"

#include <QImage>

namespace phonglab {

// Between Qt's images (grabbed framebuffers, PNG files, widgets) and core's
// RgbImage (what the reference and the checks compare). Any QImage format
// converts; a null image gives a null RgbImage and back.
RgbImage toRgbImage(const QImage &image);
QImage toQImage(const RgbImage &image);

} // namespace phonglab
