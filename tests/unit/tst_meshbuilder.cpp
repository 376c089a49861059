// From PolygonMesh to GPU MeshData: triangulation of quads, n-gons and
// concave polygons, the choice between file and computed normals, the
// replacement of unusable file normals, welding, and the statistics.

#include "mesh/detail/MeshDecimation.h"
#include "mesh/import/Triangulation.h"
#include "mesh/normals/MeshBuilder.h"

#include <QPointF>
#include <QtTest>
#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <vector>

using namespace phonglab;

namespace {

// The cube of side 2 at the origin as a file has it: 8 positions (x, y, z =
// ±1 from bits 0, 1, 2) and six quads, counter-clockwise from outside.
const std::uint32_t kCubeQuads[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3},
                                        {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
const glm::vec3 kCubeFaceNormals[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                       {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};

void addFace(PolygonMesh &mesh, std::initializer_list<std::uint32_t> positions)
{
    mesh.cornerPosition.insert(mesh.cornerPosition.end(), positions);
    mesh.faceStart.push_back(std::uint32_t(mesh.cornerPosition.size()));
}

PolygonMesh cubeWithoutNormals()
{
    PolygonMesh mesh;
    for (int i = 0; i < 8; ++i)
        mesh.positions.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
    for (const auto &q : kCubeQuads)
        addFace(mesh, {q[0], q[1], q[2], q[3]});
    return mesh;
}

// Flat shaded: six normals, each corner pointing at its face's.
PolygonMesh flatCube()
{
    PolygonMesh mesh = cubeWithoutNormals();
    mesh.normals.assign(std::begin(kCubeFaceNormals), std::end(kCubeFaceNormals));
    for (std::uint32_t f = 0; f < 6; ++f)
        mesh.cornerNormal.insert(mesh.cornerNormal.end(), 4, f);
    return mesh;
}

// Smooth: per-vertex normals, written unnormalised (the position itself,
// length √3) as some exporters do.
PolygonMesh smoothCube()
{
    PolygonMesh mesh = cubeWithoutNormals();
    mesh.normals = mesh.positions;
    mesh.cornerNormal = mesh.cornerPosition;
    return mesh;
}

glm::dvec3 triangleNormal(const MeshData &data, std::size_t t)
{
    const glm::dvec3 a(data.positions[data.indices[3 * t]]);
    return glm::cross(glm::dvec3(data.positions[data.indices[3 * t + 1]]) - a,
                      glm::dvec3(data.positions[data.indices[3 * t + 2]]) - a);
}

// Maps a point of the plane into a tilted plane in space, so the
// triangulator's projection is exercised rather than a trivial z = 0.
glm::vec3 tilted(double x, double y)
{
    const glm::dvec3 u = glm::normalize(glm::dvec3(1, 1, 0));
    const glm::dvec3 v = glm::normalize(glm::dvec3(-1, 1, 2));
    return glm::vec3(glm::dvec3(0.5, -2, 3) + x * u + y * v);
}
const glm::dvec3 kTiltedNormal =
    glm::normalize(glm::cross(glm::dvec3(1, 1, 0), glm::dvec3(-1, 1, 2)));

// Point in polygon (even-odd), in the plane's own coordinates.
bool insidePolygon(const std::vector<glm::dvec2> &polygon, const glm::dvec2 &p)
{
    bool inside = false;
    for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        const glm::dvec2 &a = polygon[i], &b = polygon[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
            inside = !inside;
    }
    return inside;
}

} // namespace

class TestMeshBuilder : public QObject
{
    Q_OBJECT

private slots:
    void flatCubeSplitsAtEdges();
    void smoothCubeStaysWelded();
    void explicitMethodIgnoresFileNormals();
    void flatConeApexSplitsManyWays();
    void triangleCornersIndexThePolygonCorners();
    void quadAndPentagonKeepWinding();
    void concavePolygon_data();
    void concavePolygon();
    void randomStarPolygons();
    void bowtieFallsBackToFan();
    void autoWithPartialNormalsComputes();
    void unusableFileNormalsAreReplaced();
    void fileNormalsKeptAsWritten();
    void boundsAndStats();
    void emptyMeshFails();
    void minusZeroIsPlusZeroEverywhere();
};

void TestMeshBuilder::flatCubeSplitsAtEdges()
{
    MeshStats stats;
    QStringList warnings;
    const BuiltMesh built = buildMeshData(flatCube(), NormalOptions());
    const MeshData &data = built.mesh;
    stats = built.stats;
    warnings = built.warnings;
    QVERIFY(data.isValid());
    QVERIFY2(warnings.isEmpty(), qPrintable(warnings.join('\n')));
    QCOMPARE(stats.triangles, 12);
    QCOMPARE(stats.vertices, 24); // 8 corners × 3 faces
    QCOMPARE(stats.splitVertices, 16);
    QVERIFY(stats.normalsFromFile);
    QCOMPARE(stats.normalMethod, NormalMethod::Auto);
    // Quads stay in order, two triangles each: a face's triangles use the
    // same four vertices, all with the face's normal.
    for (int f = 0; f < 6; ++f) {
        std::set<std::uint32_t> vertices;
        for (int c = 0; c < 6; ++c) {
            const std::uint32_t v = data.indices[6 * f + c];
            vertices.insert(v);
            QCOMPARE(data.normals[v], kCubeFaceNormals[f]);
        }
        QCOMPARE(vertices.size(), 4u);
    }
}

void TestMeshBuilder::smoothCubeStaysWelded()
{
    MeshStats stats;
    const BuiltMesh built = buildMeshData(smoothCube(), NormalOptions());
    const MeshData &data = built.mesh;
    stats = built.stats;
    QCOMPARE(stats.vertices, 8);
    QCOMPARE(stats.splitVertices, 0);
    QVERIFY(stats.normalsFromFile);
    for (std::size_t v = 0; v < data.positions.size(); ++v) {
        const glm::vec3 expected = data.positions[v] / std::sqrt(3.0f);
        QVERIFY(glm::all(glm::lessThan(glm::abs(data.normals[v] - expected), glm::vec3(1e-7f))));
    }
}

void TestMeshBuilder::explicitMethodIgnoresFileNormals()
{
    // Angle-weighted over the flat cube's positions: one smooth vertex each.
    MeshStats stats;
    stats = buildMeshData(flatCube(), {NormalMethod::AngleWeighted, std::nullopt}).stats;
    QVERIFY(!stats.normalsFromFile);
    QCOMPARE(stats.normalMethod, NormalMethod::AngleWeighted);
    QCOMPARE(stats.vertices, 8);
    QCOMPARE(stats.splitVertices, 0);
    // A 30° crease cuts every edge: the flat cube again, computed.
    const BuiltMesh built = buildMeshData(smoothCube(), {NormalMethod::AngleWeighted, 30.0});
    const MeshData &creased = built.mesh;
    stats = built.stats;
    QCOMPARE(stats.vertices, 24);
    QCOMPARE(stats.splitVertices, 16);
    for (int f = 0; f < 6; ++f)
        for (int c = 0; c < 6; ++c)
            QCOMPARE(creased.normals[creased.indices[6 * f + c]], kCubeFaceNormals[f]);
    // Flat shading splits just as much, whatever the file says.
    stats = buildMeshData(smoothCube(), {NormalMethod::Flat, std::nullopt}).stats;
    QCOMPARE(stats.vertices, 24);
    QCOMPARE(stats.normalMethod, NormalMethod::Flat);
}

void TestMeshBuilder::flatConeApexSplitsManyWays()
{
    // A flat-shaded cone of 100 faces: the apex needs 100 vertices (more
    // than a position's chain is walked for before a hash map takes over),
    // each rim position 2. Every triangle's vertices carry its normal.
    const int segments = 100;
    PolygonMesh mesh;
    mesh.positions.emplace_back(0, 1, 0);
    for (int k = 0; k < segments; ++k) {
        const double a = 2.0 * std::numbers::pi * k / segments;
        mesh.positions.emplace_back(std::sin(a), 0.0, std::cos(a));
        addFace(mesh, {0u, std::uint32_t(1 + k), std::uint32_t(1 + (k + 1) % segments)});
    }
    MeshStats stats;
    const BuiltMesh built = buildMeshData(mesh, {NormalMethod::Flat, std::nullopt});
    const MeshData &data = built.mesh;
    stats = built.stats;
    QCOMPARE(stats.vertices, 3 * segments);
    QCOMPARE(stats.splitVertices, 3 * segments - (segments + 1));
    for (int t = 0; t < segments; ++t) {
        const glm::vec3 n = glm::normalize(glm::vec3(triangleNormal(data, t)));
        for (int k = 0; k < 3; ++k)
            QVERIFY(glm::length(data.normals[data.indices[3 * t + k]] - n) < 1e-6f);
    }
}

void TestMeshBuilder::triangleCornersIndexThePolygonCorners()
{
    // A triangle, then a square: the square's corners are 3..6 and its
    // triangles refer to those corners, not to positions.
    PolygonMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    addFace(mesh, {0, 1, 2});
    addFace(mesh, {0, 1, 2, 3});
    const Triangulation triangulation = triangulate(mesh);
    QCOMPARE(triangulation.corners, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5, 3, 5, 6}));
    QCOMPARE(triangulation.fanFallbacks, 0u);
}

