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

namespace {

ProcessRun run(QProcess &p, const QStringList &args, int timeoutMs)
{
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

} // namespace

ProcessRun runPhonglab(const QStringList &args, int timeoutMs)
{
    QProcess p;
    return run(p, args, timeoutMs);
}

ProcessRun runPhonglabUnderLocale(const QStringList &args, const QString &lang, int timeoutMs)
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (const char *name : {"LANGUAGE", "LC_ALL", "LC_MESSAGES"})
        env.remove(QString::fromLatin1(name));
    env.insert(QStringLiteral("LANG"), lang);
    return runPhonglabIn(env, args, timeoutMs);
}

ProcessRun runPhonglabIn(const QProcessEnvironment &env, const QStringList &args, int timeoutMs)
{
    QProcess p;
    p.setProcessEnvironment(env);
    return run(p, args, timeoutMs);
}

} // namespace phonglab::test
