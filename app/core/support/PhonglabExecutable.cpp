#include "PhonglabExecutable.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

namespace phonglab {

QString phonglabExecutable()
{
    const QString fromEnv = qEnvironmentVariable("PHONGLAB_EXE");
    if (!fromEnv.isEmpty())
        return QFileInfo(fromEnv).isExecutable() ? fromEnv : QString();
    const QFileInfo self(QFile::symLinkTarget(QStringLiteral("/proc/self/exe")));
    if (self.fileName() == QLatin1String("phonglab"))
        return self.absoluteFilePath();
    const QFileInfo beside(self.absoluteDir().filePath(QStringLiteral("phonglab")));
    if (beside.isExecutable())
        return beside.absoluteFilePath();
#ifdef PHONGLAB_BUILD_EXE
    if (QFileInfo(QStringLiteral(PHONGLAB_BUILD_EXE)).isExecutable())
        return QStringLiteral(PHONGLAB_BUILD_EXE);
#endif
    return {};
}

} // namespace phonglab