void TestMeshBuilder::quadAndPentagonKeepWinding()
{
    // A quad in the tilted plane and a regular pentagon wound clockwise in
    // it (so facing the other way): each triangle faces like its polygon.
    PolygonMesh mesh;
    for (auto [x, y] : {std::pair{0.0, 0.0}, {2.0, 0.0}, {2.5, 1.5}, {0.0, 1.0}})
        mesh.positions.push_back(tilted(x, y));
    for (int k = 0; k < 5; ++k) {
        const double a = -2.0 * std::numbers::pi * k / 5;
        mesh.positions.push_back(tilted(5 + std::cos(a), std::sin(a)));
    }
    addFace(mesh, {0, 1, 2, 3});
    addFace(mesh, {4, 5, 6, 7, 8});
    const glm::dvec3 quadNormal =
        newellNormal(mesh.positions, std::span(mesh.cornerPosition).first(4));
    const glm::dvec3 pentagonNormal =
        newellNormal(mesh.positions, std::span(mesh.cornerPosition).subspan(4));
    QVERIFY(glm::dot(quadNormal, kTiltedNormal) > 0.0);
    QVERIFY(glm::dot(pentagonNormal, kTiltedNormal) < 0.0);

    MeshStats stats;
    const BuiltMesh built = buildMeshData(mesh, NormalOptions());
    const MeshData &data = built.mesh;
    stats = built.stats;
    QCOMPARE(stats.triangles, 2 + 3);
    for (std::size_t t = 0; t < 5; ++t) {
        const glm::dvec3 expected = t < 2 ? quadNormal : pentagonNormal;
        QVERIFY2(glm::dot(glm::normalize(triangleNormal(data, t)), glm::normalize(expected))
                     > 0.999,
                 qPrintable(QString::number(t)));
    }
}

