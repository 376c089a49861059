#include "MeshBuilder.h"

#include "NormalComputation.h"
#include "core/support/Vec3Key.h"
#include "mesh/import/Triangulation.h"

#include <QCoreApplication>
#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numeric>
#include <tuple>
#include <unordered_map>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct MeshBuilderWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::MeshBuilder)
};

namespace {

bool sameNormal(const glm::vec3 &a, const glm::vec3 &b)
{
    return vec3Key(a) == vec3Key(b);
}

// The file's normal at unit length. One already at unit length, to about
// the precision files write (six decimals), is kept bit for bit: dividing
// by a length of 1 ± ε would still nudge the last bits. Zero when it has
// no direction.
glm::vec3 unitFileNormal(const glm::vec3 &n)
{
    const glm::dvec3 d(n);
    const double length = glm::length(d);
    if (!(length > 0.0) || !std::isfinite(length))
        return glm::vec3(0.0f);
    return std::abs(length - 1.0) <= 1e-5 ? n : glm::vec3(d / length);
}

// The triangles as the rest of the build reads them: per triangle corner,
// the position index and, when the file has normals, the normal index.
// All-triangle meshes (most files) need no copy: the polygon mesh's own
// corner arrays already are these lists.
struct Triangles {
    std::span<const std::uint32_t> positions, normals;
    std::size_t fanFallbacks = 0;
    std::vector<std::uint32_t> positionStorage, normalStorage;
};

void gatherTriangles(const PolygonMesh &mesh, Triangles &out)
{
    bool allTriangles = true;
    for (std::size_t f = 0; f < mesh.faceStart.size() && allTriangles; ++f)
        allTriangles = mesh.faceStart[f] == 3 * f;
    if (allTriangles) {
        out.positions = mesh.cornerPosition;
        out.normals = mesh.cornerNormal;
        return;
    }
    const Triangulation triangulation = triangulate(mesh);
    out.fanFallbacks = triangulation.fanFallbacks;
    out.positionStorage.resize(triangulation.corners.size());
    for (std::size_t c = 0; c < triangulation.corners.size(); ++c)
        out.positionStorage[c] = mesh.cornerPosition[triangulation.corners[c]];
    out.positions = out.positionStorage;
    if (mesh.hasNormals()) {
        out.normalStorage.resize(triangulation.corners.size());
        for (std::size_t c = 0; c < triangulation.corners.size(); ++c)
            out.normalStorage[c] = mesh.cornerNormal[triangulation.corners[c]];
        out.normals = out.normalStorage;
    }
}

// Normals from the file, at unit length. Corners whose file normal has no
// direction get the computed angle-weighted normal instead.
CornerNormals fileNormals(const PolygonMesh &mesh, const Triangles &triangles,
                          const NormalOptions &options, QStringList &warnings)
{
    CornerNormals result;
    result.normals.resize(mesh.normals.size());
    std::vector<char> unusable(mesh.normals.size());
    for (std::size_t i = 0; i < mesh.normals.size(); ++i) {
        result.normals[i] = unitFileNormal(mesh.normals[i]);
        unusable[i] = result.normals[i] == glm::vec3(0.0f);
    }
    std::size_t badCorners = 0;
    for (std::uint32_t n : mesh.cornerNormal)
        badCorners += unusable[n];

    // Per-vertex normals (normal index = position index, as PLY has them)
    // need no index array of their own.
    const bool perPosition = mesh.normals.size() == mesh.positions.size()
        && std::equal(triangles.normals.begin(), triangles.normals.end(),
                      triangles.positions.begin());
    if (perPosition && badCorners == 0) {
        result.indexing = CornerNormals::Indexing::PerPosition;
        return result;
    }
    result.indexing = CornerNormals::Indexing::PerCorner;
    result.cornerNormal.assign(triangles.normals.begin(), triangles.normals.end());
    if (badCorners == 0)
        return result;

    const CornerNormals computed = computeNormals(
        mesh.positions, triangles.positions, NormalMethod::AngleWeighted, options.creaseAngleDeg);
    for (std::size_t c = 0; c < result.cornerNormal.size(); ++c) {
        if (unusable[result.cornerNormal[c]]) {
            result.cornerNormal[c] = std::uint32_t(result.normals.size());
            result.normals.push_back(computed.at(c, triangles.positions));
        }
    }
    warnings << MeshBuilderWords::tr("%1 of %2 corners have a zero or invalid normal in the file; "
                                     "computed angle-weighted normals replace them")
                    .arg(qint64(badCorners))
                    .arg(qint64(mesh.cornerNormal.size()));
    return result;
}

// Smooth normals without creases: one vertex per position used, in
// position order.
std::size_t weldPerPosition(std::span<const glm::vec3> positions,
                            std::span<const std::uint32_t> triPositions,
                            const CornerNormals &normals, MeshData &out)
{
    std::vector<std::uint32_t> vertexOf(positions.size(), 0);
    for (std::uint32_t p : triPositions)
        vertexOf[p] = 1;
    out.positions.reserve(positions.size());
    out.normals.reserve(positions.size());
    for (std::size_t p = 0; p < positions.size(); ++p) {
        if (vertexOf[p] != 0) {
            vertexOf[p] = std::uint32_t(out.positions.size());
            out.positions.push_back(positions[p]);
            out.normals.push_back(normals.normals[p]);
        }
    }
    out.indices.resize(triPositions.size());
    for (std::size_t c = 0; c < triPositions.size(); ++c)
        out.indices[c] = vertexOf[triPositions[c]];
    return out.positions.size();
}

constexpr std::uint32_t kNoVertex = std::numeric_limits<std::uint32_t>::max();

struct WeldKey {
    std::uint32_t position;
    Vec3Key normal;
    bool operator==(const WeldKey &) const = default;
};
struct WeldKeyHash {
    std::size_t operator()(const WeldKey &k) const
    {
        const std::uint64_t h =
            k.position * 0x9E3779B97F4A7C15ull ^ Vec3KeyHash()(k.normal) * 0xC2B2AE3D27D4EB4Full;
        return std::size_t(h ^ h >> 29);
    }
};

// The vertices weld() has made so far, found by position: a chain per
// position, newest first, or a hash map for the few crowded positions.
struct VertexChains {
    std::vector<std::uint32_t> head; // newest vertex of each position
    std::vector<std::uint32_t> next; // the vertex made before it, per vertex
    std::vector<char> crowded;
    std::unordered_map<WeldKey, std::uint32_t, WeldKeyHash> crowdedVertex;
};

// The vertex already made at position p with normal n, or kNoVertex. A
// position whose chain grows past the limit moves to the hash map.
std::uint32_t findVertex(VertexChains &chains, const std::vector<glm::vec3> &vertexNormals,
                         std::uint32_t p, const glm::vec3 &n)
{
    constexpr int kChainLimit = 32;
    std::uint32_t v = kNoVertex;
    if (chains.crowded[p]) {
        const auto found = chains.crowdedVertex.find({p, vec3Key(n)});
        v = found != chains.crowdedVertex.end() ? found->second : kNoVertex;
    } else {
        int steps = 0;
        for (v = chains.head[p]; v != kNoVertex && !sameNormal(vertexNormals[v], n);
             v = chains.next[v])
            ++steps;
        if (v == kNoVertex && steps >= kChainLimit) {
            chains.crowded[p] = 1;
            for (std::uint32_t w = chains.head[p]; w != kNoVertex; w = chains.next[w])
                chains.crowdedVertex.emplace(WeldKey{p, vec3Key(vertexNormals[w])}, w);
        }
    }
    return v;
}

// One GPU vertex per distinct (position index, normal's Vec3Key), in order of
// first use (which suits the GPU's vertex cache). Each position keeps a
// chain of the vertices made for it, newest first; a corner walks its
// position's chain comparing normals. Chains are short (one for smooth
// positions, a handful at hard edges); a position with many distinct
// normals (the apex of a flat-shaded cone) moves to a hash map instead.
// Returns how many positions the triangles use.
std::size_t weld(std::span<const glm::vec3> positions, std::span<const std::uint32_t> triPositions,
                 const CornerNormals &normals, MeshData &out)
{
    if (normals.indexing == CornerNormals::Indexing::PerPosition)
        return weldPerPosition(positions, triPositions, normals, out);

    VertexChains chains;
    chains.head.assign(positions.size(), kNoVertex);
    chains.crowded.assign(positions.size(), 0);
    // Room for every vertex up front: growing 100 MB of vertices by doubling
    // costs more in copies and fresh pages than the welding itself. Flat
    // shading gives about one vertex per corner; otherwise each normal
    // usually serves one position (crease groups, file normals per vertex).
    const std::size_t expected = normals.indexing == CornerNormals::Indexing::PerTriangle
        ? triPositions.size()
        : std::min(triPositions.size(), std::max(positions.size(), normals.normals.size()));
    chains.next.reserve(expected);
    out.positions.reserve(expected);
    out.normals.reserve(expected);
    out.indices.resize(triPositions.size());
    std::size_t positionsUsed = 0;

    for (std::size_t c = 0; c < triPositions.size(); ++c) {
        const std::uint32_t p = triPositions[c];
        const glm::vec3 &n = normals.at(c, triPositions);
        std::uint32_t v = findVertex(chains, out.normals, p, n);
        if (v == kNoVertex) {
            v = std::uint32_t(out.positions.size());
            positionsUsed += chains.head[p] == kNoVertex;
            out.positions.push_back(positions[p]);
            out.normals.push_back(n);
            chains.next.push_back(chains.head[p]);
            chains.head[p] = v;
            if (chains.crowded[p])
                chains.crowdedVertex.emplace(WeldKey{p, vec3Key(n)}, v);
        }
        out.indices[c] = v;
    }
    return positionsUsed;
}

// Corners without a usable file normal: all of them when the file has none.
std::size_t missingFileNormals(const PolygonMesh &mesh)
{
    std::size_t missingNormals = mesh.cornerPosition.size();
    if (mesh.hasNormals()) {
        missingNormals = 0;
        for (std::uint32_t n : mesh.cornerNormal)
            missingNormals += n == PolygonMesh::kNoNormal || n >= mesh.normals.size();
    }
    return missingNormals;
}

void setBounds(MeshStats &stats, const MeshData &data)
{
    if (!data.positions.empty()) {
        stats.boundsMin = stats.boundsMax = data.positions.front();
        for (const glm::vec3 &p : data.positions) {
            stats.boundsMin = glm::min(stats.boundsMin, p);
            stats.boundsMax = glm::max(stats.boundsMax, p);
        }
    }
}

} // namespace

