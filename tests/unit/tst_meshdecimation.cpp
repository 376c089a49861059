// Levels of detail: OpenMesh's quadric decimation through decimateMesh, the
// builtins tessellated coarser, and a scene object's "detail" through
// loadSceneMeshes. The mesh's own normals must survive exactly.
#include "mesh/detail/MeshDecimation.h"
#include "mesh/import/BuiltinMeshes.h"
#include "mesh/loading/MeshLoader.h"
#include "mesh/loading/SceneMeshes.h"

#include <QFileInfo>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <tuple>

using namespace phonglab;

namespace {

QString asset(const char *name)
{
    return QStringLiteral(PHONGLAB_SOURCE_DIR "/assets/meshes/") + QLatin1String(name);
}

MeshData load(const QString &path, NormalOptions options = {})
{
    MeshLoadResult r = loadMesh(path, options);
    if (!r.ok())
        qFatal("cannot load %s: %s", qPrintable(path), qPrintable(r.error));
    return std::move(*r.mesh);
}

using Vec = std::tuple<float, float, float>;
Vec vec(const glm::vec3 &v)
{
    return {v.x, v.y, v.z};
}

// Every (position, normal) pair of a mesh, exactly.
std::set<std::tuple<Vec, Vec>> vertexPairs(const MeshData &mesh)
{
    std::set<std::tuple<Vec, Vec>> pairs;
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
        pairs.insert({vec(mesh.positions[i]), vec(mesh.normals[i])});
    return pairs;
}

bool sameMesh(const MeshData &a, const MeshData &b)
{
    return a.positions == b.positions && a.normals == b.normals && a.indices == b.indices;
}

glm::dvec3 faceNormal(const MeshData &m, std::size_t t)
{
    const glm::dvec3 a(m.positions[m.indices[3 * t]]), b(m.positions[m.indices[3 * t + 1]]),
        c(m.positions[m.indices[3 * t + 2]]);
    return glm::normalize(glm::cross(b - a, c - a));
}

// The cube [-1, 1]³ with each face an n × n grid of quads and flat normals:
// a flat mesh whose faces can be coarsened without leaving their planes.
MeshData gridCube(int n)
{
    MeshData mesh;
    for (int axis = 0; axis < 3; ++axis) {
        for (float sign : {1.0f, -1.0f}) {
            glm::vec3 normal(0.0f), u(0.0f), v(0.0f);
            normal[axis] = sign;
            u[(axis + 1) % 3] = 1.0f;
            v[(axis + 2) % 3] = sign; // u × v = normal: counter-clockwise from outside
            const auto base = std::uint32_t(mesh.positions.size());
            for (int j = 0; j <= n; ++j)
                for (int i = 0; i <= n; ++i) {
                    mesh.positions.push_back(normal + (-1.0f + 2.0f * i / n) * u
                                             + (-1.0f + 2.0f * j / n) * v);
                    mesh.normals.push_back(normal);
                }
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    const std::uint32_t a = base + j * (n + 1) + i, b = a + 1, c = a + (n + 1),
                                        d = c + 1;
                    mesh.indices.insert(mesh.indices.end(), {a, b, d, a, d, c});
                }
        }
    }
    return mesh;
}

} // namespace

class TestMeshDecimation : public QObject
{
    Q_OBJECT

private slots:
    void shrinksToTheFraction_data();
    void shrinksToTheFraction();
    void closedStaysClosed_data();
    void closedStaysClosed();
    void positionsAreTheInputs();
    void smoothTreeKeepsFileNormals();
    void flatStaysFlat_data();
    void flatStaysFlat();
    void hardEdgesStayHard();
    void fractionOneIsIdentity();
    void levelsInOneRun();
    void deterministic();
    void badInputDoesNotCrash();
    void nonManifoldFacesAreLeftOutAndSaid();
    void builtinDetailTessellation();
    void sceneObjectDetail();
    void progressAndCancel();
};

void TestMeshDecimation::shrinksToTheFraction_data()
{
    QTest::addColumn<QString>("path");
    QTest::newRow("tree") << asset("tree.obj");
    QTest::newRow("cloud") << asset("cloud.obj");
    QTest::newRow("builtin sphere") << QStringLiteral("builtin:sphere");
}

