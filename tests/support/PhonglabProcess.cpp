#include "PhonglabProcess.h"

#include <QCoreApplication>
#include <QProcess>

namespace phonglab::test {

QString phonglabExecutable()
{
    const QString fromEnv = qEnvironmentVariable("PHONGLAB_EXE");
    if (!fromEnv.isEmpty())
        return fromEnv;
    // Tests build into <build>/tests, the application into <build>/app.
    return QCoreApplication::applicationDirPath() + QStringLiteral("/../app/phonglab");
}

ProcessRun runPhonglab(const QStringList &args, int timeoutMs)
{
    QProcess p;
    p.start(phonglabExecutable(), args);
    if (!p.waitForFinished(timeoutMs)) {
        p.kill();
        p.waitForFinished();
        return {};
    }
    ProcessRun r;
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2;
    r.out = p.readAllStandardOutput();
    r.err = QString::fromLocal8Bit(p.readAllStandardError());
    return r;
}

} // namespace phonglab::test
