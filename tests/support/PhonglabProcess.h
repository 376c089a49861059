#pragma once
#include <QByteArray>
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

} // namespace phonglab::test
