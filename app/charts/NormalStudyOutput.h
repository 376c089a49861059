#pragma once
#include "core/support/Result.h"
#include <QString>

namespace phonglab {

// The normal-method study of `phonglab bench --normals`: runs
// runNormalStudy(), prints its table and writes normals.csv, normals.png
// and normals.svg into `outDir`. False with a reason when a file cannot be
// written.
Result<> writeNormalStudy(const QString &outDir);

} // namespace phonglab
