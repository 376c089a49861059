#include "MeshRepair.h"

#include "MeshTextTokens.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>
#include <future>
#include <numeric>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct MeshRepairWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::MeshRepair)
};

namespace {

constexpr std::uint32_t kUnset = 0xffffffffu;

// Faces whose area is below this fraction of their longest edge squared
// are flat to within double rounding: no normal can be had from them.
constexpr double kZeroAreaRatio = 1e-10;

bool isFinite(const glm::vec3 &v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

int discardBadNormals(PolygonMesh &mesh)
{
    if (mesh.cornerNormal.empty())
        return 0;
    mesh.cornerNormal.resize(mesh.cornerPosition.size(), PolygonMesh::kNoNormal);
    std::vector<char> usable(mesh.normals.size());
    for (std::size_t i = 0; i < mesh.normals.size(); ++i)
        usable[i] = isFinite(mesh.normals[i]) && glm::dot(mesh.normals[i], mesh.normals[i]) > 0.0f;
    int discarded = 0;
    for (std::uint32_t &n : mesh.cornerNormal) {
        if (n != PolygonMesh::kNoNormal && (n >= usable.size() || !usable[n])) {
            n = PolygonMesh::kNoNormal;
            ++discarded;
        }
    }
    return discarded;
}

bool isDegenerate(const PolygonMesh &mesh, std::uint32_t begin, std::uint32_t end)
{
    const std::uint32_t count = end - begin;
    if (count < 3)
        return true;
    const glm::dvec3 p0(mesh.positions[mesh.cornerPosition[begin]]);
    glm::dvec3 area(0.0);
    double longestEdge2 = 0.0;
    for (std::uint32_t i = 0; i < count; ++i) {
        const glm::dvec3 a = glm::dvec3(mesh.positions[mesh.cornerPosition[begin + i]]) - p0;
        const glm::dvec3 b =
            glm::dvec3(mesh.positions[mesh.cornerPosition[begin + (i + 1) % count]]) - p0;
        area += glm::cross(a, b);
        longestEdge2 = std::max(longestEdge2, glm::dot(b - a, b - a));
    }
    // Zero area also covers fewer than 3 distinct positions.
    return longestEdge2 == 0.0 || glm::length(area) <= kZeroAreaRatio * longestEdge2;
}

void dropUnusableFaces(PolygonMesh &mesh, RepairReport &report)
{
    std::vector<char> finite(mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
        finite[i] = isFinite(mesh.positions[i]);
    const bool normals = mesh.hasNormals();
    std::uint32_t out = 0;
    std::size_t kept = 0;
    for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
        const std::uint32_t begin = mesh.faceStart[f];
        const std::uint32_t end = mesh.faceStart[f + 1];
        bool badIndex = false;
        bool nonFinite = false;
        for (std::uint32_t c = begin; c < end; ++c) {
            const std::uint32_t v = mesh.cornerPosition[c];
            badIndex = badIndex || v >= finite.size();
            nonFinite = nonFinite || (v < finite.size() && !finite[v]);
        }
        if (badIndex) {
            ++report.facesDroppedBadIndex;
            continue;
        }
        if (nonFinite) {
            ++report.facesDroppedNonFinite;
            continue;
        }
        if (isDegenerate(mesh, begin, end)) {
            ++report.facesDroppedDegenerate;
            continue;
        }
        for (std::uint32_t c = begin; c < end; ++c, ++out) {
            mesh.cornerPosition[out] = mesh.cornerPosition[c];
            if (normals)
                mesh.cornerNormal[out] = mesh.cornerNormal[c];
        }
        mesh.faceStart[++kept] = out;
    }
    mesh.faceStart.resize(kept + 1);
    mesh.cornerPosition.resize(out);
    if (normals)
        mesh.cornerNormal.resize(out);
}

// Edge adjacency: every face side, grouped by its undirected edge.
struct Side {
    std::uint32_t other; // the larger vertex index of the edge
    std::uint32_t face;
    std::uint32_t corner; // the corner the side starts at
    bool forward;         // runs from the smaller vertex to the larger
};

struct Adjacency {
    std::vector<std::uint32_t> cornerFace;
    std::vector<std::uint32_t> bucketStart; // per smaller vertex, into sides
    std::vector<Side> sides;                // within a bucket sorted by `other`
};

std::uint32_t nextCorner(const PolygonMesh &mesh, const std::vector<std::uint32_t> &cornerFace,
                         std::uint32_t c)
{
    const std::uint32_t f = cornerFace[c];
    return c + 1 < mesh.faceStart[f + 1] ? c + 1 : mesh.faceStart[f];
}

Adjacency buildAdjacency(const PolygonMesh &mesh)
{
    // A counting sort by the smaller vertex, then each (small) bucket
    // sorted: linear time, no hashing.
    Adjacency adj;
    const std::size_t corners = mesh.cornerPosition.size();
    adj.cornerFace.resize(corners);
    for (std::size_t f = 0; f < mesh.faceCount(); ++f)
        for (std::uint32_t c = mesh.faceStart[f]; c < mesh.faceStart[f + 1]; ++c)
            adj.cornerFace[c] = std::uint32_t(f);
    adj.bucketStart.assign(mesh.positions.size() + 1, 0);
    auto ends = [&](std::uint32_t c) {
        return std::pair(mesh.cornerPosition[c],
                         mesh.cornerPosition[nextCorner(mesh, adj.cornerFace, c)]);
    };
    for (std::uint32_t c = 0; c < corners; ++c) {
        const auto [a, b] = ends(c);
        if (a != b)
            ++adj.bucketStart[std::min(a, b) + 1];
    }
    std::partial_sum(adj.bucketStart.begin(), adj.bucketStart.end(), adj.bucketStart.begin());
    adj.sides.resize(adj.bucketStart.back());
    std::vector<std::uint32_t> fill(adj.bucketStart.begin(), adj.bucketStart.end() - 1);
    for (std::uint32_t c = 0; c < corners; ++c) {
        const auto [a, b] = ends(c);
        if (a != b)
            adj.sides[fill[std::min(a, b)]++] = {std::max(a, b), adj.cornerFace[c], c, a < b};
    }
    for (std::size_t v = 0; v + 1 < adj.bucketStart.size(); ++v)
        std::sort(adj.sides.begin() + adj.bucketStart[v],
                  adj.sides.begin() + adj.bucketStart[v + 1], [](const Side &x, const Side &y) {
                      return x.other < y.other || (x.other == y.other && x.face < y.face);
                  });
    return adj;
}

// Calls visit(first, count) for each run of sides sharing an edge.
template <typename Visit> void forEachEdge(const Adjacency &adj, Visit visit)
{
    const std::size_t n = adj.sides.size();
    for (std::size_t v = 0; v + 1 < adj.bucketStart.size(); ++v) {
        for (std::size_t i = adj.bucketStart[v]; i < adj.bucketStart[v + 1];) {
            std::size_t j = i + 1;
            while (j < n && j < adj.bucketStart[v + 1] && adj.sides[j].other == adj.sides[i].other)
                ++j;
            visit(i, j - i);
            i = j;
        }
    }
}

double signedVolume(const PolygonMesh &mesh, const std::vector<std::uint32_t> &faces,
                    const std::vector<char> &flip)
{
    const glm::dvec3 origin(mesh.positions[mesh.cornerPosition[mesh.faceStart[faces.front()]]]);
    double volume = 0.0;
    for (std::uint32_t f : faces) {
        const std::uint32_t begin = mesh.faceStart[f];
        const glm::dvec3 p0 = glm::dvec3(mesh.positions[mesh.cornerPosition[begin]]) - origin;
        double v = 0.0;
        for (std::uint32_t c = begin + 1; c + 1 < mesh.faceStart[f + 1]; ++c) {
            const glm::dvec3 p1 = glm::dvec3(mesh.positions[mesh.cornerPosition[c]]) - origin;
            const glm::dvec3 p2 = glm::dvec3(mesh.positions[mesh.cornerPosition[c + 1]]) - origin;
            v += glm::dot(p0, glm::cross(p1, p2));
        }
        volume += flip[f] ? -v : v;
    }
    return volume / 6.0;
}

// Which faces to turn so the winding agrees across manifold edges. Reads
// the mesh, changes nothing: it runs beside bowtieGroups().
std::vector<char> windingFlips(const PolygonMesh &mesh, const Adjacency &adj, RepairReport &report)
{
    const std::size_t faces = mesh.faceCount();
    // Neighbours across manifold edges, and whether the two faces run the
    // edge the same way (then one of them must turn).
    std::vector<std::uint32_t> start(faces + 1, 0);
    forEachEdge(adj, [&](std::size_t i, std::size_t n) {
        if (n == 2 && adj.sides[i].face != adj.sides[i + 1].face) {
            ++start[adj.sides[i].face + 1];
            ++start[adj.sides[i + 1].face + 1];
        }
    });
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<std::pair<std::uint32_t, bool>> links(start.back());
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    forEachEdge(adj, [&](std::size_t i, std::size_t n) {
        if (n != 2 || adj.sides[i].face == adj.sides[i + 1].face)
            return;
        const Side &a = adj.sides[i];
        const Side &b = adj.sides[i + 1];
        const bool same = a.forward == b.forward;
        links[fill[a.face]++] = {b.face, same};
        links[fill[b.face]++] = {a.face, same};
    });
    // A face on the boundary has a side (two distinct ends) with no link.
    // Counted face by face, not side by side: one pass in memory order.
    std::vector<char> allSidesPaired(faces);
    for (std::size_t f = 0; f < faces; ++f) {
        std::uint32_t sides = 0;
        const std::uint32_t begin = mesh.faceStart[f], end = mesh.faceStart[f + 1];
        for (std::uint32_t c = begin; c < end; ++c)
            sides += mesh.cornerPosition[c] != mesh.cornerPosition[c + 1 < end ? c + 1 : begin];
        allSidesPaired[f] = sides == start[f + 1] - start[f];
    }

    std::vector<char> flip(faces, 0);
    std::vector<char> seen(faces, 0);
    std::vector<std::uint32_t> component;
    for (std::uint32_t seed = 0; seed < faces; ++seed) {
        if (seen[seed])
            continue;
        component.clear();
        component.push_back(seed);
        seen[seed] = 1;
        bool closed = true;
        int conflicts = 0;
        for (std::size_t q = 0; q < component.size(); ++q) {
            const std::uint32_t f = component[q];
            closed = closed && allSidesPaired[f];
            for (std::uint32_t l = start[f]; l < start[f + 1]; ++l) {
                const auto [g, same] = links[l];
                const char want = char(flip[f] ^ char(same));
                if (!seen[g]) {
                    seen[g] = 1;
                    flip[g] = want;
                    component.push_back(g);
                } else if (flip[g] != want) {
                    ++conflicts; // seen from both faces of the edge
                }
            }
        }
        report.orientationConflicts += conflicts / 2;
        std::size_t flipped = 0;
        for (std::uint32_t f : component)
            flipped += flip[f];
        bool invert = 2 * flipped > component.size();
        if (closed && conflicts == 0) {
            const double volume = signedVolume(mesh, component, flip);
            if (volume != 0.0)
                invert = volume < 0.0;
        }
        if (invert)
            for (std::uint32_t f : component)
                flip[f] = char(!flip[f]);
    }
    return flip;
}

void flipFaces(PolygonMesh &mesh, const std::vector<char> &flip, RepairReport &report)
{
    for (std::size_t f = 0; f < flip.size(); ++f) {
        if (!flip[f])
            continue;
        ++report.facesFlipped;
        // Keep the first corner, reverse the rest: the same polygon, turned.
        const std::uint32_t begin = mesh.faceStart[f] + 1;
        const std::uint32_t end = mesh.faceStart[f + 1];
        std::reverse(mesh.cornerPosition.begin() + begin, mesh.cornerPosition.begin() + end);
        if (mesh.hasNormals())
            std::reverse(mesh.cornerNormal.begin() + begin, mesh.cornerNormal.begin() + end);
    }
}

std::uint32_t findRoot(std::vector<std::uint32_t> &parent, std::uint32_t x)
{
    while (parent[x] != x) {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    return x;
}

// Corners of one vertex belong together when their faces share an edge at
// that vertex (any edge of 2+ faces, non-manifold ones included). Returns a
// union-find forest over the corners. Reads the mesh, changes nothing: it
// runs beside windingFlips().
std::vector<std::uint32_t> bowtieGroups(const PolygonMesh &mesh, const Adjacency &adj)
{
    std::vector<std::uint32_t> parent(mesh.cornerPosition.size());
    std::iota(parent.begin(), parent.end(), 0u);
    auto unite = [&](std::uint32_t a, std::uint32_t b) {
        parent[findRoot(parent, a)] = findRoot(parent, b);
    };
    auto endsOf = [&](const Side &s) {
        const std::uint32_t next = nextCorner(mesh, adj.cornerFace, s.corner);
        return s.forward ? std::pair(s.corner, next)
                         : std::pair(next, s.corner); // (smaller, larger) vertex
    };
    forEachEdge(adj, [&](std::size_t i, std::size_t n) {
        const auto first = endsOf(adj.sides[i]);
        for (std::size_t k = i + 1; k < i + n; ++k) {
            const auto other = endsOf(adj.sides[k]);
            unite(first.first, other.first);
            unite(first.second, other.second);
        }
    });
    return parent;
}

// More than one group of corners at a vertex: surfaces touching at a point
// only. Every group after the first gets its own copy of the vertex.
void splitBowtieVertices(PolygonMesh &mesh, std::vector<std::uint32_t> &parent,
                         RepairReport &report)
{
    std::vector<std::uint32_t> groupVertex(parent.size(), kUnset);
    std::vector<std::uint32_t> vertexGroup(mesh.positions.size(), kUnset);
    for (std::uint32_t c = 0; c < parent.size(); ++c) {
        const std::uint32_t root = findRoot(parent, c);
        if (groupVertex[root] == kUnset) {
            const std::uint32_t v = mesh.cornerPosition[c];
            if (vertexGroup[v] == kUnset) {
                vertexGroup[v] = root;
                groupVertex[root] = v;
            } else {
                const glm::vec3 p = mesh.positions[v];
                groupVertex[root] = std::uint32_t(mesh.positions.size());
                mesh.positions.push_back(p);
                ++report.verticesDuplicated;
            }
        }
        mesh.cornerPosition[c] = groupVertex[root];
    }
}

void removeUnusedVertices(PolygonMesh &mesh, RepairReport &report)
{
    std::vector<std::uint32_t> remap(mesh.positions.size(), kUnset);
    for (std::uint32_t v : mesh.cornerPosition)
        remap[v] = 0;
    std::uint32_t next = 0;
    for (std::size_t v = 0; v < remap.size(); ++v) {
        if (remap[v] == kUnset)
            continue;
        remap[v] = next;
        mesh.positions[next++] = mesh.positions[v];
    }
    report.isolatedVerticesRemoved = int(mesh.positions.size() - next);
    mesh.positions.resize(next);
    for (std::uint32_t &v : mesh.cornerPosition)
        v = remap[v];
}

} // namespace

QStringList RepairReport::warnings() const
{
    QStringList w;
    if (facesDroppedBadIndex)
        w << MeshRepairWords::tr("dropped %1 with out-of-range vertex indices")
                 .arg(meshtext::counted(facesDroppedBadIndex,
                                        QT_TRANSLATE_NOOP("phonglab::MeshText", "face"),
                                        QT_TRANSLATE_NOOP("phonglab::MeshText", "faces")));
    if (facesDroppedNonFinite)
        w << MeshRepairWords::tr("dropped %1 using NaN or infinite coordinates")
                 .arg(meshtext::counted(facesDroppedNonFinite,
                                        QT_TRANSLATE_NOOP("phonglab::MeshText", "face"),
                                        QT_TRANSLATE_NOOP("phonglab::MeshText", "faces")));
    if (facesDroppedDegenerate)
        w << MeshRepairWords::tr("dropped %1 (fewer than 3 distinct corners or zero area)")
                 .arg(meshtext::counted(
                     facesDroppedDegenerate,
                     QT_TRANSLATE_NOOP("phonglab::MeshText", "degenerate face"),
                     QT_TRANSLATE_NOOP("phonglab::MeshText", "degenerate faces")));
    if (normalsDiscarded)
        w << MeshRepairWords::tr(
                 "ignored the file normal of %1 (missing, zero or not finite); computed instead")
                 .arg(meshtext::counted(normalsDiscarded,
                                        QT_TRANSLATE_NOOP("phonglab::MeshText", "face corner"),
                                        QT_TRANSLATE_NOOP("phonglab::MeshText", "face corners")));
    if (nonManifoldEdges)
        w << MeshRepairWords::tr("%1 (shared by 3 or more faces), kept as they are")
                 .arg(meshtext::counted(
                     nonManifoldEdges, QT_TRANSLATE_NOOP("phonglab::MeshText", "non-manifold edge"),
                     QT_TRANSLATE_NOOP("phonglab::MeshText", "non-manifold edges")));
    if (orientationConflicts)
        w << MeshRepairWords::tr("%1 no consistent winding agrees on (a non-orientable surface)")
                 .arg(meshtext::counted(orientationConflicts,
                                        QT_TRANSLATE_NOOP("phonglab::MeshText", "edge"),
                                        QT_TRANSLATE_NOOP("phonglab::MeshText", "edges")));
    if (facesFlipped)
        w << MeshRepairWords::tr("flipped %1 to make the winding consistent")
                 .arg(meshtext::counted(facesFlipped,
                                        QT_TRANSLATE_NOOP("phonglab::MeshText", "face"),
                                        QT_TRANSLATE_NOOP("phonglab::MeshText", "faces")));
    if (verticesDuplicated)
        w << MeshRepairWords::tr("split %1 where surfaces touch only at that point")
                 .arg(meshtext::counted(verticesDuplicated,
                                        QT_TRANSLATE_NOOP("phonglab::MeshText", "vertex"),
                                        QT_TRANSLATE_NOOP("phonglab::MeshText", "vertices")));
    if (isolatedVerticesRemoved)
        w << MeshRepairWords::tr("removed %1 no face uses")
                 .arg(meshtext::counted(isolatedVerticesRemoved,
                                        QT_TRANSLATE_NOOP("phonglab::MeshText", "vertex"),
                                        QT_TRANSLATE_NOOP("phonglab::MeshText", "vertices")));
    return w;
}

RepairReport repairMesh(PolygonMesh &mesh)
{
    RepairReport report;
    report.normalsDiscarded = discardBadNormals(mesh);
    dropUnusableFaces(mesh, report);
    {
        const Adjacency adj = buildAdjacency(mesh);
        forEachEdge(adj,
                    [&](std::size_t, std::size_t n) { report.nonManifoldEdges += n >= 3 ? 1 : 0; });

        // Grouping corners and choosing flips only read the mesh and the
        // adjacency: the grouping runs on a second thread. Splitting does
        // not change the signed volume the flips are chosen by (a copy has
        // its original's position), so the answers are those of one thread.
        std::future<std::vector<std::uint32_t>> groups =
            std::async(std::launch::async, [&mesh, &adj] { return bowtieGroups(mesh, adj); });
        const std::vector<char> flip = windingFlips(mesh, adj, report);
        std::vector<std::uint32_t> parent = groups.get();
        // Split first: flipping reorders corners, which the adjacency names.
        splitBowtieVertices(mesh, parent, report);
        flipFaces(mesh, flip, report);
    }
    removeUnusedVertices(mesh, report);
    return report;
}

} // namespace phonglab
