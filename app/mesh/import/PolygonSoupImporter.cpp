#include "PolygonSoupImporter.h"

#include "MeshTextTokens.h"

#include <QCoreApplication>
#include <cmath>
#include <limits>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct PolygonSoupImporterWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::PolygonSoupImporter)
};

namespace {

constexpr std::uint32_t kBadIndex = 0xffffffffu;
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

std::uint32_t cornerIndex(int idx)
{
    return idx < 0 ? kBadIndex : std::uint32_t(idx);
}

bool usableNormal(const glm::vec3 &n)
{
    return std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z)
        && (n.x != 0.0f || n.y != 0.0f || n.z != 0.0f);
}

} // namespace

void PolygonSoupImporter::setProgress(std::function<bool(std::size_t)> progress, std::size_t every)
{
    m_progress = std::move(progress);
    m_progressEvery = every;
}

void PolygonSoupImporter::countElement()
{
    ++m_elements;
    if (m_progress && m_progressEvery && m_elements % m_progressEvery == 0
        && !m_progress(m_elements))
        throw Cancelled{};
}

OpenMesh::VertexHandle PolygonSoupImporter::add_vertex(const OpenMesh::Vec3f &p)
{
    countElement();
    m_mesh.positions.emplace_back(p[0], p[1], p[2]);
    return OpenMesh::VertexHandle(int(m_mesh.positions.size() - 1));
}

OpenMesh::VertexHandle PolygonSoupImporter::add_vertex(const OpenMesh::Vec3d &p)
{
    return add_vertex(OpenMesh::Vec3f(float(p[0]), float(p[1]), float(p[2])));
}

OpenMesh::VertexHandle PolygonSoupImporter::add_vertex()
{
    return add_vertex(OpenMesh::Vec3f(0.0f, 0.0f, 0.0f));
}

void PolygonSoupImporter::set_point(OpenMesh::VertexHandle vh, const OpenMesh::Vec3f &p)
{
    if (vh.idx() >= 0 && std::size_t(vh.idx()) < m_mesh.positions.size())
        m_mesh.positions[vh.idx()] = glm::vec3(p[0], p[1], p[2]);
}

void PolygonSoupImporter::set_normal(OpenMesh::VertexHandle vh, const OpenMesh::Vec3f &n)
{
    if (vh.idx() < 0 || std::size_t(vh.idx()) >= m_mesh.positions.size())
        return;
    if (m_vertexNormals.size() <= std::size_t(vh.idx()))
        m_vertexNormals.resize(m_mesh.positions.size(), glm::vec3(kNaN));
    m_vertexNormals[vh.idx()] = glm::vec3(n[0], n[1], n[2]);
}

void PolygonSoupImporter::set_normal(OpenMesh::VertexHandle vh, const OpenMesh::Vec3d &n)
{
    set_normal(vh, OpenMesh::Vec3f(float(n[0]), float(n[1]), float(n[2])));
}

void PolygonSoupImporter::set_normal(OpenMesh::FaceHandle fh, const OpenMesh::Vec3f &n)
{
    if (fh.idx() < 0 || std::size_t(fh.idx()) >= m_faceCount)
        return;
    if (m_faceNormals.size() <= std::size_t(fh.idx()))
        m_faceNormals.resize(m_faceCount, glm::vec3(kNaN));
    m_faceNormals[fh.idx()] = glm::vec3(n[0], n[1], n[2]);
}

void PolygonSoupImporter::set_normal(OpenMesh::FaceHandle fh, const OpenMesh::Vec3d &n)
{
    set_normal(fh, OpenMesh::Vec3f(float(n[0]), float(n[1]), float(n[2])));
}

OpenMesh::FaceHandle PolygonSoupImporter::add_face(const VHandles &indices)
{
    countElement();
    for (const OpenMesh::VertexHandle &vh : indices)
        m_mesh.cornerPosition.push_back(cornerIndex(vh.idx()));
    m_mesh.faceStart.push_back(std::uint32_t(m_mesh.cornerPosition.size()));
    return OpenMesh::FaceHandle(int(m_faceCount++));
}

OpenMesh::HalfedgeHandle PolygonSoupImporter::add_edge(OpenMesh::VertexHandle from,
                                                       OpenMesh::VertexHandle to)
{
    m_edges.emplace_back(from.idx(), to.idx());
    m_next.resize(2 * m_edges.size(), -1);
    return OpenMesh::HalfedgeHandle(int(2 * (m_edges.size() - 1)));
}

void PolygonSoupImporter::set_next(OpenMesh::HalfedgeHandle heh, OpenMesh::HalfedgeHandle next)
{
    if (heh.idx() >= 0 && std::size_t(heh.idx()) < m_next.size())
        m_next[heh.idx()] = next.idx();
}

OpenMesh::FaceHandle PolygonSoupImporter::add_face(OpenMesh::HalfedgeHandle heh)
{
    countElement();
    m_faceHalfedge.push_back(heh.idx());
    return OpenMesh::FaceHandle(int(m_faceCount++));
}

