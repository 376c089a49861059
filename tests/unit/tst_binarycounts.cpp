// Binary files whose counts and chunk headers lie: OpenMesh's OM and binary
// OFF readers and QDataStream believe them, asserting, allocating gigabytes
// or reading past the end (all found by fuzzing). The prechecks and the mesh
// cache decoder walk such files first and refuse them with a located
// message, quickly; files OpenMesh itself writes still load.
#include "MeshFiles.h"
#include "mesh/import/MeshFilePrecheck.h"
#include "mesh/import/MeshFileReader.h"
#include "mesh/loading/MeshCache.h"

#include <QBuffer>
#include <QTemporaryDir>
#include <QtEndian>
#include <QtTest>

using namespace phonglab;
using namespace phonglab::test;

class TestBinaryCounts : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void omCustomPropertiesAreSkipped();
    void omChunkHeadersAreChecked_data();
    void omChunkHeadersAreChecked();
    void omBytesAfterTheEndMarkerAreAWarning();
    void binaryOffFaceCornersAreBounded();
    void binaryOffWithColoursIsRefused();
    void meshCacheCountsAreBounded();

private:
    // The reference tetrahedron as OpenMesh writes it in binary OM.
    QByteArray omTetra();
    // Saves `bytes` as `name` and checks that reading it fails quickly
    // with an error containing `message`.
    void expectRefused(const QString &name, const QByteArray &bytes, const QString &message);

    QTemporaryDir m_dir;
};

QByteArray TestBinaryCounts::omTetra()
{
    return readBytes(writeTetra(m_dir, QStringLiteral("tetra.om"), true));
}

void TestBinaryCounts::expectRefused(const QString &name, const QByteArray &bytes,
                                     const QString &message)
{
    const QString path = m_dir.filePath(name);
    writeBytes(path, bytes);
    const MeshReadResult r = readMeshFile(path);
    QVERIFY(!r.ok());
    QVERIFY2(r.error.contains(message), qPrintable(r.error));
}

void TestBinaryCounts::omCustomPropertiesAreSkipped()
{
    // A persistent property of a known type is read into the reader's
    // kernel, which has no vertices in our importer: OpenMesh asserts that
    // the block it read is as large as the property (zero) and aborts.
    TriMesh m = referenceTetra();
    OpenMesh::VPropHandleT<float> weight;
    m.add_property(weight, "weight");
    m.property(weight).set_persistent(true);
    OpenMesh::FPropHandleT<int> label;
    m.add_property(label, "label");
    m.property(label).set_persistent(true);
    for (auto v : m.vertices())
        m.property(weight, v) = 0.5f;
    for (auto f : m.faces())
        m.property(label, f) = f.idx();
    const QString path = m_dir.filePath(QStringLiteral("custom.om"));
    QVERIFY(writeMesh(m, path, OpenMesh::IO::Options::Binary));

    const MeshFilePrecheck check = precheckMeshFile(path, MeshFileFormat::Om);
    QVERIFY2(check.ok(), qPrintable(check.error));
    QVERIFY(!check.rewritten.empty());
    QVERIFY(qint64(check.rewritten.size()) < check.fileSize);
    const MeshReadResult r = readMeshFile(path);
    QVERIFY2(r.ok(), qPrintable(r.error));
    QCOMPARE(r.mesh->positions.size(), std::size_t(4));
    QCOMPARE(r.mesh->faceCount(), std::size_t(4));
}

void TestBinaryCounts::omChunkHeadersAreChecked_data()
{
    // The first chunk OpenMesh writes, at byte 16, holds the vertex
    // positions: 16 header bits, dimension - 1 in bits 11-13, the element
    // kind in bits 2-4. Header counts at bytes 4 (vertices) and 12 (edges).
    QTest::addColumn<int>("at");
    QTest::addColumn<quint32>("clear");
    QTest::addColumn<quint32>("set");
    QTest::addColumn<int>("width");
    QTest::addColumn<QString>("message");
    QTest::newRow("positions with two components")
        << 16 << (7u << 11) << (1u << 11) << 2
        << "chunk 1 (byte 16): a vertex positions chunk with 2 components per element, where the "
           "reader expects 3";
    QTest::newRow("positions with eight components")
        << 16 << (7u << 11) << (7u << 11) << 2
        << "chunk 1 (byte 16): a vertex positions chunk with 8 components";
    QTest::newRow("an unknown kind of element")
        << 16 << (7u << 2) << (3u << 2) << 2
        << "chunk 1 (byte 16): a chunk for an unknown kind of element (3)";
    QTest::newRow("positions in long doubles")
        << 16 << (3u << 14) << (2u << 14) << 2 << "a number size the reader does not know";
    QTest::newRow("a million edges")
        << 12 << 0xffffffffu << 1000000u << 4 << "halfedge topology) needs";
}

