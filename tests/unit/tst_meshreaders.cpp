#include "mesh/import/MeshFilePrecheck.h"
#include "mesh/import/MeshFileReader.h"
#include "mesh/import/MeshRepair.h"
#include "mesh/import/ObjReader.h"

#include "MeshFiles.h"

#include <QFile>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QtEndian>
#include <QtTest>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

using namespace phonglab;
using namespace phonglab::test;

namespace {

const QString kFormats = QStringLiteral(PHONGLAB_TEST_DATA_DIR "/meshes/formats/");
const QString kBad = QStringLiteral(PHONGLAB_TEST_DATA_DIR "/meshes/bad/");

// What the app does with a file: read, repair, refuse an empty result.
struct Loaded {
    std::optional<PolygonMesh> mesh;
    QString error;
    QStringList warnings;
};

Loaded load(const QString &path)
{
    MeshReadResult read = readMeshFile(path);
    Loaded out{std::nullopt, read.error, read.warnings};
    if (read.ok()) {
        out.warnings += repairMesh(*read.mesh).warnings();
        if (read.mesh->faceCount() == 0)
            out.error = QStringLiteral("no usable faces");
        else
            out.mesh = std::move(read.mesh);
    }
    return out;
}

bool anyContains(const QStringList &lines, const QString &text)
{
    return std::any_of(lines.begin(), lines.end(),
                       [&](const QString &l) { return l.contains(text); });
}

// Faces as position loops, each started at its smallest position, sorted:
// comparable across formats that number vertices differently (STL).
using Point = std::array<float, 3>;
std::vector<std::vector<Point>> canonicalFaces(const PolygonMesh &m)
{
    std::vector<std::vector<Point>> faces;
    for (std::size_t f = 0; f < m.faceCount(); ++f) {
        std::vector<Point> loop;
        for (std::uint32_t c = m.faceStart[f]; c < m.faceStart[f + 1]; ++c) {
            const glm::vec3 p = m.positions[m.cornerPosition[c]];
            loop.push_back({p.x, p.y, p.z});
        }
        std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
        faces.push_back(loop);
    }
    std::sort(faces.begin(), faces.end());
    return faces;
}

// A binary STL whose header starts with "solid", as many exporters write
// it, with zero facet normals (which means "compute them").
QByteArray binaryStl(const std::vector<std::array<glm::vec3, 3>> &triangles)
{
    QByteArray bytes = QByteArray("solid exported").leftJustified(80, ' ');
    QByteArray count(4, '\0');
    qToLittleEndian<quint32>(quint32(triangles.size()), count.data());
    bytes += count;
    for (const auto &t : triangles) {
        const float values[12] = {0,      0,      0,      t[0].x, t[0].y, t[0].z,
                                  t[1].x, t[1].y, t[1].z, t[2].x, t[2].y, t[2].z};
        bytes.append(reinterpret_cast<const char *>(values), sizeof values);
        bytes.append(2, '\0');
    }
    return bytes;
}

} // namespace

class TestMeshReaders : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    // --- every format reads the same tetrahedron
    void formatsReadTheSameTetrahedron_data();
    void formatsReadTheSameTetrahedron();

    // --- OBJ specifics
    void objKeepsPolygons();
    void objKeepsPerCornerNormals();
    void objRelativeIndices();
    void objCornerFormsAndContinuations();
    void objByteOrderMarkAndTrailingComments();
    void objNumbersMatchFromChars();
    void objProgressAndCancel();
    void objLargeFileParsedInHalves_data();
    void objLargeFileParsedInHalves();

    // --- bad input
    void rejected_data();
    void rejected();
    void unreadableFile();
    void randomBytesRejected_data();
    void randomBytesRejected();
    void hugeVertexCountIsRefusedBeforeParsing();
    void plyFormatLineMustCarryAVersion_data();
    void plyFormatLineMustCarryAVersion();
    void plyHeaderMustBeText_data();
    void plyHeaderMustBeText();
    void binaryTruncated_data();
    void binaryTruncated();
    void objCutAnywhereNeverCrashes();
    void objCutMidLineLoadsWithWarning();
    void repairedOnLoad_data();
    void repairedOnLoad();
    void stlDropsAreCounted();
    void binaryPlyNonFinite();
    void openMeshMessagesBecomeTheError();
    void openMeshProgressAndCancel();
};

