#pragma once
#include <QByteArray>
#include <QProcessEnvironment>
#include <QString>
#include <QStringList>

namespace phonglab::test {

// One run of the real `phonglab` executable, as a script sees it.
struct ProcessRun {
    int exitCode = -1; // -1: did not finish in time, -2: crashed
    QByteArray out;
    QString err;
};

// The phonglab binary: $PHONGLAB_EXE, else the path the build defines for
// tests that depend on it, else <build>/app/phonglab beside <build>/tests.
QString phonglabExecutable();

ProcessRun runPhonglab(const QStringList &args, int timeoutMs = 120000);
// The same under the locale `lang` (LANG=lang; LANGUAGE, LC_ALL and
// LC_MESSAGES removed), as a user of that desktop starts it.
ProcessRun runPhonglabUnderLocale(const QStringList &args, const QString &lang,
                                  int timeoutMs = 120000);
// The same in the environment `env`.
ProcessRun runPhonglabIn(const QProcessEnvironment &env, const QStringList &args,
                         int timeoutMs = 120000);

} // namespace phonglab::test
