#include "RuntimeDirectory.h"

#include <QByteArray>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QString>

#include <cerrno>
#include <pwd.h>
#include <sys/stat.h>
#include <unistd.h>

namespace phonglab {

namespace {

// Qt's own choice (qstandardpaths_unix.cpp): the user's name, else the uid.
QString userName()
{
    if (const passwd *entry = getpwuid(geteuid()); entry && entry->pw_name)
        return QFile::decodeName(QByteArray(entry->pw_name));
    return QString::number(geteuid());
}

} // namespace

void provideRuntimeDirectory()
{
    if (!qEnvironmentVariableIsEmpty("XDG_RUNTIME_DIR"))
        return;
    const QString path = QDir::tempPath() + QStringLiteral("/runtime-") + userName();
    const QByteArray native = QFile::encodeName(path);
    if (::mkdir(native.constData(), 0700) != 0 && errno != EEXIST)
        return;
    struct stat info {
    };
    if (::lstat(native.constData(), &info) != 0 || !S_ISDIR(info.st_mode)
        || info.st_uid != geteuid() || (info.st_mode & 0777) != 0700)
        return; // Qt says what is wrong with it
    qputenv("XDG_RUNTIME_DIR", native);
}

} // namespace phonglab
