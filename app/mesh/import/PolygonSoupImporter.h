#pragma once
#include "PolygonMesh.h"

#include "OpenMeshHeaders.h"

#include <QStringList>
#include <functional>
#include <utility>
#include <vector>

namespace phonglab {

// The target OpenMesh's reader modules write into when we read PLY, OFF, STL
// and OM. OpenMesh's own importer (read_mesh into a PolyMesh) builds
// halfedge topology and silently drops every face that does not fit it
// (non-manifold, flipped against a neighbour, bad index): exactly the faces
// MeshRepair wants to see and count. This importer records vertices, normals
// and faces as the file gives them and refuses nothing.
//
// Index convention: a corner index the file gives as negative is stored as
// 0xffffffff, which is never a valid position index, so MeshRepair drops the
// face as out of range like any other bad index.
class PolygonSoupImporter final : public OpenMesh::IO::BaseImporter
{
public:
    // Thrown out of add_vertex/add_face when the progress callback asks to
    // stop: the only way to interrupt an OpenMesh reader module.
    struct Cancelled {
    };

    // Called with the number of vertices plus faces added so far, every
    // `every` elements; returning false throws Cancelled.
    void setProgress(std::function<bool(std::size_t)> progress, std::size_t every);
    // Reservation requests above this many elements are ignored: the counts
    // come from file headers and must not decide how much we allocate.
    void setReserveLimit(std::size_t elements) { m_reserveLimit = elements; }

    // The mesh read so far. Problems found while assembling it (faces of an
    // OM file whose halfedge loop is broken, unusable STL facet normals) are
    // appended to `warnings`.
    PolygonMesh takeMesh(QStringList &warnings);

    std::size_t faceCallCount() const { return m_faceCount; }

    // --- OpenMesh::IO::BaseImporter
    OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3f &point) override;
    OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3d &point) override;
    OpenMesh::VertexHandle add_vertex() override;
    OpenMesh::HalfedgeHandle add_edge(OpenMesh::VertexHandle from,
                                      OpenMesh::VertexHandle to) override;
    OpenMesh::FaceHandle add_face(const VHandles &indices) override;
    OpenMesh::FaceHandle add_face(OpenMesh::HalfedgeHandle heh) override;
    void set_point(OpenMesh::VertexHandle vh, const OpenMesh::Vec3f &point) override;
    void set_normal(OpenMesh::VertexHandle vh, const OpenMesh::Vec3f &normal) override;
    void set_normal(OpenMesh::VertexHandle vh, const OpenMesh::Vec3d &normal) override;
    void set_normal(OpenMesh::FaceHandle fh, const OpenMesh::Vec3f &normal) override;
    void set_normal(OpenMesh::FaceHandle fh, const OpenMesh::Vec3d &normal) override;
    void set_next(OpenMesh::HalfedgeHandle heh, OpenMesh::HalfedgeHandle next) override;
    void reserve(unsigned int nV, unsigned int nE, unsigned int nF) override;
    OpenMesh::BaseKernel *kernel() override { return &m_kernel; }
    std::size_t n_vertices() const override { return m_mesh.positions.size(); }
    std::size_t n_faces() const override { return m_faceCount; }
    std::size_t n_edges() const override { return m_edges.size(); }

    // Attributes we do not use: texture coordinates, colours, status bits,
    // the halfedge-to-face links (a face's own halfedge is enough).
    void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle,
                            const std::vector<OpenMesh::Vec2f> &) override
    {
    }
    void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle,
                            const std::vector<OpenMesh::Vec3f> &) override
    {
    }
    void set_face_texindex(OpenMesh::FaceHandle, int) override { }
    void set_halfedge(OpenMesh::VertexHandle, OpenMesh::HalfedgeHandle) override { }
    void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec3uc &) override { }
    void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec4uc &) override { }
    void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec3f &) override { }
    void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec4f &) override { }
    void set_texcoord(OpenMesh::VertexHandle, const OpenMesh::Vec2f &) override { }
    void set_texcoord(OpenMesh::VertexHandle, const OpenMesh::Vec3f &) override { }
    void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec2f &) override { }
    void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec3f &) override { }
    void set_status(OpenMesh::VertexHandle, const OpenMesh::Attributes::StatusInfo &) override { }
    void set_status(OpenMesh::HalfedgeHandle, const OpenMesh::Attributes::StatusInfo &) override { }
    void set_status(OpenMesh::EdgeHandle, const OpenMesh::Attributes::StatusInfo &) override { }
    void set_status(OpenMesh::FaceHandle, const OpenMesh::Attributes::StatusInfo &) override { }
    void set_face(OpenMesh::HalfedgeHandle, OpenMesh::FaceHandle) override { }
    void request_face_texcoords2D() override { }
    void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3uc &) override { }
    void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4uc &) override { }
    void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3f &) override { }
    void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4f &) override { }
    void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec3uc &) override { }
    void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec4uc &) override { }
    void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec3f &) override { }
    void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec4f &) override { }
    void add_texture_information(int, std::string) override { }

private:
    void countElement();
    void buildHalfedgeFaces(QStringList &warnings);
    void attachNormals(QStringList &warnings);

    PolygonMesh m_mesh;
    std::size_t m_faceCount = 0;

    std::vector<glm::vec3> m_vertexNormals; // grown on demand, NaN where unset
    std::vector<glm::vec3> m_faceNormals;   // STL facet normals, NaN where unset

    // OM files from version 2 on: faces are given by one halfedge each and
    // the halfedges by their next links; halfedge 2e runs along edge e,
    // 2e+1 against it.
    std::vector<std::pair<int, int>> m_edges;
    std::vector<int> m_next;
    std::vector<int> m_faceHalfedge;

    // OM custom property chunks look properties up by name in a kernel; an
    // empty one makes the reader skip them.
    OpenMesh::BaseKernel m_kernel;

    std::function<bool(std::size_t)> m_progress;
    std::size_t m_progressEvery = 0;
    std::size_t m_elements = 0;
    std::size_t m_reserveLimit = 0;
};

} // namespace phonglab