void TestMeshDecimation::shrinksToTheFraction()
{
    QFETCH(QString, path);
    const MeshData full = load(path);
    const double full_t = double(full.triangleCount());
    std::size_t previous = full.triangleCount();
    for (const double fraction : {1.0, 0.5, 0.25, 1.0 / 16, 1.0 / 64}) {
        const auto [lod, note] = decimateMesh(full, fraction);
        qInfo("%s at %.4g: %zu of %zu triangles, %zu vertices%s",
              qPrintable(QFileInfo(path).fileName()), fraction, lod.triangleCount(),
              full.triangleCount(), lod.positions.size(),
              note.isEmpty() ? "" : qPrintable(QStringLiteral(" (") + note + u')'));
        QVERIFY(lod.isValid());
        QVERIFY2(lod.triangleCount() <= previous, "more triangles at a smaller fraction");
        previous = lod.triangleCount();
        // Collapses remove two triangles at a time; a closed piece stops at
        // a tetrahedron. Down to 1/16 the target is met within a few percent.
        if (fraction >= 1.0 / 16) {
            QVERIFY2(std::abs(double(lod.triangleCount()) - fraction * full_t)
                         <= 0.05 * fraction * full_t + 4,
                     qPrintable(QString::number(lod.triangleCount())));
            QVERIFY2(note.isEmpty(), qPrintable(note));
        }
    }
}

void TestMeshDecimation::closedStaysClosed_data()
{
    QTest::addColumn<QString>("path");
    QTest::newRow("builtin sphere") << QStringLiteral("builtin:sphere");
    QTest::newRow("builtin torus") << QStringLiteral("builtin:torus");
    QTest::newRow("blender smooth sphere")
        << QStringLiteral(PHONGLAB_TEST_DATA_DIR "/meshes/blender/sphere_smooth.obj");
    QTest::newRow("cloud") << asset("cloud.obj");
}

void TestMeshDecimation::closedStaysClosed()
{
    QFETCH(QString, path);
    const MeshData full = load(path);
    QVERIFY(isClosedMesh(full));
    for (const double fraction : {0.5, 0.1, 0.02}) {
        const auto [lod, note] = decimateMesh(full, fraction);
        QVERIFY(lod.triangleCount() < full.triangleCount());
        QVERIFY2(isClosedMesh(lod), qPrintable(QString::number(fraction)));
    }
}

void TestMeshDecimation::positionsAreTheInputs()
{
    for (const char *name : {"tree.obj", "cloud.obj"}) {
        const MeshData full = load(asset(name));
        std::set<Vec> inputs;
        for (const glm::vec3 &p : full.positions)
            inputs.insert(vec(p));
        const MeshData lod = decimateMesh(full, 0.2).mesh;
        for (const glm::vec3 &p : lod.positions)
            QVERIFY2(inputs.count(vec(p)), "a position the input does not have");
    }
}

void TestMeshDecimation::smoothTreeKeepsFileNormals()
{
    const MeshData full = load(asset("tree.obj"));
    const auto pairs = vertexPairs(full);
    for (const double fraction : {0.5, 0.25, 1.0 / 16}) {
        const MeshData lod = decimateMesh(full, fraction).mesh;
        for (std::size_t i = 0; i < lod.positions.size(); ++i)
            QVERIFY2(pairs.count({vec(lod.positions[i]), vec(lod.normals[i])}),
                     "a normal that is not the file's at that position");
    }
}

void TestMeshDecimation::flatStaysFlat_data()
{
    QTest::addColumn<QString>("path");
    QTest::addColumn<bool>("computeFlat");
    QTest::newRow("flat tree") << asset("tree_flat.obj") << false;
    QTest::newRow("sphere, flat normals")
        << QStringLiteral(PHONGLAB_TEST_DATA_DIR "/meshes/blender/sphere_nonormals.obj") << true;
}

