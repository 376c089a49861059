// Mesh files are parsed in a child process under limits: a reader that
// loads, fails, hangs, runs out of memory or crashes gives the same mesh or
// a clear message, and this process goes on. Cancel ends the child at once.
#include "ImportChildren.h"
#include "TestPaths.h"
#include "core/support/PhonglabExecutable.h"
#include "mesh/loading/MeshCache.h"
#include "mesh/loading/MeshImportProcess.h"
#include "mesh/loading/MeshLoader.h"

#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace phonglab;
using namespace phonglab::test;

class TestMeshImportProcess : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();

    void childGivesTheSameMeshAsInProcess();
    void secondOpenComesFromTheCache();
    void loadErrorIsTheReadersMessage();
    void hangingReaderIsStopped();
    void malformedPlyHeaderNeitherHangsNorGrows();
    void crashingReaderIsNamed();
    void readerOutOfMemoryIsNamed();
    void cancelEndsTheChildAtOnce();
    void missingExecutableIsAClearError();
    void limitsGrowWithTheFile();

private:
    // A private copy of `source`: a path the cache has never seen.
    QString freshCopy(const QString &source);

    QTemporaryDir m_dir;
    int m_copies = 0;
};

void TestMeshImportProcess::initTestCase()
{
    QVERIFY(m_dir.isValid());
    qputenv("PHONGLAB_CACHE_DIR", QFile::encodeName(m_dir.filePath(QStringLiteral("cache"))));
    QVERIFY2(!phonglabExecutable().isEmpty(), "no phonglab executable to import with");
}

void TestMeshImportProcess::init()
{
    qunsetenv("PHONGLAB_IMPORT_FAULT");
    qunsetenv("PHONGLAB_IMPORT_TIMEOUT_S");
    qunsetenv("PHONGLAB_IMPORT_MEMORY_MB");
}

void TestMeshImportProcess::cleanup()
{
    init();
    QVERIFY2(importChildren().isEmpty(), "an import child outlived its load");
}

QString TestMeshImportProcess::freshCopy(const QString &source)
{
    const QString suffix = source.mid(source.lastIndexOf(QLatin1Char('.')));
    const QString copy = m_dir.filePath(QStringLiteral("copy%1%2").arg(++m_copies).arg(suffix));
    if (!QFile::copy(source, copy))
        qFatal("cannot copy %s", qPrintable(source));
    return copy;
}

void TestMeshImportProcess::childGivesTheSameMeshAsInProcess()
{
    const QString path = freshCopy(sourcePath(QStringLiteral("assets/meshes/tree.obj")));
    const MeshLoadResult direct = importMeshFile(path);
    const MeshLoadResult isolated = loadMesh(path);
    QVERIFY2(isolated.ok(), qPrintable(isolated.error));
    QVERIFY(direct.ok());
    QVERIFY(!isolated.stats.fromCache);
    QVERIFY(isolated.mesh->positions == direct.mesh->positions);
    QVERIFY(isolated.mesh->normals == direct.mesh->normals);
    QVERIFY(isolated.mesh->indices == direct.mesh->indices);
    QCOMPARE(isolated.warnings, direct.warnings);
    QCOMPARE(isolated.stats.triangles, direct.stats.triangles);
    QCOMPARE(isolated.stats.normalsFromFile, direct.stats.normalsFromFile);
    QCOMPARE(isolated.stats.closed, direct.stats.closed);
}

void TestMeshImportProcess::secondOpenComesFromTheCache()
{
    const QString path = freshCopy(sourcePath(QStringLiteral("assets/meshes/cloud.obj")));
    const NormalOptions flat{NormalMethod::Flat, {}};
    QVERIFY(loadMesh(path, flat).ok());
    QVERIFY(QFile::exists(MeshCache::entryPath(path, flat)));
    // Cached: no child runs, even one that would crash.
    qputenv("PHONGLAB_IMPORT_FAULT", "crash");
    const MeshLoadResult again = loadMesh(path, flat);
    QVERIFY2(again.ok(), qPrintable(again.error));
    QVERIFY(again.stats.fromCache);
    QCOMPARE(again.stats.normalMethod, NormalMethod::Flat);
}

void TestMeshImportProcess::loadErrorIsTheReadersMessage()
{
    const QString path = freshCopy(testDataPath(QStringLiteral("meshes/bad/words.ply")));
    const MeshLoadResult direct = importMeshFile(path);
    const MeshLoadResult isolated = loadMesh(path);
    QVERIFY(!isolated.ok());
    QCOMPARE(isolated.error, direct.error);
    QVERIFY(isolated.error.startsWith(path));
}

void TestMeshImportProcess::hangingReaderIsStopped()
{
    qputenv("PHONGLAB_IMPORT_FAULT", "hang");
    qputenv("PHONGLAB_IMPORT_TIMEOUT_S", "1.5");
    const QString path = freshCopy(sourcePath(QStringLiteral("assets/meshes/tree.obj")));
    QElapsedTimer clock;
    clock.start();
    const MeshLoadResult r = loadMesh(path);
    qInfo("hanging reader stopped after %lld ms", clock.elapsed());
    QVERIFY(!r.ok());
    QVERIFY2(r.error.contains(QLatin1String("stopped answering after 1.5 s")), qPrintable(r.error));
    QVERIFY(!QFile::exists(MeshCache::entryPath(path, {})));
}

