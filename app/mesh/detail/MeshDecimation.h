#pragma once
#include "core/scene/MeshData.h"

#include <QString>
#include <functional>
#include <vector>

namespace phonglab {

// Levels of detail for the bench and for a scene object's "detail".
//
// A coarser copy of `mesh` with about fraction × its triangles, made by
// OpenMesh's Decimater with the quadric module (halfedge collapses, so every
// position of the result is one of the input's, bit for bit). Collapses that
// would turn a face by more than 60° (a flip or a fold) are refused, and
// boundary vertices are locked, so open edges keep their exact outline and a
// closed mesh stays closed.
//
// Normals are the mesh's own, never recomputed for smooth meshes: a corner
// its face already had keeps its original normal; a corner a collapse moved
// onto another vertex takes, among the original normals at that position,
// the one closest to the new face's normal (hard edges stay hard, a smooth
// vertex keeps its single normal). A faceted mesh (every triangle's corners
// share one normal) stays faceted: a face gets the original normal closest
// to its own when they agree within 0.05°, else its own geometric normal.
//
// fraction in (0, 1]; 1 returns the mesh unchanged, as does a fraction out
// of range, NaN or an invalid mesh (with the note saying why). Faces OpenMesh
// cannot take (non-manifold edges or vertices, non-finite corners) are left
// out and counted in the note; triangles with two corners at one position (a
// UV sphere's poles) have no area and are dropped without a word. The decimation may stop
// above the target when every remaining collapse is refused; the note says so.
// Deterministic; no GL; safe on any thread.
//
// progress(fraction done) is called now and then on the calling thread;
// returning false stops the decimation: the mesh is then empty and the note
// says "cancelled".
using DecimationProgress = std::function<bool(double)>;
struct DecimatedMesh {
    MeshData mesh;
    QString note; // what the user should know about this level; empty when nothing
};
DecimatedMesh decimateMesh(const MeshData &mesh, double fraction,
                           const DecimationProgress &progress = {});

// Several levels at once, in the order of `fractions`, for the price of one
// decimation to the coarsest: one run goes from fine to coarse and each
// level is taken on the way (a level may differ from decimateMesh's at the
// same fraction only in the order of equally good collapses). The note
// gathers what each level would say.
struct DecimatedLevels {
    std::vector<MeshData> levels;
    QString note;
};
DecimatedLevels decimateMeshLevels(const MeshData &mesh, const std::vector<double> &fractions,
                                   const DecimationProgress &progress = {});

// True when the mesh, welded by exact position (MeshData splits a point into
// one vertex per normal), has every edge on exactly two triangles
// (isClosedSurface), triangles with two corners at one position ignored:
// what decimation must preserve.
bool isClosedMesh(const MeshData &mesh);

} // namespace phonglab