void TestMeshBuilder::concavePolygon_data()
{
    // The L: a 2×2 square missing its upper right quarter, area 3, reflex
    // at (1, 1). The dart: a quad whose fourth corner (0.5, 1) is pushed
    // inside, area 1.5. Each outline is tried with every corner first, so
    // the awkward corner sits at every place in the order; a fan from the
    // wrong corner (or the dart's wrong diagonal) covers ground outside.
    QTest::addColumn<QList<QPointF>>("outline");
    QTest::addColumn<int>("rotation");
    QTest::addColumn<double>("area");
    const QList<QPointF> ell = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    const QList<QPointF> dart = {{0, 0}, {2, 1}, {0, 2}, {0.5, 1}};
    for (int r = 0; r < 6; ++r)
        QTest::addRow("L, start %d", r) << ell << r << 3.0;
    for (int r = 0; r < 4; ++r)
        QTest::addRow("dart, start %d", r) << dart << r << 1.5;
    // A square with a corner in the middle of an edge: not strictly convex,
    // and no triangle may come out flat along that edge.
    const QList<QPointF> midpoint = {{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}};
    for (int r = 0; r < 5; ++r)
        QTest::addRow("midpoint, start %d", r) << midpoint << r << 4.0;
}

void TestMeshBuilder::concavePolygon()
{
    QFETCH(QList<QPointF>, outline);
    QFETCH(int, rotation);
    QFETCH(double, area);
    const int n = int(outline.size());
    PolygonMesh mesh;
    std::vector<glm::dvec2> plane;
    for (int k = 0; k < n; ++k) {
        const QPointF &p = outline[(k + rotation) % n];
        plane.emplace_back(p.x(), p.y());
        mesh.positions.push_back(tilted(p.x(), p.y()));
        mesh.cornerPosition.push_back(std::uint32_t(k));
    }
    mesh.faceStart.push_back(std::uint32_t(n));

    MeshStats stats;
    QStringList warnings;
    const BuiltMesh built = buildMeshData(mesh, NormalOptions());
    const MeshData &data = built.mesh;
    stats = built.stats;
    warnings = built.warnings;
    QCOMPARE(stats.triangles, n - 2);
    QVERIFY(warnings.isEmpty());
    double sum = 0.0;
    for (int t = 0; t < n - 2; ++t) {
        const glm::dvec3 normal = triangleNormal(data, t);
        QVERIFY2(glm::dot(normal, kTiltedNormal) > 0.0, "triangle wound against the polygon");
        sum += glm::length(normal) / 2;
        // The centroid, back in the plane's coordinates, lies inside.
        glm::dvec3 centroid(0.0);
        for (int k = 0; k < 3; ++k)
            centroid += glm::dvec3(data.positions[data.indices[3 * t + k]]) / 3.0;
        const glm::dvec3 d = centroid - glm::dvec3(0.5, -2, 3);
        const glm::dvec2 local(glm::dot(d, glm::normalize(glm::dvec3(1, 1, 0))),
                               glm::dot(d, glm::normalize(glm::dvec3(-1, 1, 2))));
        QVERIFY2(insidePolygon(plane, local),
                 qPrintable(QStringLiteral("triangle %1 outside").arg(t)));
    }
    QVERIFY2(std::abs(sum - area) < 1e-5, qPrintable(QString::number(sum)));
}