void TestMeshReaders::formatsReadTheSameTetrahedron_data()
{
    QTest::addColumn<QString>("path");
    QTest::newRow("obj") << kFormats + "tetra.obj";
    QTest::newRow("obj, every corner form") << kFormats + "corner_forms.obj";
    QTest::newRow("ply ascii") << kFormats + "tetra_ascii.ply";
    QTest::newRow("off") << kFormats + "tetra.off";
    QTest::newRow("off, comments and glued counts") << kFormats + "tetra_commented.off";
    QTest::newRow("stl ascii") << kFormats + "tetra_ascii.stl";
    QTest::newRow("ply ascii, written") << writeTetra(m_dir, "w_ascii.ply", false);
    QTest::newRow("ply binary, written") << writeTetra(m_dir, "w_binary.ply", true);
    QTest::newRow("off, written") << writeTetra(m_dir, "w.off", false);
    QTest::newRow("off binary, written") << writeTetra(m_dir, "w_binary.off", true);
    const QString countsOnHeader = m_dir.filePath("counts_on_header.off");
    writeBytes(countsOnHeader,
               "OFF 4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
    QTest::newRow("off, counts on the header line") << countsOnHeader;
    QTest::newRow("stl ascii, written") << writeTetra(m_dir, "w_ascii.stl", false);
    QTest::newRow("stl binary, written") << writeTetra(m_dir, "w_binary.stl", true);
    QTest::newRow("om, written") << writeTetra(m_dir, "w.om", true);
    QTest::newRow("upper-case suffix") << writeTetra(m_dir, "W_UPPER.PLY", true);
}

void TestMeshReaders::formatsReadTheSameTetrahedron()
{
    QFETCH(QString, path);
    QVERIFY(!path.isEmpty());
    const MeshReadResult r = readMeshFile(path);
    QVERIFY2(r.ok(), qPrintable(r.error));
    PolygonMesh mesh = *r.mesh;
    QCOMPARE(mesh.positions.size(), std::size_t(4));
    QCOMPARE(mesh.faceCount(), std::size_t(4));

    PolygonMesh reference;
    reference.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    reference.cornerPosition = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    reference.faceStart = {0, 3, 6, 9, 12};
    QVERIFY(canonicalFaces(mesh) == canonicalFaces(reference));

    // A clean file needs no repair.
    const RepairReport report = repairMesh(mesh);
    QVERIFY2(report.warnings().isEmpty(), qPrintable(report.warnings().join("; ")));
}

void TestMeshReaders::objKeepsPolygons()
{
    const Loaded l = load(kFormats + "quad_pentagon.obj");
    QVERIFY2(l.mesh, qPrintable(l.error));
    QVERIFY2(l.warnings.isEmpty(), qPrintable(l.warnings.join("; ")));
    QCOMPARE(l.mesh->faceCount(), std::size_t(2));
    QCOMPARE(l.mesh->cornerCount(0), std::size_t(4));
    QCOMPARE(l.mesh->cornerCount(1), std::size_t(5));
    QVERIFY(!l.mesh->hasNormals());
}

void TestMeshReaders::objKeepsPerCornerNormals()
{
    const MeshReadResult r = readMeshFile(kFormats + "cube_flat_normals.obj");
    QVERIFY2(r.ok(), qPrintable(r.error));
    QVERIFY2(r.warnings.isEmpty(), qPrintable(r.warnings.join("; ")));
    const PolygonMesh &m = *r.mesh;
    QCOMPARE(m.positions.size(), std::size_t(8));
    QCOMPARE(m.normals.size(), std::size_t(6));
    QCOMPARE(m.faceCount(), std::size_t(6));
    QVERIFY(m.hasNormals());
    // Each face's corners use that face's normal, which is its plane normal.
    for (std::size_t f = 0; f < 6; ++f) {
        for (std::uint32_t c = m.faceStart[f]; c < m.faceStart[f + 1]; ++c) {
            QCOMPARE(m.cornerNormal[c], std::uint32_t(f));
            const glm::vec3 p = m.positions[m.cornerPosition[c]];
            QCOMPARE(glm::dot(p, m.normals[f]), 1.0f);
        }
    }
    // And so every vertex carries three different normals.
    for (std::uint32_t v = 0; v < 8; ++v) {
        QSet<std::uint32_t> normals;
        for (std::size_t c = 0; c < m.cornerPosition.size(); ++c)
            if (m.cornerPosition[c] == v)
                normals.insert(m.cornerNormal[c]);
        QCOMPARE(normals.size(), 3);
    }
}

void TestMeshReaders::objRelativeIndices()
{
    const MeshReadResult r = readMeshFile(kFormats + "relative_indices.obj");
    QVERIFY2(r.ok(), qPrintable(r.error));
    const PolygonMesh &m = *r.mesh;
    QCOMPARE(m.faceCount(), std::size_t(3));
    QCOMPARE(m.cornerPosition, (std::vector<std::uint32_t>{0, 1, 2, 0, 1, 3, 0, 1, 3}));
    const std::uint32_t none = PolygonMesh::kNoNormal;
    QCOMPARE(m.cornerNormal,
             (std::vector<std::uint32_t>{none, none, none, none, none, none, 0, 0, 0}));
}

void TestMeshReaders::objCornerFormsAndContinuations()
{
    const MeshReadResult r = readMeshFile(kFormats + "corner_forms.obj");
    QVERIFY2(r.ok(), qPrintable(r.error));
    QVERIFY2(r.warnings.isEmpty(), qPrintable(r.warnings.join("; ")));
    const PolygonMesh &m = *r.mesh;
    QCOMPARE(m.positions.size(), std::size_t(4));
    QCOMPARE(m.positions[3], glm::vec3(0, 0, 1)); // continued `v` line
    QCOMPARE(m.positions[1], glm::vec3(1, 0, 0)); // w ignored
    QCOMPARE(m.faceCount(), std::size_t(4));
    const std::uint32_t none = PolygonMesh::kNoNormal;
    QCOMPARE(m.cornerPosition, (std::vector<std::uint32_t>{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}));
    QCOMPARE(m.cornerNormal,
             (std::vector<std::uint32_t>{none, none, none, none, none, none, 1, 1, 1, 0, 0, 0}));
}

void TestMeshReaders::objByteOrderMarkAndTrailingComments()
{
    const MeshReadResult r =
        parseObj("\xEF\xBB\xBFv 0 0 0\nv 1 0 0 # x\nv 0 1 0\nf 1 2 3 # the only face\n");
    QVERIFY2(r.ok(), qPrintable(r.error));
    QVERIFY2(r.warnings.isEmpty(), qPrintable(r.warnings.join("; ")));
    QCOMPARE(r.mesh->positions.size(), std::size_t(3));
    QCOMPARE(r.mesh->cornerPosition, (std::vector<std::uint32_t>{0, 1, 2}));
}

void TestMeshReaders::objNumbersMatchFromChars()
{
    // The OBJ reader's fast decimal path against std::from_chars, in the
    // notations exporters use: within one float ulp, exactly for most.
    QRandomGenerator rng(42);
    const char *formats[] = {"%.6f", "%.4f", "%.9g", "%.17g", "%e", "%.3e", "%g", "%.0f"};
    std::string text;
    std::vector<float> expected;
    for (int i = 0; i < 3000; ++i) {
        const double magnitude = std::pow(10.0, rng.bounded(-8.0) + rng.bounded(14.0) - 4.0);
        const double value = (rng.bounded(2) ? -1.0 : 1.0) * rng.bounded(1.0) * magnitude;
        const std::string token = QString::asprintf(formats[i % 8], value).toStdString();
        float f = 0.0f;
        std::from_chars(token.data(), token.data() + token.size(), f);
        expected.push_back(f);
        text += "v " + token + " 0 +" + token + "\n";
    }
    text += "f 1 2 3\n";
    const MeshReadResult r = parseObj(text);
    QVERIFY2(r.ok(), qPrintable(r.error));
    QVERIFY2(r.warnings.isEmpty(), qPrintable(r.warnings.join("; ")));
    int inexact = 0;
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const float got = r.mesh->positions[i].x;
        QCOMPARE(r.mesh->positions[i].z, got);
        if (got != expected[i]) {
            ++inexact;
            QVERIFY2(std::nextafter(expected[i], got) == got,
                     qPrintable(QString::number(expected[i], 'g', 9)));
        }
    }
    QVERIFY(inexact < 10);
}

