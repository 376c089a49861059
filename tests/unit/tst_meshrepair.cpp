#include "mesh/import/MeshRepair.h"

#include <QtTest>

#include <cmath>
#include <limits>
#include <map>

using namespace phonglab;

namespace {

using Faces = std::vector<std::vector<std::uint32_t>>;

PolygonMesh makeMesh(std::vector<glm::vec3> positions, const Faces &faces)
{
    PolygonMesh m;
    m.positions = std::move(positions);
    for (const auto &face : faces) {
        m.cornerPosition.insert(m.cornerPosition.end(), face.begin(), face.end());
        m.faceStart.push_back(std::uint32_t(m.cornerPosition.size()));
    }
    return m;
}

const std::vector<glm::vec3> kTetraPositions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
const Faces kTetraFaces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

const std::vector<glm::vec3> kCubePositions = {{1, 1, -1},  {1, -1, -1},  {1, 1, 1},  {1, -1, 1},
                                               {-1, 1, -1}, {-1, -1, -1}, {-1, 1, 1}, {-1, -1, 1}};
const Faces kCubeFaces = {{0, 4, 6, 2}, {3, 2, 6, 7}, {7, 6, 4, 5},
                          {5, 1, 3, 7}, {1, 0, 2, 3}, {5, 4, 0, 1}};

Faces reversed(Faces faces, std::initializer_list<int> which)
{
    for (int f : which)
        std::reverse(faces[f].begin(), faces[f].end());
    return faces;
}

// Every directed edge used at most once and, on a closed mesh, its reverse
// used too: the winding agrees across all edges.
bool windingConsistent(const PolygonMesh &m)
{
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (std::size_t f = 0; f < m.faceCount(); ++f) {
        for (std::uint32_t c = m.faceStart[f]; c < m.faceStart[f + 1]; ++c) {
            const std::uint32_t next = c + 1 < m.faceStart[f + 1] ? c + 1 : m.faceStart[f];
            if (++directed[{m.cornerPosition[c], m.cornerPosition[next]}] > 1)
                return false;
        }
    }
    return true;
}

double signedVolume(const PolygonMesh &m)
{
    double v = 0.0;
    for (std::size_t f = 0; f < m.faceCount(); ++f) {
        const glm::dvec3 p0(m.positions[m.cornerPosition[m.faceStart[f]]]);
        for (std::uint32_t c = m.faceStart[f] + 1; c + 1 < m.faceStart[f + 1]; ++c)
            v += glm::dot(p0,
                          glm::cross(glm::dvec3(m.positions[m.cornerPosition[c]]),
                                     glm::dvec3(m.positions[m.cornerPosition[c + 1]])));
    }
    return v / 6.0;
}

} // namespace

Q_DECLARE_METATYPE(std::vector<glm::vec3>)
Q_DECLARE_METATYPE(Faces)

class TestMeshRepair : public QObject
{
    Q_OBJECT

private slots:
    void cleanMeshUnchanged()
    {
        PolygonMesh m = makeMesh(kTetraPositions, kTetraFaces);
        const std::vector<std::uint32_t> before = m.cornerPosition;
        const RepairReport r = repairMesh(m);
        QVERIFY(r.warnings().isEmpty());
        QCOMPARE(m.cornerPosition, before);
        QCOMPARE(m.positions.size(), std::size_t(4));
    }

    void outOfRangeAndNegativeIndicesDropped()
    {
        // Readers store an index that cannot be resolved as 0xffffffff.
        Faces faces = kTetraFaces;
        faces.push_back({0, 1, 4});
        faces.push_back({0xffffffffu, 1, 2});
        PolygonMesh m = makeMesh(kTetraPositions, faces);
        const RepairReport r = repairMesh(m);
        QCOMPARE(r.facesDroppedBadIndex, 2);
        QCOMPARE(m.faceCount(), std::size_t(4));
        QCOMPARE(r.warnings(), QStringList{"dropped 2 faces with out-of-range vertex indices"});
    }

