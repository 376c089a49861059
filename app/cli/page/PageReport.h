#pragma once
#include "render/page/PageCheck.h"

#include <QString>

namespace phonglab::cli {

// `check --page` without a scene (or a page that could not be run): the
// page's own findings printed, as text or JSON; the exit code.
int reportPageAlone(const PageCheck &check, bool json, const QString &note);

} // namespace phonglab::cli
