// Into OpenMesh and back: MeshData's vertices welded by exact position,
// and the decimated faces made MeshData again with the input's own normals
// (a corner keeps its normal, a moved one takes the closest original).
// Apart from MeshDecimation.cpp, which runs the decimation between the two.
#include "DecimationWeld.h"

#include "core/support/Vec3Key.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <unordered_map>

namespace phonglab::decimation {

Weld weldByPosition(const MeshData &mesh)
{
    Weld w;
    w.weldedOf.assign(mesh.positions.size(), kNone);
    std::unordered_map<Vec3Key, std::uint32_t, Vec3KeyHash> idOf;
    idOf.reserve(mesh.positions.size());
    // Welded ids in order of first use, so the result never depends on hashing.
    for (std::uint32_t v : mesh.indices) {
        if (w.weldedOf[v] != kNone)
            continue;
        const auto [it, added] =
            idOf.try_emplace(vec3Key(mesh.positions[v]), std::uint32_t(w.firstGpu.size()));
        if (added)
            w.firstGpu.push_back(v);
        w.weldedOf[v] = it->second;
    }
    const std::size_t count = w.firstGpu.size();
    w.candStart.assign(count + 1, 0);
    for (std::uint32_t id : w.weldedOf)
        if (id != kNone)
            ++w.candStart[id + 1];
    for (std::size_t i = 0; i < count; ++i)
        w.candStart[i + 1] += w.candStart[i];
    w.candidates.resize(w.candStart[count]);
    std::vector<std::uint32_t> fill(w.candStart.begin(), w.candStart.end() - 1);
    for (std::uint32_t v = 0; v < w.weldedOf.size(); ++v)
        if (w.weldedOf[v] != kNone)
            w.candidates[fill[w.weldedOf[v]]++] = v;
    // One candidate per distinct normal (by bits), the lowest GPU vertex first.
    std::vector<std::uint32_t> kept;
    kept.reserve(w.candidates.size());
    std::vector<std::uint32_t> start(count + 1, 0);
    for (std::size_t i = 0; i < count; ++i) {
        start[i] = std::uint32_t(kept.size());
        const auto begin = w.candidates.begin() + w.candStart[i],
                   end = w.candidates.begin() + w.candStart[i + 1];
        const auto normalKey = [&](std::uint32_t v) {
            const Vec3Key k = vec3Key(mesh.normals[v]);
            return std::tuple(k.x, k.y, k.z, v);
        };
        std::sort(begin, end,
                  [&](std::uint32_t a, std::uint32_t b) { return normalKey(a) < normalKey(b); });
        for (auto it = begin; it != end; ++it)
            if (it == begin || !(vec3Key(mesh.normals[*it]) == vec3Key(mesh.normals[*(it - 1)])))
                kept.push_back(*it);
    }
    start[count] = std::uint32_t(kept.size());
    w.candidates = std::move(kept);
    w.candStart = std::move(start);
    return w;
}

bool isFaceted(const MeshData &mesh)
{
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const Vec3Key n = vec3Key(mesh.normals[mesh.indices[t]]);
        if (!(vec3Key(mesh.normals[mesh.indices[t + 1]]) == n)
            || !(vec3Key(mesh.normals[mesh.indices[t + 2]]) == n))
            return false;
    }
    return true;
}

namespace {

// A new face of a faceted mesh reuses an original normal only when it is
// this close to its own (Blender writes normals to ~1e-6, far below this).
constexpr double kFacetKeepDeg = 0.05;

// Output vertices, one per (welded position, normal bits).
class VertexTable
{
public:
    explicit VertexTable(const MeshData &input, const Weld &weld)
        : m_input(input)
        , m_weld(weld)
    {
    }

    std::uint32_t add(std::uint32_t welded, const glm::vec3 &normal)
    {
        const Vec3Key n = vec3Key(normal);
        const auto [it, added] =
            m_index.try_emplace(Key{welded, n.x, n.y, n.z}, std::uint32_t(out.positions.size()));
        if (added) {
            out.positions.push_back(m_input.positions[m_weld.firstGpu[welded]]);
            out.normals.push_back(normal);
        }
        return it->second;
    }

