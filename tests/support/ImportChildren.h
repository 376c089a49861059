#pragma once
#include <QList>

namespace phonglab::test {

// Process ids of this process's children that run `phonglab __import-mesh`
// (read from /proc): what must be gone once an import ends or is cancelled.
QList<qint64> importChildren();

} // namespace phonglab::test
