#pragma once
#include <QString>

namespace phonglab {

// The normal-method study of `phonglab bench --normals`: runs
// runNormalStudy(), prints its table and writes normals.csv, normals.png
// and normals.svg into `outDir`. False with a reason when a file cannot be
// written.
bool writeNormalStudy(const QString &outDir, QString *error);

} // namespace phonglab