void TestMeshReaders::objProgressAndCancel()
{
    // About 12 MB of OBJ: progress at least every few MB, increasing.
    std::string text;
    for (int i = 0; i < 300000; ++i)
        text += "v 0.123456 1.234567 2.345678\nf 1 2 3\n";
    QList<double> fractions;
    const MeshReadResult ok = parseObj(text, [&](double f) {
        fractions << f;
        return true;
    });
    QVERIFY(ok.ok());
    QVERIFY2(fractions.size() >= 2, qPrintable(QString::number(fractions.size())));
    QVERIFY(std::is_sorted(fractions.begin(), fractions.end()));
    QVERIFY(fractions.last() <= 1.0);

    const MeshReadResult cancelled = parseObj(text, [](double f) { return f < 0.3; });
    QVERIFY(!cancelled.ok());
    QCOMPARE(cancelled.error, QStringLiteral("cancelled"));

    const QString path = m_dir.filePath("cancel.obj");
    writeBytes(path, QByteArray::fromStdString(text));
    const MeshReadResult fileCancelled = readMeshFile(path, [](double f) { return f < 0.5; });
    QCOMPARE(fileCancelled.error, QStringLiteral("cancelled"));
}

void TestMeshReaders::objLargeFileParsedInHalves_data()
{
    QTest::addColumn<bool>("relative");
    QTest::addColumn<bool>("continued");
    QTest::newRow("absolute indices") << false << false;
    QTest::newRow("relative indices") << true << false;
    QTest::newRow("every vertex line continued") << false << true;
}

