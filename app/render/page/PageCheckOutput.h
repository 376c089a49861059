#pragma once
#include "PageCheck.h"

#include <QJsonObject>
#include <QStringList>

namespace phonglab {

// The JSON "page" object: {file, webgl, frame, animated, canvas,
// milliseconds, steps, served, refused, errors, console_errors, fidelity,
// javascript, own_scene}; and the same as text lines.
QJsonObject pageJson(const PageCheck &check);
QStringList pageText(const PageCheck &check);

} // namespace phonglab
