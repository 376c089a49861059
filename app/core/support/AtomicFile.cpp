#include "AtomicFile.h"

#include <QCoreApplication>
#include <QDir>
#include <QSaveFile>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct AtomicFileWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::AtomicFile)
};

Result<> writeFileAtomically(const QString &path, const QByteArray &bytes)
{
    QSaveFile file(path);
    if (file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size() && file.commit())
        return {};
    return fail(AtomicFileWords::tr("%1: cannot write: %2")
                    .arg(QDir::toNativeSeparators(path), file.errorString()));
}

} // namespace phonglab