void TestMeshBuilder::randomStarPolygons()
{
    // Star-shaped polygons (corners at increasing angles, random radii) are
    // simple but deeply concave. Each must come out as n − 2 triangles, all
    // facing the polygon's way, with areas summing to the polygon's.
    std::mt19937 random(20240611);
    const auto uniform = [&] { return double(random()) / double(std::mt19937::max()); };
    for (int round = 0; round < 200; ++round) {
        const int n = 4 + int(uniform() * 40);
        PolygonMesh mesh;
        std::vector<glm::dvec2> plane;
        for (int k = 0; k < n; ++k) {
            const double angle = 2.0 * std::numbers::pi * (k + 0.8 * uniform()) / n;
            const double radius = 0.2 + uniform();
            plane.emplace_back(radius * std::cos(angle), radius * std::sin(angle));
            mesh.positions.push_back(tilted(plane.back().x, plane.back().y));
            mesh.cornerPosition.push_back(std::uint32_t(k));
        }
        mesh.faceStart.push_back(std::uint32_t(n));
        double area = 0.0;
        for (int k = 0; k < n; ++k) {
            const glm::dvec2 &p = plane[k], &q = plane[(k + 1) % n];
            area += (p.x * q.y - q.x * p.y) / 2;
        }

        const Triangulation triangulation = triangulate(mesh);
        QCOMPARE(triangulation.fanFallbacks, 0u);
        QCOMPARE(int(triangulation.triangleCount()), n - 2);
        double sum = 0.0;
        for (std::size_t t = 0; t < triangulation.corners.size(); t += 3) {
            const glm::dvec2 &a = plane[triangulation.corners[t]],
                             &b = plane[triangulation.corners[t + 1]],
                             &c = plane[triangulation.corners[t + 2]];
            const double doubleArea = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
            QVERIFY2(
                doubleArea > 0.0,
                qPrintable(QStringLiteral("round %1: triangle %2 flipped").arg(round).arg(t / 3)));
            sum += doubleArea / 2;
        }
        QVERIFY2(std::abs(sum - area) < 1e-5,
                 qPrintable(QStringLiteral("round %1: %2 vs %3").arg(round).arg(sum).arg(area)));
    }
}

