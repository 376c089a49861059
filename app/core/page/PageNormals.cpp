#include "PageNormals.h"

#include "CapturedVertices.h"
#include "DrawBindings.h"

#include <QCoreApplication>

#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <map>
#include <unordered_map>

namespace phonglab {

struct PageNormalsWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::PageNormals)
};

namespace {

constexpr double kSameDirection = 1e-3; // |a - b| of unit vectors
constexpr double kMatchedShare = 0.9;   // of a draw's vertices found in the mesh
constexpr double kExactShare = 0.99;

enum class VertexNormal {
    Exact,
    Face,
    NotNormalised,
    Positions,
    Other,
    Count
};

// A position as a key that JavaScript's double-then-float parse of the
// file and the mesh reader's float parse both land on.
using PositionKey = std::array<std::int64_t, 3>;
PositionKey positionKey(const glm::dvec3 &p)
{
    return {std::llround(p.x * 65536.0), std::llround(p.y * 65536.0), std::llround(p.z * 65536.0)};
}

struct PositionKeyHash {
    std::size_t operator()(const PositionKey &k) const
    {
        return std::size_t(k[0] * 73856093LL ^ k[1] * 19349663LL ^ k[2] * 83492791LL);
    }
};

using MeshNormals = std::unordered_map<PositionKey, std::vector<glm::dvec3>, PositionKeyHash>;

MeshNormals normalsByPosition(const MeshData &mesh)
{
    MeshNormals out;
    for (std::size_t i = 0; i < mesh.positions.size() && i < mesh.normals.size(); ++i)
        out[positionKey(glm::dvec3(mesh.positions[i]))].push_back(
            glm::normalize(glm::dvec3(mesh.normals[i])));
    return out;
}

bool near(const glm::dvec3 &a, const glm::dvec3 &b, double tolerance)
{
    return glm::length(a - b) < tolerance;
}

VertexNormal classify(const glm::dvec3 &sent, const glm::dvec3 &position,
                      const std::vector<glm::dvec3> &blender, const std::optional<glm::dvec3> &face)
{
    const double length = glm::length(sent);
    for (const glm::dvec3 &b : blender)
        if (near(sent, b, kSameDirection))
            return VertexNormal::Exact;
    if (near(sent, position, 1e-5))
        return VertexNormal::Positions;
    if (length > 1e-12)
        for (const glm::dvec3 &b : blender)
            if (near(sent / length, b, kSameDirection))
                return VertexNormal::NotNormalised;
    if (face && length > 1e-12 && near(sent / length, *face, kSameDirection))
        return VertexNormal::Face;
    return VertexNormal::Other;
}

struct DrawnMesh {
    std::array<qint64, std::size_t(VertexNormal::Count)> counts{};
    qint64 vertices = 0;
    bool hasNormals = false;
    QString where;
};

// The faces' normals of a triangle list, per vertex.
std::vector<std::optional<glm::dvec3>> faceNormals(const std::vector<glm::dvec4> &positions,
                                                   unsigned mode)
{
    std::vector<std::optional<glm::dvec3>> out(positions.size());
    if (mode != 4) // TRIANGLES
        return out;
    for (std::size_t i = 0; i + 2 < positions.size(); i += 3) {
        const glm::dvec3 a(positions[i]), b(positions[i + 1]), c(positions[i + 2]);
        const glm::dvec3 n = glm::cross(b - a, c - a);
        if (glm::length(n) > 1e-20)
            out[i] = out[i + 1] = out[i + 2] = glm::normalize(n);
    }
    return out;
}

std::optional<DrawnMesh> drawnAs(const PageCapture &capture, const CapturedOp &draw,
                                 const MeshNormals &mesh)
{
    const ProgramBindings bindings = drawBindings(draw);
    const CapturedAttribute *position = attributeMeaning(draw, bindings, BindingMeaning::Position);
    const std::optional<std::vector<qint64>> vertices = drawnVertices(capture, draw);
    if (!position || !vertices || vertices->empty())
        return std::nullopt;
    const std::vector<glm::dvec4> positions = attributeValues(capture, *position, *vertices);
    qint64 found = 0;
    for (const glm::dvec4 &p : positions)
        found += mesh.count(positionKey(glm::dvec3(p)));
    if (found < kMatchedShare * double(positions.size()))
        return std::nullopt;
    DrawnMesh drawn;
    drawn.vertices = qint64(positions.size());
    const CapturedAttribute *normal = attributeMeaning(draw, bindings, BindingMeaning::Normal);
    drawn.hasNormals = normal && normal->enabled;
    if (!drawn.hasNormals)
        return drawn;
    if (const CapturedBuffer *buffer = capture.buffer(normal->buffer))
        drawn.where = callSiteText(buffer->setAt);
    const std::vector<glm::dvec4> normals = attributeValues(capture, *normal, *vertices);
    const std::vector<std::optional<glm::dvec3>> faces = faceNormals(positions, draw.mode);
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const auto it = mesh.find(positionKey(glm::dvec3(positions[i])));
        if (it == mesh.end())
            continue;
        ++drawn.counts[std::size_t(
            classify(glm::dvec3(normals[i]), glm::dvec3(positions[i]), it->second, faces[i]))];
    }
    return drawn;
}

