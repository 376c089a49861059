// How the real executable starts as a desktop program: without a display it
// says so and exits 1 (no Qt abort), and `phonglab --version` is the
// project's version, the one the package carries.
#include "PhonglabProcess.h"
#include "TestPaths.h"

#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTest>

using namespace phonglab::test;

class TestGuiStartup : public QObject
{
    Q_OBJECT

private slots:
    void withoutADisplayExplainsAndExits();
    void versionIsTheProjectVersion();
};

void TestGuiStartup::withoutADisplayExplainsAndExits()
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (const char *name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"})
        env.remove(QString::fromLatin1(name));
    QProcess process;
    process.setProcessEnvironment(env);
    process.start(phonglabExecutable(), {});
    QVERIFY(process.waitForFinished(60000));
    QCOMPARE(process.exitStatus(), QProcess::NormalExit); // not an abort
    QCOMPARE(process.exitCode(), 1);
    const QString err = QString::fromLocal8Bit(process.readAllStandardError());
    QVERIFY2(err.startsWith(QStringLiteral("phonglab: the editor window needs a display (X11 or "
                                           "Wayland), and DISPLAY is not set.")),
             qPrintable(err));
    QVERIFY2(err.contains(QStringLiteral("render, check, grade, mesh-info and bench")),
             qPrintable(err));
    QVERIFY2(!err.contains(QStringLiteral("qt.qpa")), qPrintable(err)); // Qt never got to try
}

void TestGuiStartup::versionIsTheProjectVersion()
{
    QFile lists(sourcePath(QStringLiteral("CMakeLists.txt")));
    QVERIFY(lists.open(QIODevice::ReadOnly | QIODevice::Text));
    const QRegularExpressionMatch project =
        QRegularExpression(QStringLiteral(R"(project\(\s*PhongLab\s+VERSION\s+([0-9.]+))"))
            .match(QString::fromUtf8(lists.readAll()));
    QVERIFY(project.hasMatch());

    const ProcessRun run = runPhonglab({QStringLiteral("--version")});
    QCOMPARE(run.exitCode, 0);
    QCOMPARE(QString::fromUtf8(run.out).trimmed(),
             QStringLiteral("phonglab ") + project.captured(1));
}

QTEST_GUILESS_MAIN(TestGuiStartup)
#include "tst_guistartup.moc"
