#include "mesh/import/MeshTopology.h"

#include <QtTest>

#include <map>
#include <random>

using namespace phonglab;

namespace {

using Faces = std::vector<std::vector<std::uint32_t>>;

PolygonMesh makeMesh(std::size_t positions, const Faces &faces)
{
    PolygonMesh m;
    m.positions.assign(positions, glm::vec3(0.0f));
    for (const auto &face : faces) {
        m.cornerPosition.insert(m.cornerPosition.end(), face.begin(), face.end());
        m.faceStart.push_back(std::uint32_t(m.cornerPosition.size()));
    }
    return m;
}

// The definition, spelled out: every undirected edge used by exactly two
// face sides.
bool closedByCounting(const PolygonMesh &m)
{
    if (m.faceCount() == 0)
        return false;
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
    for (std::size_t f = 0; f < m.faceCount(); ++f) {
        for (std::uint32_t c = m.faceStart[f]; c < m.faceStart[f + 1]; ++c) {
            const std::uint32_t next = c + 1 < m.faceStart[f + 1] ? c + 1 : m.faceStart[f];
            const std::uint32_t a = m.cornerPosition[c], b = m.cornerPosition[next];
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    }
    return std::all_of(uses.begin(), uses.end(), [](const auto &e) { return e.second == 2; });
}

const Faces kTetra = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

// A cone of `sides` triangles around apex 0, closed by a fan of triangles
// around apex `sides + 1`: both apexes have more neighbours than the small
// buckets sort by insertion.
Faces doubleCone(std::uint32_t sides)
{
    Faces faces;
    const std::uint32_t bottom = sides + 1;
    for (std::uint32_t i = 0; i < sides; ++i) {
        const std::uint32_t a = 1 + i, b = 1 + (i + 1) % sides;
        faces.push_back({0, a, b});
        faces.push_back({bottom, b, a});
    }
    return faces;
}

} // namespace

Q_DECLARE_METATYPE(Faces)

class TestMeshTopology : public QObject
{
    Q_OBJECT

private slots:
    void closedSurface_data()
    {
        QTest::addColumn<std::size_t>("positions");
        QTest::addColumn<Faces>("faces");
        QTest::addColumn<bool>("closed");
        QTest::newRow("tetrahedron") << std::size_t(4) << kTetra << true;
        QTest::newRow("open: one face missing")
            << std::size_t(4) << Faces(kTetra.begin(), kTetra.end() - 1) << false;
        Faces threeOnEdge = kTetra;
        threeOnEdge.push_back({0, 1, 4});
        QTest::newRow("an edge of three faces") << std::size_t(5) << threeOnEdge << false;
        Faces twice = kTetra;
        twice.insert(twice.end(), kTetra.begin(), kTetra.end());
        QTest::newRow("every edge four times") << std::size_t(4) << twice << false;
        QTest::newRow("a face and its reverse")
            << std::size_t(3) << Faces{{0, 1, 2}, {0, 2, 1}} << true;
        QTest::newRow("quad with a repeated corner")
            << std::size_t(3) << Faces{{0, 0, 1, 2}, {0, 2, 1}} << false;
        QTest::newRow("wide double cone") << std::size_t(202) << doubleCone(200) << true;
        Faces broken = doubleCone(200);
        broken.pop_back();
        QTest::newRow("wide double cone, one face missing") << std::size_t(202) << broken << false;
        QTest::newRow("index beyond the positions")
            << std::size_t(3) << Faces{{0, 1, 0xffffffffu}, {0, 0xffffffffu, 1}} << true;
    }

    void closedSurface()
    {
        QFETCH(std::size_t, positions);
        QFETCH(Faces, faces);
        QFETCH(bool, closed);
        const PolygonMesh m = makeMesh(positions, faces);
        QCOMPARE(closedByCounting(m), closed); // the row itself is right
        QCOMPARE(isClosedSurface(m), closed);
    }

    void emptyMeshIsNotClosed() { QVERIFY(!isClosedSurface(makeMesh(3, {}))); }

    // Small random polygon soups over few vertices hit every case at once:
    // edges used once, twice, three and more times, repeated corners.
    void agreesWithCountingOnRandomSoups()
    {
        std::mt19937 rng(7);
        int closedSeen = 0;
        for (int trial = 0; trial < 4000; ++trial) {
            const std::uint32_t vertices = 3 + rng() % 6;
            Faces faces;
            const int count = 1 + int(rng() % 8);
            for (int f = 0; f < count; ++f) {
                std::vector<std::uint32_t> face(3 + rng() % 2);
                for (std::uint32_t &v : face)
                    v = rng() % vertices;
                faces.push_back(face);
                if (rng() % 2) { // its reverse too: closed soups are common enough
                    std::reverse(face.begin(), face.end());
                    faces.push_back(face);
                }
            }
            const PolygonMesh m = makeMesh(vertices, faces);
            const bool expected = closedByCounting(m);
            closedSeen += expected;
            QCOMPARE(isClosedSurface(m), expected);
        }
        QVERIFY(closedSeen > 100); // both answers were exercised
    }
};

QTEST_GUILESS_MAIN(TestMeshTopology)
#include "tst_meshtopology.moc"
