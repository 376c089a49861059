#include "MeshRepair.h"

#include "MeshRepairEdges.h"
#include "MeshTextTokens.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>
#include <future>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct MeshRepairWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::MeshRepair)
};

namespace {

using repair::Adjacency;
using repair::bowtieGroups;
using repair::buildAdjacency;
using repair::flipFaces;
using repair::forEachEdge;
using repair::kUnset;
using repair::splitBowtieVertices;
using repair::windingFlips;

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