void TestMeshImportProcess::malformedPlyHeaderNeitherHangsNorGrows()
{
    // OpenMesh reads the version after 'format ascii' as a float; when that
    // fails its header loop never ends, logging all the while (it hung
    // `phonglab mesh-info` with memory growing by ~80 MB/s).
    qputenv("PHONGLAB_IMPORT_TIMEOUT_S", "3");
    const QString path =
        freshCopy(testDataPath(QStringLiteral("meshes/bad/ply_format_without_version.ply")));
    QElapsedTimer clock;
    clock.start();
    const MeshLoadResult r = loadMesh(path);
    qInfo("malformed PLY header: %lld ms, %s", clock.elapsed(), qPrintable(r.error));
    QVERIFY(!r.ok());
    QVERIFY(r.error.startsWith(path));
}

void TestMeshImportProcess::crashingReaderIsNamed()
{
    qputenv("PHONGLAB_IMPORT_FAULT", "crash");
    const QString path = freshCopy(sourcePath(QStringLiteral("assets/meshes/tree.obj")));
    const MeshLoadResult r = loadMesh(path);
    QVERIFY(!r.ok());
    QVERIFY2(r.error.contains(QLatin1String("crashed with signal 11 (SIGSEGV)")),
             qPrintable(r.error));
}

void TestMeshImportProcess::readerOutOfMemoryIsNamed()
{
#if defined(__SANITIZE_ADDRESS__)
    QSKIP("AddressSanitizer reserves terabytes of address space: no RLIMIT_AS in this build");
#endif
    qputenv("PHONGLAB_IMPORT_FAULT", "oom");
    qputenv("PHONGLAB_IMPORT_MEMORY_MB", "1024");
    const QString path = freshCopy(sourcePath(QStringLiteral("assets/meshes/tree.obj")));
    const MeshLoadResult r = loadMesh(path);
    QVERIFY(!r.ok());
    QVERIFY2(r.error.contains(QLatin1String("ran out of memory (limit 1024 MB)")),
             qPrintable(r.error));
}

void TestMeshImportProcess::cancelEndsTheChildAtOnce()
{
    qputenv("PHONGLAB_IMPORT_FAULT", "hang");
    const QString path = freshCopy(sourcePath(QStringLiteral("assets/meshes/tree.obj")));
    QElapsedTimer clock;
    qint64 childrenSeen = 0;
    const LoadProgress cancelWhenRunning = [&](double) {
        if (clock.isValid())
            return false;
        childrenSeen = importChildren().size();
        if (childrenSeen == 0)
            return true;
        clock.start(); // Cancel pressed now
        return false;
    };
    const MeshLoadResult r = loadMesh(path, {}, cancelWhenRunning);
    const qint64 cancelToReturnMs = clock.elapsed();
    qInfo("cancel to return: %lld ms", cancelToReturnMs);
    QCOMPARE(childrenSeen, 1);
    QCOMPARE(r.error, QStringLiteral("cancelled"));
    QVERIFY(importChildren().isEmpty()); // killed, not left to time out
}

void TestMeshImportProcess::missingExecutableIsAClearError()
{
    const QByteArray saved = qgetenv("PHONGLAB_EXE");
    qputenv("PHONGLAB_EXE", "/nonexistent/phonglab");
    const QString path = freshCopy(sourcePath(QStringLiteral("assets/meshes/tree.obj")));
    const MeshLoadResult r = loadMesh(path);
    saved.isNull() ? qunsetenv("PHONGLAB_EXE") : qputenv("PHONGLAB_EXE", saved);
    QVERIFY(!r.ok());
    QVERIFY2(r.error.contains(QLatin1String("cannot find the phonglab executable")),
             qPrintable(r.error));
}

void TestMeshImportProcess::limitsGrowWithTheFile()
{
    const MeshImportLimits small = MeshImportLimits::forFile(1000);
    const MeshImportLimits large = MeshImportLimits::forFile(qint64(500) << 20);
    QCOMPARE(small.wallClockMs, 30'000);
    QVERIFY(large.wallClockMs > small.wallClockMs);
    QVERIFY(large.addressSpaceBytes > small.addressSpaceBytes);
    QVERIFY(small.cpuSeconds * 1000 > small.wallClockMs);
    qputenv("PHONGLAB_IMPORT_TIMEOUT_S", "2.5");
    qputenv("PHONGLAB_IMPORT_MEMORY_MB", "300");
    const MeshImportLimits set = MeshImportLimits::forFile(1000);
    QCOMPARE(set.wallClockMs, 2500);
    QCOMPARE(set.addressSpaceBytes, qint64(300) << 20);
}

QTEST_GUILESS_MAIN(TestMeshImportProcess)
#include "tst_meshimportprocess.moc"
