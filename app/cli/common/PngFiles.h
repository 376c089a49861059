#pragma once
#include "core/support/Result.h"

#include <QImage>
#include <QString>

namespace phonglab::cli {

// Writes a PNG that appears only once complete.
Result<> writePng(const QImage &image, const QString &path);
// Why `path`, given to `option`, cannot name the PNG a command writes: a
// suffix that names another image format (`-o out.jpg`) would put PNG data
// under a JPEG's name. Empty when it can (.png, no suffix, or a suffix no
// image format uses).
QString pngNameProblem(const QString &option, const QString &path);

} // namespace phonglab::cli