void TestBinaryCounts::omChunkHeadersAreChecked()
{
    QFETCH(int, at);
    QFETCH(quint32, clear);
    QFETCH(quint32, set);
    QFETCH(int, width);
    QFETCH(QString, message);
    QByteArray bytes = omTetra();
    QVERIFY(bytes.size() > 32);
    if (width == 2)
        qToLittleEndian<quint16>(
            quint16((qFromLittleEndian<quint16>(bytes.constData() + at) & ~clear) | set),
            bytes.data() + at);
    else
        qToLittleEndian<quint32>(
            (qFromLittleEndian<quint32>(bytes.constData() + at) & ~clear) | set, bytes.data() + at);
    expectRefused(QStringLiteral("changed.om"), bytes, message);
}

void TestBinaryCounts::omBytesAfterTheEndMarkerAreAWarning()
{
    const QString path = m_dir.filePath(QStringLiteral("trailing.om"));
    writeBytes(path, omTetra() + QByteArray(7, 'x'));
    const MeshReadResult r = readMeshFile(path);
    QVERIFY2(r.ok(), qPrintable(r.error));
    QVERIFY2(r.warnings.contains(QStringLiteral("7 bytes after the end marker were ignored")),
             qPrintable(r.warnings.join("; ")));
}

void TestBinaryCounts::binaryOffFaceCornersAreBounded()
{
    // OpenMesh grows a face's index list one read at a time for as many
    // corners as the face says, past the end of the file: 10^9 of them took
    // gigabytes.
    QByteArray bytes = readBytes(writeTetra(m_dir, QStringLiteral("tetra_binary.off"), true));
    const qsizetype body = bytes.indexOf('\n') + 1;
    QVERIFY(body > 0);
    QCOMPARE(qFromLittleEndian<quint32>(bytes.constData() + body), 4u); // vertices
    const qsizetype firstFace = body + 12 + 4 * 12;
    QCOMPARE(qFromLittleEndian<quint32>(bytes.constData() + firstFace), 3u);
    qToLittleEndian<quint32>(1000000000u, bytes.data() + firstFace);
    expectRefused(
        QStringLiteral("corners.off"), bytes,
        QStringLiteral("binary OFF face 1 (byte %1) declares 1000000000 corners").arg(firstFace));
}

void TestBinaryCounts::binaryOffWithColoursIsRefused()
{
    QByteArray bytes("COFF BINARY\n");
    for (quint32 count : {3u, 1u, 0u}) {
        QByteArray word(4, '\0');
        qToLittleEndian<quint32>(count, word.data());
        bytes += word;
    }
    bytes += QByteArray(200, '\0');
    const QString path = m_dir.filePath(QStringLiteral("colours.off"));
    writeBytes(path, bytes);
    const MeshReadResult r = readMeshFile(path);
    QVERIFY(!r.ok());
    QVERIFY2(r.error.contains(
                 "binary COFF files (with colours or texture coordinates) are not supported"),
             qPrintable(r.error));
}

void TestBinaryCounts::meshCacheCountsAreBounded()
{
    // The import child hands meshes back in the cache format; a corrupt
    // list count made QDataStream reserve ~25 GB. Linux may grant that
    // untouched here; under the fuzzers' malloc limit (scripts/fuzz.sh
    // --replay of tests/data/fuzz/meshcache) and the import child's
    // address-space limit it is a crash, which that replay shows.
    MeshLoadResult result;
    result.mesh =
        MeshData{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}}, {0, 1, 2}};
    result.warnings = QStringList{QStringLiteral("w")};
    QBuffer buffer;
    QVERIFY(buffer.open(QIODevice::ReadWrite));
    QVERIFY(MeshCache::encode(buffer, "key", result));
    QByteArray bytes = buffer.data();
    QBuffer whole(&bytes);
    QVERIFY(whole.open(QIODevice::ReadOnly));
    const std::optional<MeshLoadResult> decoded = MeshCache::decode(whole, std::nullopt);
    QVERIFY(decoded && decoded->warnings == result.warnings);

    // The list: a 32-bit count, then each string as its byte length and UTF-16.
    const qsizetype string = bytes.indexOf(QByteArray("\0\0\0\2\0w", 6));
    QVERIFY(string > 4);
    qToBigEndian<quint32>(1000000000u, bytes.data() + string - 4);
    QBuffer corrupt(&bytes);
    QVERIFY(corrupt.open(QIODevice::ReadOnly));
    QVERIFY(MeshCache::decode(corrupt, std::nullopt) == std::nullopt);
}

QTEST_GUILESS_MAIN(TestBinaryCounts)
#include "tst_binarycounts.moc"