// A faceted mesh stays faceted: one normal per triangle, its own facet's
// (an original normal where the face kept its plane).
void TestMeshDecimation::flatStaysFlat()
{
    QFETCH(QString, path);
    QFETCH(bool, computeFlat);
    NormalOptions options;
    if (computeFlat)
        options.method = NormalMethod::Flat;
    const MeshData full = load(path, options);
    // How far a file's flat normal may be from its triangle's own: Blender
    // gives both triangles of a non-planar quad the quad's normal.
    const auto offFace = [](const MeshData &m, std::size_t t) {
        const glm::dvec3 n(m.normals[m.indices[3 * t]]);
        return glm::degrees(std::acos(std::clamp(glm::dot(n, faceNormal(m, t)), -1.0, 1.0)));
    };
    double inputWorst = 0.0;
    for (std::size_t t = 0; t < full.triangleCount(); ++t)
        inputWorst = std::max(inputWorst, offFace(full, t));
    const MeshData lod = decimateMesh(full, 0.25).mesh;
    QVERIFY(lod.triangleCount() < full.triangleCount() / 3);
    for (std::size_t t = 0; t < lod.triangleCount(); ++t) {
        const glm::vec3 n = lod.normals[lod.indices[3 * t]];
        QCOMPARE(lod.normals[lod.indices[3 * t + 1]], n);
        QCOMPARE(lod.normals[lod.indices[3 * t + 2]], n);
        QVERIFY2(offFace(lod, t) <= inputWorst + 0.1, qPrintable(QString::number(offFace(lod, t))));
    }
}

// A subdivided cube coarsens within its faces; the corners stay sharp and
// every normal is exactly one of the six axes the input had.
void TestMeshDecimation::hardEdgesStayHard()
{
    const MeshData full = gridCube(8);
    QCOMPARE(full.triangleCount(), std::size_t(6 * 8 * 8 * 2));
    QVERIFY(isClosedMesh(full));
    const auto pairs = vertexPairs(full);
    const MeshData lod = decimateMesh(full, 0.1).mesh;
    QVERIFY(lod.triangleCount() <= 80);
    QVERIFY(isClosedMesh(lod));
    for (std::size_t i = 0; i < lod.positions.size(); ++i)
        QVERIFY(pairs.count({vec(lod.positions[i]), vec(lod.normals[i])}));
    for (std::size_t t = 0; t < lod.triangleCount(); ++t) {
        const glm::vec3 n = lod.normals[lod.indices[3 * t]];
        QCOMPARE(std::abs(n.x) + std::abs(n.y) + std::abs(n.z), 1.0f);
        QCOMPARE(lod.normals[lod.indices[3 * t + 1]], n);
        QCOMPARE(lod.normals[lod.indices[3 * t + 2]], n);
        QVERIFY(glm::dot(glm::dvec3(n), faceNormal(lod, t)) > 0.9999);
    }
}

void TestMeshDecimation::fractionOneIsIdentity()
{
    const MeshData full = load(asset("cloud.obj"));
    const DecimatedMesh same = decimateMesh(full, 1.0);
    QVERIFY(sameMesh(same.mesh, full));
    QVERIFY(same.note.isEmpty());
}

void TestMeshDecimation::levelsInOneRun()
{
    const MeshData full = load(asset("cloud.obj"));
    const auto [levels, note] = decimateMeshLevels(full, {1.0 / 16, 1.0, 0.25, 2.0});
    QCOMPARE(levels.size(), std::size_t(4));
    QVERIFY(sameMesh(levels[1], full));
    QVERIFY(sameMesh(levels[3], full)); // out of range: unchanged, and said
    QVERIFY2(note.contains(QStringLiteral("(0, 1]")), qPrintable(note));
    QVERIFY(std::abs(double(levels[2].triangleCount()) - 750.0) <= 40.0);
    QVERIFY(std::abs(double(levels[0].triangleCount()) - 187.5) <= 14.0);
    QVERIFY(isClosedMesh(levels[0]) && isClosedMesh(levels[2]));
    // The first level of a run is what decimateMesh gives.
    QVERIFY(sameMesh(decimateMeshLevels(full, {0.25, 1.0 / 16}).levels[0],
                     decimateMesh(full, 0.25).mesh));
}

void TestMeshDecimation::deterministic()
{
    const MeshData full = load(asset("tree.obj"));
    QVERIFY(sameMesh(decimateMesh(full, 0.3).mesh, decimateMesh(full, 0.3).mesh));
}