BuiltMesh buildMeshData(const PolygonMesh &mesh, const NormalOptions &options)
{
    BuiltMesh built;
    const auto fail = [&built](const QString &message) {
        built.error = message;
        return built;
    };
    QStringList &warnings = built.warnings;

    // Corner and vertex numbers are 32-bit throughout, as the GPU's indices
    // are. Polygon corners fit (faceStart is 32-bit); triangulating an
    // n-gon makes 3(n − 2) corners of n, so check before making them.
    std::size_t triangleCorners = 0;
    for (std::size_t f = 0; f < mesh.faceCount(); ++f)
        triangleCorners += mesh.cornerCount(f) >= 3 ? 3 * (mesh.cornerCount(f) - 2) : 0;
    if (triangleCorners == 0)
        return fail(MeshBuilderWords::tr("the mesh has no faces"));
    if (triangleCorners > std::numeric_limits<std::uint32_t>::max())
        return fail(
            MeshBuilderWords::tr(
                "the mesh is too large: %1 triangles exceed what 32-bit indices can address")
                .arg(qint64(triangleCorners / 3)));

    Triangles triangles;
    gatherTriangles(mesh, triangles);
    if (triangles.fanFallbacks != 0)
        warnings << MeshBuilderWords::tr(
                        "%1 polygons cross or fold onto themselves; they were split as fans")
                        .arg(qint64(triangles.fanFallbacks));

    const std::size_t missingNormals = missingFileNormals(mesh);
    const bool fromFile = options.method == NormalMethod::Auto && missingNormals == 0;
    const NormalMethod method = fromFile       ? NormalMethod::Auto
        : options.method == NormalMethod::Auto ? NormalMethod::AngleWeighted
                                               : options.method;
    if (options.method == NormalMethod::Auto && mesh.hasNormals() && missingNormals != 0)
        warnings << MeshBuilderWords::tr("%1 of %2 corners have no normal in the file; "
                                         "computed angle-weighted normals for the whole mesh")
                        .arg(qint64(missingNormals))
                        .arg(qint64(mesh.cornerPosition.size()));

    const CornerNormals normals = fromFile
        ? fileNormals(mesh, triangles, options, warnings)
        : computeNormals(mesh.positions, triangles.positions, method, options.creaseAngleDeg);

    MeshData &data = built.mesh;
    const std::size_t positionsUsed = weld(mesh.positions, triangles.positions, normals, data);

    MeshStats &stats = built.stats;
    stats.fileVertices = qint64(mesh.positions.size());
    stats.vertices = qint64(data.positions.size());
    stats.triangles = qint64(data.triangleCount());
    stats.normalsFromFile = fromFile;
    stats.normalMethod = method;
    setBounds(stats, data);
    stats.splitVertices = stats.vertices - qint64(positionsUsed);
    return built;
}

} // namespace phonglab
