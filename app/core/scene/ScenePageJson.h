#pragma once
#include "PageSettings.h"
#include "core/support/Result.h"

#include <QJsonValue>
#include <QString>

namespace phonglab::scenejson {

// The scene's "page": {"steps": [STEP, ...], "libraries": [DIR, ...],
// "meshes": DIR, "frame": N} (core/scene/PageSettings.h); every error
// located ("page.steps[1]: expected a string (got number)").
Result<PageSettings> readPageSettings(const QJsonValue &value, const QString &path);
QJsonValue pageSettingsJson(const PageSettings &settings);

} // namespace phonglab::scenejson