void TestMeshDecimation::badInputDoesNotCrash()
{
    const MeshData cube = makeCube();
    for (const double fraction : {0.0, -0.5, 1.5, std::numeric_limits<double>::quiet_NaN(),
                                  std::numeric_limits<double>::infinity()}) {
        const DecimatedMesh refused = decimateMesh(cube, fraction);
        QVERIFY(sameMesh(refused.mesh, cube));
        QVERIFY2(refused.note.contains(QStringLiteral("(0, 1]")), qPrintable(refused.note));
    }
    QVERIFY(decimateMesh(MeshData{}, 0.5).mesh.indices.empty());

    MeshData broken = cube;
    broken.indices[4] = 999; // out of range
    const DecimatedMesh fromBroken = decimateMesh(broken, 0.5);
    QVERIFY(sameMesh(fromBroken.mesh, broken));
    QVERIFY(!fromBroken.note.isEmpty());

    MeshData nan = makeUvSphere(16, 8);
    nan.positions[20] = glm::vec3(std::numeric_limits<float>::quiet_NaN());
    const DecimatedMesh fromNan = decimateMesh(nan, 0.5);
    QVERIFY(fromNan.mesh.isValid());
    QVERIFY2(fromNan.note.contains(QStringLiteral("non-finite")), qPrintable(fromNan.note));

    // The smallest closed meshes cannot shrink further; asking is no error.
    const MeshData tiny = decimateMesh(cube, 1e-9).mesh;
    QVERIFY(tiny.isValid());
    QVERIFY(isClosedMesh(tiny));
}

void TestMeshDecimation::nonManifoldFacesAreLeftOutAndSaid()
{
    // A fan of 12 triangles, plus three more on one edge (an edge with
    // three faces), plus a duplicate: OpenMesh takes only the manifold part.
    MeshData mesh = makeUvSphere(12, 6);
    const std::size_t base = mesh.positions.size();
    mesh.positions.push_back({0.0f, 0.0f, 3.0f});
    mesh.normals.push_back({0.0f, 0.0f, 1.0f});
    const std::uint32_t a = mesh.indices[0], b = mesh.indices[1];
    mesh.indices.insert(mesh.indices.end(), {a, b, std::uint32_t(base)});
    mesh.indices.insert(mesh.indices.end(), {mesh.indices[3], mesh.indices[4], mesh.indices[5]});
    const auto [lod, note] = decimateMesh(mesh, 0.5);
    QVERIFY(lod.isValid());
    QVERIFY(lod.triangleCount() > 0);
    QVERIFY2(note.contains(QStringLiteral("non-manifold")), qPrintable(note));
}

void TestMeshDecimation::builtinDetailTessellation()
{
    for (const QString &spec :
         {QStringLiteral("builtin:sphere"), QStringLiteral("builtin:torus")}) {
        const std::size_t full = builtinMesh(spec)->triangleCount();
        QCOMPARE(builtinMesh(spec, 1.0)->triangleCount(), full);
        for (const double detail : {0.5, 0.25, 1.0 / 16, 1.0 / 64}) {
            const std::size_t t = builtinMesh(spec, detail)->triangleCount();
            QVERIFY2(std::abs(double(t) / full - detail) < 0.02 * detail + 0.001,
                     qPrintable(QString::number(t)));
        }
        const MeshData tiny = *builtinMesh(spec, 1e-9);
        QCOMPARE(tiny.triangleCount(), std::size_t(6 * 3 * 2));
        QVERIFY(isClosedMesh(tiny));
    }
    QCOMPARE(builtinDetailLabel(QStringLiteral("builtin:sphere"), 1.0 / 64),
             QStringLiteral("32\u00d716"));
    QCOMPARE(builtinDetailLabel(QStringLiteral("builtin:torus"), 0.25),
             QStringLiteral("96\u00d748"));
    QCOMPARE(builtinDetailLabel(QStringLiteral("builtin:sphere"), 1.0),
             QStringLiteral("256\u00d7128"));
    QCOMPARE(builtinMesh(QStringLiteral("builtin:cube"), 0.1)->triangleCount(), std::size_t(12));
    QVERIFY(!builtinMesh(QStringLiteral("builtin:teapot"), 0.5));
    QVERIFY(builtinDetailLabel(QStringLiteral("builtin:teapot"), 0.5).isEmpty());
}

