// The repair steps that work along a mesh's edges: the adjacency of face
// sides by edge, the winding made to agree across manifold edges (and a
// closed component turned outwards), and "bowtie" vertices split where
// surfaces touch at one point. Apart from MeshRepair.cpp, whose steps look
// at one face or vertex at a time.
#include "MeshRepairEdges.h"

#include <algorithm>
#include <numeric>

namespace phonglab::repair {

namespace {

std::uint32_t nextCorner(const PolygonMesh &mesh, const std::vector<std::uint32_t> &cornerFace,
                         std::uint32_t c)
{
    const std::uint32_t f = cornerFace[c];
    return c + 1 < mesh.faceStart[f + 1] ? c + 1 : mesh.faceStart[f];
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

std::uint32_t findRoot(std::vector<std::uint32_t> &parent, std::uint32_t x)
{
    while (parent[x] != x) {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    return x;
}

// Neighbours across manifold edges, per face (CSR: links[start[f]..start[f+1])),
// and whether the two faces run the edge the same way (then one of them must turn).
struct FaceLinks {
    std::vector<std::uint32_t> start;
    std::vector<std::pair<std::uint32_t, bool>> links;
};

FaceLinks buildFaceLinks(const Adjacency &adj, std::size_t faces)
{
    FaceLinks out;
    std::vector<std::uint32_t> &start = out.start;
    start.assign(faces + 1, 0);
    forEachEdge(adj, [&](std::size_t i, std::size_t n) {
        if (n == 2 && adj.sides[i].face != adj.sides[i + 1].face) {
            ++start[adj.sides[i].face + 1];
            ++start[adj.sides[i + 1].face + 1];
        }
    });
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<std::pair<std::uint32_t, bool>> &links = out.links;
    links.resize(start.back());
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
    return out;
}

// A face on the boundary has a side (two distinct ends) with no link.
// Counted face by face, not side by side: one pass in memory order.
std::vector<char> allSidesPaired(const PolygonMesh &mesh, const std::vector<std::uint32_t> &start)
{
    const std::size_t faces = mesh.faceCount();
    std::vector<char> paired(faces);
    for (std::size_t f = 0; f < faces; ++f) {
        std::uint32_t sides = 0;
        const std::uint32_t begin = mesh.faceStart[f], end = mesh.faceStart[f + 1];
        for (std::uint32_t c = begin; c < end; ++c)
            sides += mesh.cornerPosition[c] != mesh.cornerPosition[c + 1 < end ? c + 1 : begin];
        paired[f] = sides == start[f + 1] - start[f];
    }
    return paired;
}

// The per-face state windingFlips carries from one component to the next;
// `component` is only scratch space reused to save allocations.
struct OrientState {
    std::vector<char> &flip;
    std::vector<char> &seen;
    std::vector<std::uint32_t> &component;
};

// Flood-fills the component of `seed`, choosing each face's flip so the
// winding agrees with its neighbours; then turns the whole component if
// that makes it face outwards (closed and consistent) or flips fewer faces.
void orientComponent(const PolygonMesh &mesh, const FaceLinks &links,
                     const std::vector<char> &closedFaces, std::uint32_t seed,
                     const OrientState &state, RepairReport &report)
{
    std::vector<char> &flip = state.flip;
    std::vector<char> &seen = state.seen;
    std::vector<std::uint32_t> &component = state.component;
    component.clear();
    component.push_back(seed);
    seen[seed] = 1;
    bool closed = true;
    int conflicts = 0;
    for (std::size_t q = 0; q < component.size(); ++q) {
        const std::uint32_t f = component[q];
        closed = closed && closedFaces[f];
        for (std::uint32_t l = links.start[f]; l < links.start[f + 1]; ++l) {
            const auto [g, same] = links.links[l];
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

} // namespace

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

std::vector<char> windingFlips(const PolygonMesh &mesh, const Adjacency &adj, RepairReport &report)
{
    const std::size_t faces = mesh.faceCount();
    const FaceLinks links = buildFaceLinks(adj, faces);
    const std::vector<char> closedFaces = allSidesPaired(mesh, links.start);

    std::vector<char> flip(faces, 0);
    std::vector<char> seen(faces, 0);
    std::vector<std::uint32_t> component;
    for (std::uint32_t seed = 0; seed < faces; ++seed) {
        if (seen[seed])
            continue;
        orientComponent(mesh, links, closedFaces, seed, {flip, seen, component}, report);
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

} // namespace phonglab::repair