void PolygonSoupImporter::reserve(unsigned int nV, unsigned int nE, unsigned int nF)
{
    if (nV <= m_reserveLimit)
        m_mesh.positions.reserve(nV);
    if (nF <= m_reserveLimit) {
        m_mesh.faceStart.reserve(std::size_t(nF) + 1);
        m_mesh.cornerPosition.reserve(3 * std::size_t(nF));
    }
}

void PolygonSoupImporter::buildHalfedgeFaces(QStringList &warnings)
{
    // Walk each face's halfedge loop and take the vertex each halfedge points
    // to. A loop that leaves the halfedge range or does not close within the
    // number of halfedges is broken: the file is corrupt there.
    const std::size_t halfedges = m_next.size();
    auto toVertex = [this](int h) {
        const auto &edge = m_edges[std::size_t(h) / 2];
        return (h & 1) ? edge.first : edge.second;
    };
    std::size_t broken = 0;
    std::vector<std::uint32_t> corners;
    for (int start : m_faceHalfedge) {
        corners.clear();
        bool closed = false;
        int h = start;
        for (std::size_t steps = 0; h >= 0 && std::size_t(h) < halfedges && steps < halfedges;
             ++steps) {
            corners.push_back(cornerIndex(toVertex(h)));
            h = m_next[h];
            if (h == start) {
                closed = true;
                break;
            }
        }
        if (!closed) {
            ++broken;
            continue;
        }
        m_mesh.cornerPosition.insert(m_mesh.cornerPosition.end(), corners.begin(), corners.end());
        m_mesh.faceStart.push_back(std::uint32_t(m_mesh.cornerPosition.size()));
    }
    if (broken)
        warnings << PolygonSoupImporterWords::tr(
                        "dropped %1 whose halfedge loop in the .om file is broken")
                        .arg(meshtext::counted(broken,
                                               QT_TRANSLATE_NOOP("phonglab::MeshText", "face"),
                                               QT_TRANSLATE_NOOP("phonglab::MeshText", "faces")));
    m_faceHalfedge.clear();
}

void PolygonSoupImporter::attachNormals(QStringList &warnings)
{
    if (!m_vertexNormals.empty()) {
        // Per-vertex normals: each corner uses its vertex's normal.
        m_vertexNormals.resize(m_mesh.positions.size(), glm::vec3(kNaN));
        m_mesh.normals = std::move(m_vertexNormals);
        m_mesh.cornerNormal.resize(m_mesh.cornerPosition.size());
        for (std::size_t c = 0; c < m_mesh.cornerPosition.size(); ++c) {
            const std::uint32_t v = m_mesh.cornerPosition[c];
            m_mesh.cornerNormal[c] = v < m_mesh.normals.size() ? v : PolygonMesh::kNoNormal;
        }
        return;
    }
    if (m_faceNormals.empty() || m_faceNormals.size() > m_mesh.faceCount())
        return;

    // STL facet normals. Many exporters write 0 0 0 to mean "compute it":
    // such facets get no file normal.
    m_faceNormals.resize(m_mesh.faceCount(), glm::vec3(kNaN));
    std::size_t unusable = 0;
    for (const glm::vec3 &n : m_faceNormals)
        unusable += usableNormal(n) ? 0 : 1;
    if (unusable == m_faceNormals.size()) {
        warnings << PolygonSoupImporterWords::tr(
            "the file's facet normals are all zero or invalid; normals will be computed");
        return;
    }
    if (unusable)
        warnings << PolygonSoupImporterWords::tr(
                        "%1 zero or invalid; those faces get computed normals")
                        .arg(meshtext::counted(
                            unusable, QT_TRANSLATE_NOOP("phonglab::MeshText", "facet normal is"),
                            QT_TRANSLATE_NOOP("phonglab::MeshText", "facet normals are")));
    m_mesh.normals = std::move(m_faceNormals);
    m_mesh.cornerNormal.resize(m_mesh.cornerPosition.size());
    for (std::size_t f = 0; f < m_mesh.faceCount(); ++f) {
        const std::uint32_t n =
            usableNormal(m_mesh.normals[f]) ? std::uint32_t(f) : PolygonMesh::kNoNormal;
        for (std::uint32_t c = m_mesh.faceStart[f]; c < m_mesh.faceStart[f + 1]; ++c)
            m_mesh.cornerNormal[c] = n;
    }
}

PolygonMesh PolygonSoupImporter::takeMesh(QStringList &warnings)
{
    // OM files carry either vertex-list faces (before version 2) or halfedge
    // faces, never both; halfedge faces are appended after any others.
    if (!m_faceHalfedge.empty())
        buildHalfedgeFaces(warnings);
    attachNormals(warnings);
    PolygonMesh mesh = std::move(m_mesh);
    m_mesh = PolygonMesh{};
    m_faceCount = 0;
    return mesh;
}

} // namespace phonglab