    void nonFiniteFacesDropped()
    {
        std::vector<glm::vec3> p = kTetraPositions;
        p.push_back({std::numeric_limits<float>::quiet_NaN(), 0, 0});
        p.push_back({0, std::numeric_limits<float>::infinity(), 0});
        Faces faces = kTetraFaces;
        faces.push_back({0, 1, 4});
        faces.push_back({1, 2, 5});
        PolygonMesh m = makeMesh(p, faces);
        const RepairReport r = repairMesh(m);
        QCOMPARE(r.facesDroppedNonFinite, 2);
        QCOMPARE(r.isolatedVerticesRemoved, 2);
        QCOMPARE(m.faceCount(), std::size_t(4));
        for (const glm::vec3 &v : m.positions)
            QVERIFY(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
        QCOMPARE(r.warnings(),
                 (QStringList{"dropped 2 faces using NaN or infinite coordinates",
                              "removed 2 vertices no face uses"}));
    }

    void degenerateFacesDropped()
    {
        std::vector<glm::vec3> p = kTetraPositions;
        p.push_back({2, 0, 0}); // 4: on the line through 0 and 1
        p.push_back({0, 0, 0}); // 5: at vertex 0's position
        p.push_back({5, 0, 0});
        p.push_back({6, 0, 0});
        p.push_back({5, 1, 0});
        Faces faces = kTetraFaces;
        faces.push_back({0, 1, 4});       // collinear
        faces.push_back({0, 1, 1});       // a repeated index
        faces.push_back({0, 5, 2});       // two corners at one position
        faces.push_back({0, 1});          // too few corners
        faces.push_back({0, 1, 0, 2, 2}); // out and back: no area
        faces.push_back({6, 7, 7, 8});    // a repeated corner, yet a real triangle
        PolygonMesh m = makeMesh(p, faces);
        const RepairReport r = repairMesh(m);
        QCOMPARE(r.facesDroppedDegenerate, 5);
        QCOMPARE(m.faceCount(), std::size_t(5));
        QCOMPARE(r.warnings().first(),
                 QStringLiteral(
                     "dropped 5 degenerate faces (fewer than 3 distinct corners or zero area)"));
    }

    void tinyButRealFacesKept()
    {
        // Small and thin is not zero: a sliver with aspect 1e-5 stays.
        PolygonMesh m = makeMesh({{0, 0, 0}, {1e-3f, 0, 0}, {0.5e-3f, 1e-8f, 0}}, {{0, 1, 2}});
        const RepairReport r = repairMesh(m);
        QCOMPARE(r.facesDroppedDegenerate, 0);
        QCOMPARE(m.faceCount(), std::size_t(1));
    }

    void nonManifoldEdgeKept()
    {
        PolygonMesh m = makeMesh({{0, 0, 0}, {1, 0, 0}, {0.5f, 1, 0}, {0.5f, -1, 0}, {0.5f, 0, 1}},
                                 {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
        const RepairReport r = repairMesh(m);
        QCOMPARE(r.nonManifoldEdges, 1);
        QCOMPARE(m.faceCount(), std::size_t(3));
        QCOMPARE(r.warnings(),
                 QStringList{"1 non-manifold edge (shared by 3 or more faces), kept as they are"});
    }

    void windingMadeConsistent_data()
    {
        QTest::addColumn<std::vector<glm::vec3>>("positions");
        QTest::addColumn<Faces>("faces");
        QTest::addColumn<int>("flipped");
        QTest::newRow("tetrahedron, first face flipped")
            << kTetraPositions << reversed(kTetraFaces, {0}) << 1;
        QTest::newRow("tetrahedron, last face flipped")
            << kTetraPositions << reversed(kTetraFaces, {3}) << 1;
        QTest::newRow("tetrahedron inside out")
            << kTetraPositions << reversed(kTetraFaces, {0, 1, 2, 3}) << 4;
        QTest::newRow("cube, one face flipped") << kCubePositions << reversed(kCubeFaces, {2}) << 1;
        QTest::newRow("cube, two faces flipped")
            << kCubePositions << reversed(kCubeFaces, {0, 5}) << 2;
        // Closed: the outside decides, not the majority.
        QTest::newRow("cube, four faces flipped")
            << kCubePositions << reversed(kCubeFaces, {0, 1, 2, 3}) << 4;
    }

    void windingMadeConsistent()
    {
        QFETCH(std::vector<glm::vec3>, positions);
        QFETCH(Faces, faces);
        QFETCH(int, flipped);
        PolygonMesh m = makeMesh(positions, faces);
        const RepairReport r = repairMesh(m);
        QCOMPARE(r.facesFlipped, flipped);
        QVERIFY(windingConsistent(m));
        QVERIFY2(signedVolume(m) > 0.0, "closed meshes end up wound outwards");
        QCOMPARE(r.warnings(),
                 QStringList{QStringLiteral("flipped %1 to make the winding consistent")
                                 .arg(flipped == 1 ? QStringLiteral("1 face")
                                                   : QStringLiteral("%1 faces").arg(flipped))});
    }

    void openSurfaceFollowsTheMajority()
    {
        // A strip of three quads with the middle one reversed.
        PolygonMesh m = makeMesh({{0, 0, 0},
                                  {0, 1, 0},
                                  {1, 0, 0},
                                  {1, 1, 0},
                                  {2, 0, 0},
                                  {2, 1, 0},
                                  {3, 0, 0},
                                  {3, 1, 0}},
                                 {{0, 2, 3, 1}, {2, 3, 5, 4}, {4, 6, 7, 5}});
        const RepairReport r = repairMesh(m);
        QCOMPARE(r.facesFlipped, 1);
        QVERIFY(windingConsistent(m));
        QCOMPARE(m.cornerPosition[0], 0u); // the majority orientation is kept
        QCOMPARE(m.cornerPosition[1], 2u);
    }

    void flipCarriesCornerNormals()
    {
        PolygonMesh m = makeMesh(kTetraPositions, reversed(kTetraFaces, {0}));
        m.normals = {{0, 0, -1}, {0, -1, 0}, {-1, 0, 0}, {1, 1, 1}};
        m.cornerNormal = {0, 1, 2, 3, 3, 3, 3, 3, 3, 3, 3, 3};
        const RepairReport r = repairMesh(m);
        QCOMPARE(r.facesFlipped, 1);
        // The first corner stays, the others turn with their normals:
        // (1 2 0) with normals (0 1 2) becomes (1 0 2) with (0 2 1).
        QCOMPARE(std::vector<std::uint32_t>(m.cornerPosition.begin(), m.cornerPosition.begin() + 3),
                 (std::vector<std::uint32_t>{1, 0, 2}));
        QCOMPARE(std::vector<std::uint32_t>(m.cornerNormal.begin(), m.cornerNormal.begin() + 3),
                 (std::vector<std::uint32_t>{0, 2, 1}));
    }

    void nonOrientableSurfaceCounted()
    {
        // A Möbius strip of four quads: no winding agrees on every edge.
        std::vector<glm::vec3> p;
        const int n = 4;
        for (int i = 0; i < n; ++i) {
            const float a = float(i) * 2.0f * float(M_PI) / n;
            const float t = a / 2.0f;
            const glm::vec3 centre(std::cos(a), std::sin(a), 0.0f);
            const glm::vec3 across(std::cos(t) * std::cos(a), std::cos(t) * std::sin(a),
                                   std::sin(t));
            p.push_back(centre - 0.3f * across);
            p.push_back(centre + 0.3f * across);
        }
        Faces faces;
        for (int i = 0; i + 1 < n; ++i)
            faces.push_back({std::uint32_t(2 * i), std::uint32_t(2 * i + 2),
                             std::uint32_t(2 * i + 3), std::uint32_t(2 * i + 1)});
        faces.push_back(
            {std::uint32_t(2 * n - 2), 1, 0, std::uint32_t(2 * n - 1)}); // the half twist
        PolygonMesh m = makeMesh(p, faces);
        const RepairReport r = repairMesh(m);
        QCOMPARE(r.orientationConflicts, 1);
        QCOMPARE(m.faceCount(), std::size_t(n));
    }

    void isolatedVerticesRemoved()
    {
        std::vector<glm::vec3> p = {{5, 5, 5}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                                    {6, 6, 6}, {0, 0, 1}, {7, 7, 7}};
        PolygonMesh m = makeMesh(p, {{1, 3, 2}, {1, 2, 5}, {1, 5, 3}, {2, 3, 5}});
        const RepairReport r = repairMesh(m);
        QCOMPARE(r.isolatedVerticesRemoved, 3);
        QCOMPARE(m.positions, kTetraPositions);
        QCOMPARE(m.cornerPosition,
                 (std::vector<std::uint32_t>{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}));
        QCOMPARE(r.warnings(), QStringList{"removed 3 vertices no face uses"});
    }

    void bowtieVertexSplit()
    {
        // Two triangles meeting at vertex 0 only.
        PolygonMesh m = makeMesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}},
                                 {{0, 1, 2}, {0, 3, 4}});
        const RepairReport r = repairMesh(m);
        QCOMPARE(r.verticesDuplicated, 1);
        QCOMPARE(m.positions.size(), std::size_t(6));
        QVERIFY(m.cornerPosition[0] != m.cornerPosition[3]);
        QCOMPARE(m.positions[m.cornerPosition[0]], m.positions[m.cornerPosition[3]]);
        QCOMPARE(r.warnings(),
                 QStringList{"split 1 vertex where surfaces touch only at that point"});
    }

