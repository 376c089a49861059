#pragma once
#include "Result.h"

#include <QByteArray>
#include <QString>

namespace phonglab {

// Writes `bytes` to `path` as a whole or not at all (QSaveFile: a new file
// renamed over the old one), so that a reader, a crash or a full disk never
// leaves half a file where the user's was. Fails with
// "<path>: cannot write: <reason>".
Result<> writeFileAtomically(const QString &path, const QByteArray &bytes);

} // namespace phonglab