void TestMeshDecimation::sceneObjectDetail()
{
    Scene scene;
    SceneObject tree;
    tree.mesh = asset("tree.obj");
    SceneObject quarterTree = tree;
    quarterTree.detail = 0.25;
    SceneObject sphere;
    sphere.mesh = QStringLiteral("builtin:sphere");
    sphere.detail = 1.0 / 16;
    scene.objects = {tree, quarterTree, sphere};
    QCOMPARE(meshKey(scene, quarterTree), meshKey(scene, tree) + QStringLiteral("|detail=0.25"));
    QCOMPARE(meshKey(scene, sphere), QStringLiteral("builtin:sphere|detail=0.0625"));

    const SceneMeshes meshes = loadSceneMeshes(scene);
    QVERIFY2(meshes.ok(), qPrintable(meshes.error));
    QCOMPARE(meshes.entries.size(), 3);
    const MeshStats &full = meshes.entries.value(meshKey(scene, tree)).stats;
    const SceneMeshes::Entry &quarter = meshes.entries[meshKey(scene, quarterTree)];
    QCOMPARE(full.detail, 1.0);
    QCOMPARE(quarter.stats.detail, 0.25);
    QCOMPARE(quarter.stats.fullTriangles, full.triangles);
    QCOMPARE(quarter.stats.triangles, qint64(quarter.mesh->triangleCount()));
    QCOMPARE(quarter.stats.vertices, qint64(quarter.mesh->positions.size()));
    QVERIFY(std::abs(quarter.stats.triangles - full.triangles / 4) <= full.triangles / 40 + 4);
    QCOMPARE(quarter.stats.fileFaces, full.fileFaces); // what the file has is unchanged
    QVERIFY2(quarter.warnings.isEmpty(), qPrintable(quarter.warnings.join(u'\n')));

    const MeshStats &coarseSphere = meshes.entries.value(meshKey(scene, sphere)).stats;
    QCOMPARE(coarseSphere.triangles, qint64(64 * 32 * 2));
    QCOMPARE(coarseSphere.fullTriangles, qint64(256 * 128 * 2));
    QVERIFY(coarseSphere.closed);
}

// Long decimations report progress and stop when asked: the same result
// with and without a progress callback, a rising fraction, and an empty
// mesh with "cancelled" when the callback says no. A scene load cancelled
// during decimation fails with "cancelled" and keeps nothing.
void TestMeshDecimation::progressAndCancel()
{
    const MeshData sphere = makeUvSphere(128, 64);
    std::vector<double> seen;
    const auto [withProgress, note] = decimateMesh(sphere, 0.1, [&seen](double f) {
        seen.push_back(f);
        return true;
    });
    QVERIFY2(note.isEmpty(), qPrintable(note));
    QVERIFY(seen.size() >= 10);
    QVERIFY(std::is_sorted(seen.begin(), seen.end()));
    QVERIFY(seen.front() >= 0.0 && seen.back() <= 1.0 && seen.back() > 0.8);
    const MeshData plain = decimateMesh(sphere, 0.1).mesh;
    QCOMPARE(withProgress.indices, plain.indices);
    QCOMPARE(withProgress.positions, plain.positions);

    int calls = 0;
    const DecimatedMesh stopped =
        decimateMesh(sphere, 0.1, [&calls](double) { return ++calls < 3; });
    QCOMPARE(stopped.note, QStringLiteral("cancelled"));
    QVERIFY(stopped.mesh.indices.empty());
    QCOMPARE(calls, 3); // not asked again once it said no

    Scene scene;
    SceneObject tree;
    tree.mesh = asset("tree.obj");
    tree.detail = 0.25;
    scene.objects = {tree};
    double last = 0.0;
    const SceneMeshes loaded = loadSceneMeshes(scene, {}, [&last](double f) {
        last = f;
        return f < 0.6; // past loading (first half), into decimating
    });
    QCOMPARE(loaded.error, QStringLiteral("cancelled"));
    QVERIFY(loaded.entries.isEmpty());
    QVERIFY(last >= 0.5);
}

QTEST_APPLESS_MAIN(TestMeshDecimation)
#include "tst_meshdecimation.moc"