    void fanAroundVertexNotSplit()
    {
        // A closed fan and the cube: every vertex is one surface.
        PolygonMesh cube = makeMesh(kCubePositions, kCubeFaces);
        QCOMPARE(repairMesh(cube).verticesDuplicated, 0);
        PolygonMesh fan = makeMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}},
                                   {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}});
        const RepairReport r = repairMesh(fan);
        QVERIFY(r.warnings().isEmpty());
    }

    void badNormalsDiscarded()
    {
        PolygonMesh m = makeMesh(kTetraPositions, kTetraFaces);
        m.normals = {{0, 0, -1}, {std::numeric_limits<float>::quiet_NaN(), 0, 0}, {0, 0, 0}};
        m.cornerNormal = {0, 0, 0, 1, 1, 1, 2, 2, 2, 7, PolygonMesh::kNoNormal, 0};
        const RepairReport r = repairMesh(m);
        QCOMPARE(r.normalsDiscarded, 7);
        const std::uint32_t none = PolygonMesh::kNoNormal;
        QCOMPARE(m.cornerNormal,
                 (std::vector<std::uint32_t>{0, 0, 0, none, none, none, none, none, none, none,
                                             none, 0}));
    }

    void everythingDroppedLeavesNoFaces()
    {
        PolygonMesh m = makeMesh({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {{0, 1, 2}, {0, 1, 5}});
        const RepairReport r = repairMesh(m);
        QCOMPARE(m.faceCount(), std::size_t(0));
        QVERIFY(m.positions.empty());
        QCOMPARE(r.warnings().size(), 3);
    }
};

QTEST_GUILESS_MAIN(TestMeshRepair)
#include "tst_meshrepair.moc"