JavaScriptFinding findingFor(const QString &name, const DrawnMesh &drawn)
{
    const auto share = [&](VertexNormal kind) {
        return double(drawn.counts[std::size_t(kind)])
            / double(std::max<qint64>(1, drawn.vertices));
    };
    JavaScriptFinding f{{}, name, true, {}, drawn.where};
    if (!drawn.hasNormals) {
        f.key = QStringLiteral("normals-missing");
        f.message = PageNormalsWords::tr("%1 is drawn without normals: the shader's normal "
                                         "input gets no buffer")
                        .arg(name);
        return f;
    }
    if (share(VertexNormal::Exact) >= kExactShare) {
        f.key = QStringLiteral("normals-exact");
        f.mistake = false;
        f.message = PageNormalsWords::tr("%1: Blender's normals, exactly").arg(name);
        return f;
    }
    VertexNormal most = VertexNormal::Face;
    for (VertexNormal kind :
         {VertexNormal::NotNormalised, VertexNormal::Positions, VertexNormal::Other})
        if (share(kind) > share(most))
            most = kind;
    const QString percent = QString::number(100.0 * share(most), 'f', 0);
    switch (most) {
    case VertexNormal::Face:
        f.key = QStringLiteral("normals-face");
        f.message = PageNormalsWords::tr("%1: the faces' normals instead of Blender's (%2 % of "
                                         "the vertices): the mesh looks faceted")
                        .arg(name, percent);
        break;
    case VertexNormal::NotNormalised:
        f.key = QStringLiteral("normals-not-normalised");
        f.message = PageNormalsWords::tr("%1: Blender's directions, but not of length 1 (%2 % of "
                                         "the vertices)")
                        .arg(name, percent);
        break;
    case VertexNormal::Positions:
        f.key = QStringLiteral("normals-positions");
        f.message = PageNormalsWords::tr("%1: the positions sent as normals (%2 % of the "
                                         "vertices)")
                        .arg(name, percent);
        break;
    default:
        f.key = QStringLiteral("normals-other");
        f.message = PageNormalsWords::tr("%1: normals that are neither Blender's nor the faces' "
                                         "(%2 % of the vertices)")
                        .arg(name, percent);
    }
    return f;
}

} // namespace

std::vector<JavaScriptFinding> checkPageNormals(const PageCapture &capture,
                                                const std::vector<CourseMesh> &meshes)
{
    const std::vector<const CapturedOp *> draws = capture.draws();
    std::vector<std::optional<DrawnMesh>> drawn(meshes.size());
    std::vector<std::size_t> drawOf(meshes.size(), 0);
    for (std::size_t m = 0; m < meshes.size(); ++m) {
        const MeshNormals normals = normalsByPosition(meshes[m].mesh);
        for (std::size_t d = 0; d < draws.size() && !drawn[m]; ++d)
            if ((drawn[m] = drawnAs(capture, *draws[d], normals)))
                drawOf[m] = d;
    }
    const auto exact = [&](std::size_t m) {
        return drawn[m]->counts[std::size_t(VertexNormal::Exact)];
    };
    std::vector<JavaScriptFinding> out;
    for (std::size_t m = 0; m < meshes.size(); ++m) {
        if (!drawn[m]) {
            out.push_back({QStringLiteral("normals-missing"),
                           meshes[m].name,
                           true,
                           PageNormalsWords::tr("%1 is not drawn in the captured frame (its "
                                                "positions are in no draw's buffer)")
                               .arg(meshes[m].name),
                           {}});
            continue;
        }
        // Meshes of the same positions (cloud.obj and cloud_flat.obj) are
        // one drawn mesh: the one whose normals the page sent is it.
        bool another = false;
        for (std::size_t o = 0; o < meshes.size(); ++o)
            if (o != m && drawn[o] && drawOf[o] == drawOf[m]
                && (exact(o) > exact(m) || (exact(o) == exact(m) && o < m)))
                another = true;
        if (!another)
            out.push_back(findingFor(meshes[m].name, *drawn[m]));
    }
    return out;
}

} // namespace phonglab
