#include "ImportChildren.h"

#include <QDir>
#include <QFile>

#include <unistd.h>

namespace phonglab::test {

QList<qint64> importChildren()
{
    QList<qint64> pids;
    const QByteArray self = QByteArray::number(qint64(::getpid()));
    const QStringList entries =
        QDir(QStringLiteral("/proc")).entryList(QDir::Dirs | QDir::NoDotAndDotDot);
    for (const QString &entry : entries) {
        bool numeric = false;
        const qint64 pid = entry.toLongLong(&numeric);
        if (!numeric)
            continue;
        QFile stat(QStringLiteral("/proc/%1/stat").arg(pid));
        QFile cmdline(QStringLiteral("/proc/%1/cmdline").arg(pid));
        if (!stat.open(QIODevice::ReadOnly) || !cmdline.open(QIODevice::ReadOnly))
            continue;
        // "pid (comm) state ppid ...": comm may hold spaces, so split after ')'.
        const QByteArray line = stat.readAll();
        const QList<QByteArray> fields = line.mid(line.lastIndexOf(')') + 2).split(' ');
        if (fields.size() > 1 && fields[0] != "Z" && fields[1] == self
            && cmdline.readAll().contains("__import-mesh"))
            pids << pid;
    }
    return pids;
}

} // namespace phonglab::test