    MeshData out;

private:
    struct Key {
        std::uint32_t welded, x, y, z;
        bool operator==(const Key &) const = default;
    };
    struct KeyHash {
        std::size_t operator()(const Key &k) const
        {
            return Vec3KeyHash()(Vec3Key{k.x ^ (k.welded * 0x85EBCA6Bu), k.y, k.z + k.welded});
        }
    };
    const MeshData &m_input;
    const Weld &m_weld;
    std::unordered_map<Key, std::uint32_t, KeyHash> m_index;
};

// Among the candidate normals at `welded`, the one closest to `direction`.
glm::vec3 closestNormal(const MeshData &mesh, const Weld &w, std::uint32_t welded,
                        const glm::dvec3 &direction)
{
    std::uint32_t best = w.candidates[w.candStart[welded]];
    double bestDot = -std::numeric_limits<double>::infinity();
    for (std::uint32_t i = w.candStart[welded]; i < w.candStart[welded + 1]; ++i) {
        const double d = glm::dot(glm::dvec3(mesh.normals[w.candidates[i]]), direction);
        if (d > bestDot) {
            bestDot = d;
            best = w.candidates[i];
        }
    }
    return mesh.normals[best];
}

// One normal for the whole face of a faceted mesh: an original one if the
// face still lies in an original facet's plane, else its own. `length` is
// that of the face's unnormalised cross product (0: no area, no own normal).
glm::vec3 facetNormal(const MeshData &input, const Weld &w, const std::uint32_t (&v)[3],
                      const glm::dvec3 &faceNormal, double length, double keepCos)
{
    glm::vec3 best(0.0f);
    double bestDot = -2.0;
    for (int c = 0; c < 3; ++c) {
        const glm::vec3 n = closestNormal(input, w, v[c], faceNormal);
        const double d = glm::dot(glm::dvec3(n), faceNormal);
        if (d > bestDot) {
            bestDot = d;
            best = n;
        }
    }
    const glm::vec3 own(faceNormal);
    return (bestDot >= keepCos || length == 0.0) ? best : own;
}

} // namespace

MeshData rebuild(const MeshData &input, const Weld &w, const OmMesh &om,
                 const std::vector<std::uint32_t> &faceTriangle, bool faceted)
{
    VertexTable table(input, w);
    table.out.indices.reserve(om.n_faces() * 3);
    const double keepCos = std::cos(glm::radians(kFacetKeepDeg));
    for (OpenMesh::FaceHandle f : om.all_faces()) {
        if (om.status(f).deleted())
            continue;
        // The halfedge cycle follows the order the face was added in, so the
        // winding is the input's.
        std::uint32_t v[3];
        OpenMesh::HalfedgeHandle h = om.halfedge_handle(f);
        for (int c = 0; c < 3; ++c, h = om.next_halfedge_handle(h))
            v[c] = std::uint32_t(om.to_vertex_handle(h).idx());
        const glm::dvec3 p0(input.positions[w.firstGpu[v[0]]]),
            p1(input.positions[w.firstGpu[v[1]]]), p2(input.positions[w.firstGpu[v[2]]]);
        const glm::dvec3 cross = glm::cross(p1 - p0, p2 - p0);
        const double length = glm::length(cross);
        const glm::dvec3 faceNormal = length > 0.0 ? cross / length : glm::dvec3(0.0);

        // The input triangle this face started as, corner by welded position.
        const std::uint32_t t = faceTriangle[std::size_t(f.idx())];
        const std::uint32_t *original = &input.indices[3 * std::size_t(t)];
        const auto originalCorner = [&](std::uint32_t welded) -> std::uint32_t {
            for (int c = 0; c < 3; ++c)
                if (w.weldedOf[original[c]] == welded)
                    return original[c];
            return kNone;
        };

        glm::vec3 normal[3];
        const bool untouched = originalCorner(v[0]) != kNone && originalCorner(v[1]) != kNone
            && originalCorner(v[2]) != kNone;
        if (untouched) {
            for (int c = 0; c < 3; ++c)
                normal[c] = input.normals[originalCorner(v[c])];
        } else if (faceted) {
            const glm::vec3 chosen = facetNormal(input, w, v, faceNormal, length, keepCos);
            normal[0] = normal[1] = normal[2] = chosen;
        } else {
            for (int c = 0; c < 3; ++c) {
                const std::uint32_t kept = originalCorner(v[c]);
                normal[c] =
                    kept != kNone ? input.normals[kept] : closestNormal(input, w, v[c], faceNormal);
            }
        }
        for (int c = 0; c < 3; ++c)
            table.out.indices.push_back(table.add(v[c], normal[c]));
    }
    return std::move(table.out);
}

} // namespace phonglab::decimation
