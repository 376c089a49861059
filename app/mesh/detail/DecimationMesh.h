#pragma once
// Internal to MeshDecimation.cpp (and DecimationWeld.cpp, which reads the
// result back): the OpenMesh mesh type it decimates and its flip guard
// module, kept apart so each file stays one topic.
#include "mesh/import/OpenMeshHeaders.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace phonglab::decimation {

// OpenMesh's triangle mesh with two of its checks redone here, same logic.
// The originals live in libOpenMeshCore, which Debian builds with
// assertions on: each status lookup there builds and compares type-name
// strings, and these two run for every candidate collapse (about half of
// the decimation time). The decimater calls them through the mesh type, so
// these hide the library's.
struct OmMesh : OpenMesh::TriMesh_ArrayKernelT<> {
    OpenMesh::HalfedgeHandle find_halfedge(OpenMesh::VertexHandle from,
                                           OpenMesh::VertexHandle to) const
    {
        for (OpenMesh::HalfedgeHandle h : voh_range(from))
            if (to_vertex_handle(h) == to)
                return h;
        return OpenMesh::HalfedgeHandle();
    }

    // TriConnectivity::is_collapse_ok: may halfedge v0 -> v1 collapse
    // without breaking the surface (a fin, a pinched vertex, two faces on
    // top of each other)?
    bool is_collapse_ok(OpenMesh::HalfedgeHandle v0v1)
    {
        if (status(edge_handle(v0v1)).deleted())
            return false;
        const OpenMesh::HalfedgeHandle v1v0 = opposite_halfedge_handle(v0v1);
        const OpenMesh::VertexHandle v0 = to_vertex_handle(v1v0), v1 = to_vertex_handle(v0v1);
        if (status(v0).deleted() || status(v1).deleted())
            return false;
        // The two edges from the far corner of each face must not both be
        // boundary edges (the face would collapse into a dangling edge).
        OpenMesh::VertexHandle vl, vr;
        if (!is_boundary(v0v1)) {
            const OpenMesh::HalfedgeHandle h1 = next_halfedge_handle(v0v1),
                                           h2 = next_halfedge_handle(h1);
            vl = to_vertex_handle(h1);
            if (is_boundary(opposite_halfedge_handle(h1))
                && is_boundary(opposite_halfedge_handle(h2)))
                return false;
        }
        if (!is_boundary(v1v0)) {
            const OpenMesh::HalfedgeHandle h1 = next_halfedge_handle(v1v0),
                                           h2 = next_halfedge_handle(h1);
            vr = to_vertex_handle(h1);
            if (is_boundary(opposite_halfedge_handle(h1))
                && is_boundary(opposite_halfedge_handle(h2)))
                return false;
        }
        if (vl == vr)
            return false;
        // The one-rings of v0 and v1 may share only vl and vr (else two
        // faces would end up on top of each other). v1's ring is gathered
        // into a small array and compared (valences are small) rather than
        // tagged as the library does: that touched every neighbour's status
        // three times, and on large meshes those are cache misses.
        std::array<OpenMesh::VertexHandle, 64> ring1;
        std::size_t ring1Size = 0;
        for (OpenMesh::VertexHandle v : vv_range(v1)) {
            if (ring1Size == ring1.size())
                return oneRingsShareOnly(v0, v1, vl, vr); // a high valence: tag instead
            ring1[ring1Size++] = v;
        }
        for (OpenMesh::VertexHandle v : vv_range(v0))
            if (v != vl && v != vr
                && std::find(ring1.begin(), ring1.begin() + ring1Size, v)
                    != ring1.begin() + ring1Size)
                return false;
        return !pinches(v0v1, v1v0, v0, v1);
    }

private:
    // An inner edge between two boundary vertices would pinch the surface.
    bool pinches(OpenMesh::HalfedgeHandle v0v1, OpenMesh::HalfedgeHandle v1v0,
                 OpenMesh::VertexHandle v0, OpenMesh::VertexHandle v1) const
    {
        return is_boundary(v0) && is_boundary(v1) && !is_boundary(v0v1) && !is_boundary(v1v0);
    }

    bool oneRingsShareOnly(OpenMesh::VertexHandle v0, OpenMesh::VertexHandle v1,
                           OpenMesh::VertexHandle vl, OpenMesh::VertexHandle vr)
    {
        for (OpenMesh::VertexHandle v : vv_range(v0))
            status(v).set_tagged(false);
        for (OpenMesh::VertexHandle v : vv_range(v1))
            status(v).set_tagged(true);
        for (OpenMesh::VertexHandle v : vv_range(v0))
            if (status(v).tagged() && v != vl && v != vr)
                return false;
        const OpenMesh::HalfedgeHandle v0v1 = find_halfedge(v0, v1);
        return !pinches(v0v1, opposite_halfedge_handle(v0v1), v0, v1);
    }
};

// ModNormalFlippingT's test (no face around the collapsing vertex may turn
// by more than the limit), without normalising each moved face's normal:
// d = n_old · n_new ≥ cos(limit) |n_new| as d > 0 and d² ≥ cos² |n_new|²
// (cos > 0 for a limit below 90°). The library's version spent half of all
// decimation time in those square roots. The decimater itself keeps the
// stored face normals current after each collapse.
template <typename MeshT> class ModFlipGuardT : public OpenMesh::Decimater::ModBaseT<MeshT>
{
public:
    DECIMATING_MODULE(ModFlipGuardT, MeshT, FlipGuard);

    explicit ModFlipGuardT(MeshT &mesh)
        : Base(mesh, true)
    {
    }

    void set_max_normal_deviation(double degrees)
    {
        const double c = std::cos(glm::radians(std::clamp(degrees, 0.0, 89.0)));
        m_minCosSquared = float(c * c);
    }

    float collapse_priority(const CollapseInfo &ci) override
    {
        const MeshT &mesh = Base::mesh();
        for (OpenMesh::HalfedgeHandle h : mesh.voh_range(ci.v0)) {
            const OpenMesh::FaceHandle f = mesh.face_handle(h);
            if (!f.is_valid() || f == ci.fl || f == ci.fr)
                continue; // the two faces the collapse removes
            const OpenMesh::HalfedgeHandle next = mesh.next_halfedge_handle(h);
            const auto b = mesh.point(mesh.to_vertex_handle(h)) - ci.p1;
            const auto c = mesh.point(mesh.to_vertex_handle(next)) - ci.p1;
            const auto moved = OpenMesh::cross(b, c); // the face with v0 at v1's place
            const float d = OpenMesh::dot(mesh.normal(f), moved);
            if (!(d > 0.0f && d * d >= m_minCosSquared * moved.sqrnorm()))
                return float(Base::ILLEGAL_COLLAPSE);
        }
        return float(Base::LEGAL_COLLAPSE);
    }

private:
    float m_minCosSquared = 0.25f;
};

} // namespace phonglab::decimation