void TestMeshBuilder::bowtieFallsBackToFan()
{
    // A quad crossing itself: its two lobes cancel, so it has no plane.
    PolygonMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}};
    addFace(mesh, {0, 1, 2, 3});
    QCOMPARE(triangulate(mesh).fanFallbacks, 1u);
    MeshStats stats;
    QStringList warnings;
    const BuiltMesh built = buildMeshData(mesh, NormalOptions());
    const MeshData &data = built.mesh;
    stats = built.stats;
    warnings = built.warnings;
    QCOMPARE(stats.triangles, 2);
    QCOMPARE(warnings.size(), 1);
    QVERIFY2(warnings.first().startsWith("1 polygons"), qPrintable(warnings.first()));
    for (const glm::vec3 &n : data.normals)
        QVERIFY(std::abs(glm::length(n) - 1.0f) < 1e-6f);
}

void TestMeshBuilder::autoWithPartialNormalsComputes()
{
    // The +X face (corners 0..3) lost its normals: compute all of them.
    PolygonMesh mesh = flatCube();
    for (int c = 0; c < 4; ++c)
        mesh.cornerNormal[c] = PolygonMesh::kNoNormal;
    MeshStats stats;
    QStringList warnings;
    const BuiltMesh built = buildMeshData(mesh, NormalOptions());
    const MeshData &data = built.mesh;
    stats = built.stats;
    warnings = built.warnings;
    QVERIFY(!stats.normalsFromFile);
    QCOMPARE(stats.normalMethod, NormalMethod::AngleWeighted);
    QCOMPARE(stats.vertices, 8);
    QCOMPARE(warnings.size(), 1);
    QVERIFY2(warnings.first().startsWith("4 of 24 corners have no normal"),
             qPrintable(warnings.first()));
    for (std::size_t v = 0; v < data.positions.size(); ++v)
        QVERIFY(glm::length(data.normals[v] - data.positions[v] / std::sqrt(3.0f)) < 1e-6f);
}

void TestMeshBuilder::unusableFileNormalsAreReplaced()
{
    // The +X face's normal is zero, the −X face's NaN: their 8 corners get
    // the computed angle-weighted normal, the cube diagonal; the other
    // faces keep theirs. Those 8 corners are distinct vertices: 24 in all.
    PolygonMesh mesh = flatCube();
    mesh.normals[0] = glm::vec3(0.0f);
    mesh.normals[1] = glm::vec3(std::nanf(""), 0, 0);
    MeshStats stats;
    QStringList warnings;
    const BuiltMesh built = buildMeshData(mesh, NormalOptions());
    const MeshData &data = built.mesh;
    stats = built.stats;
    warnings = built.warnings;
    QVERIFY(stats.normalsFromFile);
    QCOMPARE(stats.vertices, 24);
    QCOMPARE(warnings.size(), 1);
    QVERIFY2(warnings.first().startsWith("8 of 24 corners have a zero or invalid normal"),
             qPrintable(warnings.first()));
    for (int f = 0; f < 6; ++f) {
        for (int c = 0; c < 6; ++c) {
            const std::uint32_t v = data.indices[6 * f + c];
            const glm::vec3 expected =
                f < 2 ? data.positions[v] / std::sqrt(3.0f) : kCubeFaceNormals[f];
            QVERIFY(glm::length(data.normals[v] - expected) < 1e-6f);
        }
    }
}

