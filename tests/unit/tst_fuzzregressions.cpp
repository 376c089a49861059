// Every input a fuzzer ever found (tests/data/fuzz/<target>/) and every seed
// (tests/fuzz/corpus/<target>/) goes once more through the fuzz target's
// own entry point (../fuzz/FuzzEntry.h), in an ordinary build: what crashed,
// hung or ran out of memory once must now end, quickly, with a mesh or a
// message. A broken promise of an entry point aborts, failing this test.
#include "../fuzz/FuzzEntry.h"
#include "TestPaths.h"

#include <QDirIterator>
#include <QFile>
#include <QTest>

using namespace phonglab;

class TestFuzzRegressions : public QObject
{
    Q_OBJECT

private slots:
    void everyTargetHasSeeds();
    void inputReadsOrIsRefused_data();
    void inputReadsOrIsRefused();
    void foundPlyHeadersAreRefusedWithALocatedError();
};

namespace {

QString fuzzDataDir(const QString &kind, const QString &target)
{
    return kind == QLatin1String("seed")
        ? QStringLiteral(PHONGLAB_SOURCE_DIR "/tests/fuzz/corpus/") + target
        : QStringLiteral(PHONGLAB_TEST_DATA_DIR "/fuzz/") + target;
}

QStringList filesUnder(const QString &dir)
{
    QStringList files;
    QDirIterator it(dir, QDir::Files);
    while (it.hasNext())
        files << it.next();
    files.sort();
    return files;
}

QByteArray contents(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

} // namespace

void TestFuzzRegressions::everyTargetHasSeeds()
{
    for (const QString &target : fuzz::targetNames())
        QVERIFY2(!filesUnder(fuzzDataDir(QStringLiteral("seed"), target)).isEmpty(),
                 qPrintable(target));
}

void TestFuzzRegressions::inputReadsOrIsRefused_data()
{
    QTest::addColumn<QString>("target");
    QTest::addColumn<QString>("path");
    for (const QString &target : fuzz::targetNames())
        for (const QString &kind : {QStringLiteral("found"), QStringLiteral("seed")})
            for (const QString &path : filesUnder(fuzzDataDir(kind, target)))
                QTest::newRow(qPrintable(
                    QStringLiteral("%1 %2 %3").arg(target, kind, QFileInfo(path).fileName())))
                    << target << path;
}

void TestFuzzRegressions::inputReadsOrIsRefused()
{
    QFETCH(QString, target);
    QFETCH(QString, path);
    const QByteArray bytes = contents(path);
    QVERIFY2(!bytes.isEmpty() || QFileInfo(path).size() == 0, qPrintable(path));
    // An input that once crashed, hung or ran slow: it now reads, or is
    // refused with a message. (Speed is the fuzzers' business: they stop an
    // input at 10 s; scripts/fuzz.sh --replay runs these under that limit.)
    const fuzz::Outcome outcome = fuzz::run(target.toStdString(), bytes);
    QVERIFY(outcome.ok || !outcome.error.isEmpty());
}

void TestFuzzRegressions::foundPlyHeadersAreRefusedWithALocatedError()
{
    // Each made OpenMesh's PLY header loop spin forever, logging (one grew
    // past 2 GB): a format line whose version does not read as a number, a
    // header word with control bytes in it.
    const QStringList found =
        filesUnder(fuzzDataDir(QStringLiteral("found"), QStringLiteral("ply")));
    QVERIFY(found.size() >= 3);
    for (const QString &path : found) {
        const fuzz::Outcome outcome = fuzz::run("ply", contents(path));
        QVERIFY2(!outcome.ok, qPrintable(path));
        QVERIFY2(outcome.error.contains(QLatin1String("PLY header line 2: expected 'format"))
                     || outcome.error.contains(
                         QLatin1String("PLY header line 3: byte 0x01 at column 10 is not text")),
                 qPrintable(outcome.error));
    }
}

QTEST_GUILESS_MAIN(TestFuzzRegressions)
#include "tst_fuzzregressions.moc"