void TestMeshReaders::objLargeFileParsedInHalves()
{
    // Over 8 MB, so the second half is parsed on a second thread: whatever
    // is cut at the middle (faces, normals, line numbers, relative indices,
    // continued lines) must read as one pass reads it.
    QFETCH(bool, relative);
    QFETCH(bool, continued);
    const int triangles = 140000;
    const int badAt = triangles * 3 / 4;
    std::string text = "# made by the test\n";
    std::size_t line = 1, badLine = 0;
    for (int t = 0; t < triangles; ++t) {
        for (int k = 0; k < 3; ++k) {
            const int v = 3 * t + k;
            text += "v " + std::to_string(v) + " 0.5 ";
            text += continued ? "\\\n" + std::to_string(-v) + "\n" : std::to_string(-v) + "\n";
            line += continued ? 2 : 1;
        }
        text += "vn 0 0 1\n";
        ++line;
        if (relative) {
            text += "f -3//-1 -2//-1 -1//-1\n";
        } else {
            const std::string n = "//" + std::to_string(t + 1);
            text += "f " + std::to_string(3 * t + 1) + n + " " + std::to_string(3 * t + 2) + n + " "
                + std::to_string(3 * t + 3) + n + "\n";
        }
        ++line;
        if (t == badAt) {
            text += "nonsense here\n";
            badLine = ++line;
        }
    }
    QVERIFY(text.size() > (8u << 20));
    const MeshReadResult r = parseObj(text);
    QVERIFY2(r.ok(), qPrintable(r.error));
    QCOMPARE(r.warnings,
             QStringList{QStringLiteral("skipped 1 unreadable line (first at line %1: "
                                        "\"nonsense here\")")
                             .arg(badLine)});
    const PolygonMesh &m = *r.mesh;
    QCOMPARE(m.positions.size(), std::size_t(3 * triangles));
    QCOMPARE(m.normals.size(), std::size_t(triangles));
    QCOMPARE(m.faceCount(), std::size_t(triangles));
    for (int v = 0; v < 3 * triangles; ++v)
        QCOMPARE(m.positions[v], glm::vec3(float(v), 0.5f, float(-v)));
    for (int t = 0; t < triangles; ++t) {
        QCOMPARE(m.faceStart[t + 1], std::uint32_t(3 * t + 3));
        for (int k = 0; k < 3; ++k) {
            QCOMPARE(m.cornerPosition[3 * t + k], std::uint32_t(3 * t + k));
            QCOMPARE(m.cornerNormal[3 * t + k], std::uint32_t(t));
        }
    }
}