void TestMeshBuilder::fileNormalsKeptAsWritten()
{
    // Unit normals pass through bit for bit, including six-decimal ones as
    // OBJ files write them ((1, 2, 3)/√14 here, length 1 − 4e-7), which
    // dividing by their length would nudge. Others are normalised.
    PolygonMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    mesh.normals = {{0.6f, 0.8f, 0.0f},
                    {0.267261f, 0.534522f, 0.801784f},
                    {0.0f, 3.0f, 4.0f},
                    {0.0f, 0.0f, 0.5f}};
    addFace(mesh, {0, 1, 2});
    addFace(mesh, {2, 1, 3});
    mesh.cornerNormal = {0, 1, 2, 2, 1, 3};
    const BuiltMesh built = buildMeshData(mesh, NormalOptions());
    const MeshData &data = built.mesh;
    QCOMPARE(data.normals[data.indices[0]], glm::vec3(0.6f, 0.8f, 0.0f));
    QCOMPARE(data.normals[data.indices[1]], glm::vec3(0.267261f, 0.534522f, 0.801784f));
    QCOMPARE(data.normals[data.indices[2]], glm::vec3(0.0f, 0.6f, 0.8f));
    QCOMPARE(data.normals[data.indices[5]], glm::vec3(0.0f, 0.0f, 1.0f));
}

void TestMeshBuilder::boundsAndStats()
{
    // A box from (−1, −2, 0) to (3, 2, 0.5), plus one position no face uses:
    // it counts as a file vertex but neither as a GPU vertex nor in bounds.
    PolygonMesh mesh = smoothCube();
    for (glm::vec3 &p : mesh.positions)
        p = glm::vec3(1, 0, 0.25f) + p * glm::vec3(2, 2, 0.25f);
    mesh.positions.emplace_back(100, 100, 100);
    MeshStats stats;
    const BuiltMesh built = buildMeshData(mesh, {NormalMethod::Flat, std::nullopt});
    const MeshData &data = built.mesh;
    stats = built.stats;
    QCOMPARE(stats.fileVertices, 9);
    QCOMPARE(stats.vertices, 24);
    QCOMPARE(stats.splitVertices, 16);
    QCOMPARE(stats.triangles, 12);
    QCOMPARE(stats.boundsMin, glm::vec3(-1, -2, 0));
    QCOMPARE(stats.boundsMax, glm::vec3(3, 2, 0.5f));
    QCOMPARE(qint64(data.positions.size()), stats.vertices);
}

void TestMeshBuilder::emptyMeshFails()
{
    PolygonMesh mesh;
    mesh.positions = {{0, 0, 0}};
    QString error;
    const BuiltMesh built = buildMeshData(mesh, NormalOptions());
    const MeshData &data = built.mesh;
    error = built.error;
    QVERIFY(data.positions.empty());
    QVERIFY(data.indices.empty());
    QCOMPARE(error, QStringLiteral("the mesh has no faces"));
}

void TestMeshBuilder::minusZeroIsPlusZeroEverywhere()
{
    // A tetrahedron whose file writes one normal twice, once with -0 where
    // the other has 0 (Blender writes both). One position, one normal: one
    // GPU vertex, no split, whichever zero a corner names.
    PolygonMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    mesh.normals = {{0.0f, 0.0f, -1.0f}, {-0.0f, -0.0f, -1.0f}};
    addFace(mesh, {0, 2, 1});
    addFace(mesh, {0, 1, 3});
    addFace(mesh, {0, 3, 2});
    addFace(mesh, {1, 2, 3});
    // Position 0 gets the -0 spelling in one face and the +0 one in another;
    // the rest share the +0 one (the normals are not meant to be right).
    mesh.cornerNormal = {0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0};
    const BuiltMesh built = buildMeshData(mesh, {NormalMethod::Auto, std::nullopt});
    QVERIFY2(built.error.isEmpty(), qPrintable(built.error));
    QCOMPARE(qint64(built.mesh.positions.size()), 4);
    QCOMPARE(built.stats.splitVertices, 0);

    // Decimation welds positions with the same key: a closed mesh whose
    // copies of one corner differ only in the sign of a zero stays closed.
    const BuiltMesh flat = buildMeshData(mesh, {NormalMethod::Flat, std::nullopt});
    MeshData signed0 = flat.mesh;
    QVERIFY(isClosedMesh(signed0));
    int flipped = 0;
    for (glm::vec3 &p : signed0.positions)
        if (p == glm::vec3(0, 0, 0) && flipped++ % 2 == 0)
            p = glm::vec3(-0.0f, 0.0f, -0.0f);
    QCOMPARE(flipped, 3);
    QVERIFY(isClosedMesh(signed0));
}

QTEST_GUILESS_MAIN(TestMeshBuilder)
#include "tst_meshbuilder.moc"