void TestMeshReaders::rejected_data()
{
    QTest::addColumn<QString>("path");
    QTest::addColumn<QString>("errorPart");
    QTest::newRow("empty obj") << kBad + "empty.obj"
                               << "empty";
    for (const char *suffix : {"ply", "off", "stl", "om"}) {
        const QString path = m_dir.filePath(QStringLiteral("empty.%1").arg(suffix));
        writeBytes(path, {});
        QTest::newRow(qPrintable(QStringLiteral("empty %1").arg(suffix))) << path << "empty";
    }
    QTest::newRow("missing file") << kBad + "no_such_file.obj"
                                  << "not found";
    QTest::newRow("directory") << m_dir.path() + "/"
                               << "unsupported";
    const QString dirWithSuffix = m_dir.filePath("folder.obj");
    QDir().mkpath(dirWithSuffix);
    QTest::newRow("directory named .obj") << dirWithSuffix << "not a regular file";
    QTest::newRow("unsupported suffix") << kBad + "mesh.fbx"
                                        << ".obj, .ply, .off, .stl, .om";
    const QString huge = m_dir.filePath("huge_sparse.obj");
    QFile sparse(huge);
    QVERIFY(sparse.open(QIODevice::WriteOnly) && sparse.resize(kMaxMeshFileBytes + 1));
    sparse.close();
    QTest::newRow("over the size limit") << huge << "too large";
    QTest::newRow("words in ascii ply")
        << kBad + "words.ply"
        << "line 11: expected a number for 'y' of vertex 2, found 'hello'";
    QTest::newRow("words in off") << kBad + "words.off"
                                  << "line 5: expected a number, found 'one'";
    QTest::newRow("words in ascii stl") << kBad + "words.stl"
                                        << "line 12: expected 'vertex x y z', found 'zero'";
    QTest::newRow("truncated off") << kBad + "truncated.off"
                                   << "ends after 2 of 4 faces";
    QTest::newRow("ply renamed to obj") << kBad + "ply_renamed.obj"
                                        << "a PLY file";
    const QString png = m_dir.filePath("image.ply");
    writeBytes(png, QByteArray("\x89PNG\r\n\x1a\n", 8) + QByteArray(100, '\0'));
    QTest::newRow("png named .ply") << png << "a PNG image";
    const QString nulObj = m_dir.filePath("nul.obj");
    writeBytes(nulObj, QByteArray("v 0 0 0\nv 1 0 0\n\0\0\0v 0 1 0\nf 1 2 3\n", 34));
    QTest::newRow("NUL bytes in obj") << nulObj << "binary data";
    const QString noFaces = m_dir.filePath("points.obj");
    writeBytes(noFaces, "v 0 0 0\nv 1 0 0\n");
    QTest::newRow("obj without faces") << noFaces << "no faces";
    const QString text = m_dir.filePath("prose.obj");
    writeBytes(text, "This is not a mesh.\nJust some words.\n");
    QTest::newRow("prose as obj") << text << "not an OBJ file";
    const QString onlyBad = m_dir.filePath("only_bad.obj");
    writeBytes(onlyBad, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
    QTest::newRow("no usable faces") << onlyBad << "no usable faces";
    const QString stlNoFacets = m_dir.filePath("nofacets.stl");
    writeBytes(stlNoFacets, "solid empty\nendsolid empty\n");
    QTest::newRow("ascii stl without facets") << stlNoFacets << "no facets";
    const QString pointCloud = m_dir.filePath("cloud.ply");
    writeBytes(pointCloud,
               "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
               "property float z\nend_header\n0 0 0\n");
    QTest::newRow("ply point cloud") << pointCloud << "no faces";
}

void TestMeshReaders::rejected()
{
    QFETCH(QString, path);
    QFETCH(QString, errorPart);
    const Loaded l = load(path);
    QVERIFY(!l.mesh);
    QVERIFY2(l.error.contains(errorPart), qPrintable(l.error));
}

void TestMeshReaders::unreadableFile()
{
    const QString path = m_dir.filePath("locked.obj");
    writeBytes(path, readBytes(kFormats + "tetra.obj"));
    QFile::setPermissions(path, QFileDevice::Permissions());
    if (QFile f(path); f.open(QIODevice::ReadOnly))
        QSKIP("permissions do not stop this user (root?)");
    const MeshReadResult r = readMeshFile(path);
    QVERIFY(!r.ok());
    QVERIFY2(r.error.startsWith("cannot open the file"), qPrintable(r.error));
}

void TestMeshReaders::randomBytesRejected_data()
{
    QTest::addColumn<QString>("path");
    for (const char *suffix : {"obj", "ply", "off", "stl", "om"}) {
        for (quint32 seed : {1u, 2u, 3u}) {
            QRandomGenerator rng(seed);
            QByteArray bytes(4096, Qt::Uninitialized);
            for (char &b : bytes)
                b = char(rng.bounded(256));
            const QString path =
                m_dir.filePath(QStringLiteral("random%1.%2").arg(seed).arg(suffix));
            writeBytes(path, bytes);
            QTest::newRow(qPrintable(QStringLiteral("%1 seed %2").arg(suffix).arg(seed))) << path;
        }
    }
}

void TestMeshReaders::randomBytesRejected()
{
    QFETCH(QString, path);
    const Loaded l = load(path);
    QVERIFY(!l.mesh);
    QVERIFY(!l.error.isEmpty());
}

void TestMeshReaders::hugeVertexCountIsRefusedBeforeParsing()
{
    // 10^9 vertices claimed in a 180-byte file: refused by the precheck,
    // before any parser (OpenMesh alone would reserve for them and die of
    // std::bad_alloc); the message is the precheck's.
    const MeshReadResult r = readMeshFile(kBad + "huge_vertex_count.ply");
    QVERIFY(!r.ok());
    QVERIFY2(r.error.contains("declares 1000000000 vertex elements"), qPrintable(r.error));

    // The same claim in the other formats with counts.
    const QString stl = m_dir.filePath("huge.stl");
    QByteArray stlBytes(84, '\0');
    qToLittleEndian<quint32>(1000000000u, stlBytes.data() + 80);
    writeBytes(stl, stlBytes + QByteArray(50, '\0'));
    QVERIFY(readMeshFile(stl).error.contains("declares 1000000000 triangles"));
    const QString off = m_dir.filePath("huge.off");
    writeBytes(off, "OFF\n1000000000 1000000000 0\n0 0 0\n");
    QVERIFY(readMeshFile(off).error.contains("declares 1000000000 vertices"));
    const QString om = m_dir.filePath("huge.om");
    QByteArray omBytes = readBytes(writeTetra(m_dir, "for_huge.om", true));
    qToLittleEndian<quint32>(1000000000u, omBytes.data() + 4);
    writeBytes(om, omBytes);
    QVERIFY(readMeshFile(om).error.contains("declares 1000000000 vertices"));
}

void TestMeshReaders::plyFormatLineMustCarryAVersion_data()
{
    QTest::addColumn<QByteArray>("formatLine");
    QTest::newRow("no version") << QByteArray("format ascii");
    QTest::newRow("exponent without digits") << QByteArray("format ascii 1.0e");
    QTest::newRow("not a number") << QByteArray("format binary_big_endian /.0");
    QTest::newRow("a word too many") << QByteArray("format ascii 1.0 x");
    QTest::newRow("point without digits") << QByteArray("format ascii 1.");
    QTest::newRow("a version past a float (fuzz find)")
        << QByteArray("format ascii 6666666666666666666666661.0");
}

void TestMeshReaders::plyFormatLineMustCarryAVersion()
{
    // OpenMesh's PLY header loop never ends when the version after the
    // format does not read as a float (found by fuzzing; it hung mesh-info
    // and grew by ~80 MB/s): the precheck refuses such a line, located.
    QFETCH(QByteArray, formatLine);
    const QString path = m_dir.filePath("format.ply");
    writeBytes(path,
               "ply\n" + formatLine
                   + "\nelement vertex 3\nproperty float x\nproperty float y\n"
                     "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                     "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    const MeshReadResult r = readMeshFile(path);
    QVERIFY(!r.ok());
    QVERIFY2(r.error.contains(QLatin1String("PLY header line 2: expected 'format")),
             qPrintable(r.error));

    // The same file with a version reads.
    writeBytes(path, readBytes(path).replace(formatLine, "format ascii 1.0"));
    QVERIFY2(readMeshFile(path).ok(), qPrintable(readMeshFile(path).error));
}

void TestMeshReaders::plyHeaderMustBeText_data()
{
    QTest::addColumn<QByteArray>("elementLine");
    QTest::addColumn<QString>("error"); // empty: the file reads
    static constexpr char kFound[] = "element v\x01\0a`\0\x0c\x88vertex 3";
    QTest::newRow("nul and form feed in a name (fuzz find)")
        << QByteArray(kFound, sizeof kFound - 1)
        << "PLY header line 3: byte 0x01 at column 10 is not text";
    QTest::newRow("form feed between words") << QByteArray("element vertex\x0c"
                                                           "3")
                                             << "byte 0x0c at column 15";
    QTest::newRow("a second format line")
        << QByteArray("format binary_little_endian 1.0\nelement vertex 3")
        << "PLY header line 3: a second 'format' line";
    QTest::newRow("words after end_header") << QByteArray("element vertex 3\nend_header float nz")
                                            << "PLY header line 4: words after 'end_header'";
    QTest::newRow("UTF-8 in a comment reads")
        << QByteArray("comment made by Jos\xc3\xa9\nelement vertex 3") << "";
}

void TestMeshReaders::plyHeaderMustBeText()
{
    // OpenMesh splits header words at any whitespace and reads counts with
    // operator>>; a word it cannot read sent it round its header loop,
    // logging, until the fuzzer's memory limit (2 GB) stopped it.
    QFETCH(QByteArray, elementLine);
    QFETCH(QString, error);
    const QString path = m_dir.filePath("header.ply");
    writeBytes(path,
               "ply\nformat ascii 1.0\n" + elementLine
                   + "\nproperty float x\nproperty float y\n"
                     "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                     "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    const MeshReadResult r = readMeshFile(path);
    if (error.isEmpty()) {
        QVERIFY2(r.ok(), qPrintable(r.error));
    } else {
        QVERIFY(!r.ok());
        QVERIFY2(r.error.contains(error), qPrintable(r.error));
    }
}

void TestMeshReaders::binaryTruncated_data()
{
    QTest::addColumn<QString>("name");
    QTest::newRow("binary ply") << "cut.ply";
    QTest::newRow("binary stl") << "cut.stl";
    QTest::newRow("om") << "cut.om";
}

void TestMeshReaders::binaryTruncated()
{
    // Policy: a binary file whose header promises more than it holds is an
    // error, wherever it is cut (a partial mesh would look like a bug).
    QFETCH(QString, name);
    const QByteArray whole = readBytes(writeTetra(m_dir, "whole_" + name, true));
    QVERIFY(!whole.isEmpty());
    const QString path = m_dir.filePath(name);
    for (qsizetype size = 1; size < whole.size(); ++size) {
        writeBytes(path, whole.left(size));
        const Loaded l = load(path);
        QVERIFY2(!l.mesh, qPrintable(QStringLiteral("%1 bytes of %2").arg(size).arg(whole.size())));
        QVERIFY(!l.error.isEmpty());
    }
    writeBytes(path, whole.left(whole.size() / 2));
    const QString error = load(path).error;
    QVERIFY2(error.contains("truncated"), qPrintable(error));
}

void TestMeshReaders::objCutAnywhereNeverCrashes()
{
    const QByteArray whole = readBytes(kFormats + "cube_flat_normals.obj");
    const QString path = m_dir.filePath("cut_anywhere.obj");
    for (qsizetype size = 1; size <= whole.size(); ++size) {
        writeBytes(path, whole.left(size));
        const Loaded l = load(path);
        QVERIFY(l.mesh || !l.error.isEmpty());
    }
}

void TestMeshReaders::objCutMidLineLoadsWithWarning()
{
    // Policy: OBJ has no counts, so a cut file loads what is complete and
    // says what it lost.
    const Loaded l = load(kBad + "truncated_mid_line.obj");
    QVERIFY2(l.mesh, qPrintable(l.error));
    QCOMPARE(l.mesh->faceCount(), std::size_t(4));
    QCOMPARE(l.mesh->positions.size(), std::size_t(4));
    QVERIFY2(anyContains(l.warnings, "skipped 1 unreadable line (first at line 10: \"v 0.25 0.\")"),
             qPrintable(l.warnings.join("; ")));
    QVERIFY(anyContains(l.warnings, "the file looks truncated"));
    QVERIFY(anyContains(l.warnings, "removed 1 vertex no face uses"));

    const QString cutFace = m_dir.filePath("cut_face.obj");
    writeBytes(cutFace, readBytes(kFormats + "tetra.obj") + "f 1 2");
    const Loaded lf = load(cutFace);
    QVERIFY2(lf.mesh, qPrintable(lf.error));
    QCOMPARE(lf.mesh->faceCount(), std::size_t(4));
    QVERIFY2(anyContains(lf.warnings, "dropped 1 degenerate face"),
             qPrintable(lf.warnings.join("; ")));
}

void TestMeshReaders::repairedOnLoad_data()
{
    QTest::addColumn<QString>("path");
    QTest::addColumn<int>("faces");
    QTest::addColumn<int>("vertices");
    QTest::addColumn<QStringList>("warnings");
    QTest::newRow("out-of-range and negative indices")
        << kBad + "bad_indices.obj" << 4 << 4
        << QStringList{"dropped 3 faces with out-of-range vertex indices"};
    QTest::newRow("NaN and inf coordinates")
        << kBad + "nan_coords.obj" << 4 << 4
        << QStringList{"dropped 2 faces using NaN or infinite coordinates",
                       "removed 2 vertices no face uses"};
    QTest::newRow("zero-area faces")
        << kBad + "zero_area.obj" << 4 << 4
        << QStringList{"dropped 3 degenerate faces (fewer than 3 distinct corners or zero area)",
                       "removed 2 vertices no face uses"};
    QTest::newRow("non-manifold edge")
        << kBad + "nonmanifold_edge.obj" << 3 << 5
        << QStringList{"1 non-manifold edge (shared by 3 or more faces), kept as they are"};
    QTest::newRow("cube with a flipped face")
        << kBad + "flipped_face_cube.obj" << 6 << 8
        << QStringList{"flipped 1 face to make the winding consistent"};
    QTest::newRow("tetrahedron with a flipped face")
        << kBad + "flipped_face_tetra.obj" << 4 << 4
        << QStringList{"flipped 1 face to make the winding consistent"};
    QTest::newRow("isolated vertices") << kBad + "isolated_vertices.obj" << 4 << 4
                                       << QStringList{"removed 3 vertices no face uses"};
    QTest::newRow("off face colours without COFF")
        << kFormats + "tetra_commented.off" << 4 << 4
        << QStringList{"ignored the values after the vertex indices on 1 face line (face colours "
                       "need a COFF header)"};
}

void TestMeshReaders::repairedOnLoad()
{
    QFETCH(QString, path);
    QFETCH(int, faces);
    QFETCH(int, vertices);
    QFETCH(QStringList, warnings);
    const Loaded l = load(path);
    QVERIFY2(l.mesh, qPrintable(l.error));
    QCOMPARE(int(l.mesh->faceCount()), faces);
    QCOMPARE(int(l.mesh->positions.size()), vertices);
    QCOMPARE(l.warnings, warnings);
}

void TestMeshReaders::stlDropsAreCounted()
{
    const glm::vec3 o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const QString path = m_dir.filePath("drops.stl");
    writeBytes(path,
               binaryStl({{o, y, x},
                          {o, x, z},
                          {o, z, y},
                          {x, y, z},
                          {o, o, x},                     // two corners at one position
                          {glm::vec3(nan, 0, 0), o, x},  // NaN
                          {o, x, glm::vec3(2, 0, 0)}})); // zero area
    const Loaded l = load(path);
    QVERIFY2(l.mesh, qPrintable(l.error));
    QCOMPARE(l.mesh->faceCount(), std::size_t(4));
    QCOMPARE(l.mesh->positions.size(), std::size_t(4));
    QCOMPARE(
        l.warnings,
        (QStringList{"dropped 1 triangle with NaN or infinite coordinates",
                     "the file's facet normals are all zero or invalid; normals will be computed",
                     "dropped 1 triangle with two corners at the same position",
                     "dropped 1 degenerate face (fewer than 3 distinct corners or zero area)",
                     "removed 1 vertex no face uses"}));
}

void TestMeshReaders::binaryPlyNonFinite()
{
    const QString path = m_dir.filePath("nan.ply");
    QByteArray bytes(
        "ply\nformat binary_little_endian 1.0\nelement vertex 5\nproperty float x\nproperty float "
        "y\n"
        "property float z\nelement face 5\nproperty list uchar int vertex_indices\nend_header\n");
    const float inf = std::numeric_limits<float>::infinity();
    const float coords[15] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, inf, 0, 0};
    bytes.append(reinterpret_cast<const char *>(coords), sizeof coords);
    for (const auto &f :
         {std::array<qint32, 3>{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 1, 4}}) {
        bytes.append(char(3));
        bytes.append(reinterpret_cast<const char *>(f.data()), 12);
    }
    writeBytes(path, bytes);
    const Loaded l = load(path);
    QVERIFY2(l.mesh, qPrintable(l.error));
    QCOMPARE(l.mesh->faceCount(), std::size_t(4));
    QCOMPARE(l.warnings,
             (QStringList{"dropped 1 face using NaN or infinite coordinates",
                          "removed 1 vertex no face uses"}));
}

void TestMeshReaders::openMeshMessagesBecomeTheError()
{
    // OpenMesh refuses this list type with a console message; it must reach
    // the user as the error rather than stderr.
    const QString path = m_dir.filePath("ushort.ply");
    QByteArray bytes("ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float "
                     "x\nproperty float y\n"
                     "property float z\nelement face 1\nproperty list ushort ushort "
                     "vertex_indices\nend_header\n");
    const float coords[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    bytes.append(reinterpret_cast<const char *>(coords), sizeof coords);
    const quint16 face[4] = {3, 0, 1, 2};
    bytes.append(reinterpret_cast<const char *>(face), sizeof face);
    writeBytes(path, bytes);
    const MeshReadResult r = readMeshFile(path);
    QVERIFY(!r.ok());
    QVERIFY2(r.error.contains("Unsupported Index type for property list: ushort"),
             qPrintable(r.error));
}

void TestMeshReaders::openMeshProgressAndCancel()
{
    TriMesh m;
    std::vector<TriMesh::VertexHandle> v;
    const int n = 200;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
            v.push_back(m.add_vertex({float(i), float(j), 0.0f}));
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const int a = j * (n + 1) + i;
            m.add_face(v[a], v[a + 1], v[a + n + 2]);
            m.add_face(v[a], v[a + n + 2], v[a + n + 1]);
        }
    }
    const QString path = m_dir.filePath("grid.ply");
    QVERIFY(writeMesh(m, path, OpenMesh::IO::Options::Binary));

    QList<double> fractions;
    const MeshReadResult ok = readMeshFile(path, [&](double f) {
        fractions << f;
        return true;
    });
    QVERIFY2(ok.ok(), qPrintable(ok.error));
    QCOMPARE(ok.mesh->faceCount(), std::size_t(2 * n * n));
    QVERIFY(fractions.size() >= 3);
    QVERIFY(std::is_sorted(fractions.begin(), fractions.end()));
    QCOMPARE(fractions.last(), 1.0);

    const MeshReadResult cancelled = readMeshFile(path, [](double f) { return f < 0.2; });
    QCOMPARE(cancelled.error, QStringLiteral("cancelled"));
    // OpenMesh is usable again after the interrupted read.
    QVERIFY(readMeshFile(path).ok());
}

QTEST_GUILESS_MAIN(TestMeshReaders)
#include "tst_meshreaders.moc"
