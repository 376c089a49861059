#pragma once
#include <QString>

#include <vector>

namespace phonglab {

// The normal methods of the importer (computeNormals: flat, average, area,
// angle) on regular and irregular tessellations of the unit sphere, where
// the exact normal is known: how far off each method is, and what it costs.
// For the bench's "which normals does a scene need" and docs.
struct NormalStudyRow {
    QString tessellation; // e.g. "UV sphere 64×32", "icosphere (jittered)"
    QString method;       // normalMethodName(): "flat", "average", "area", "angle"
    qint64 triangles = 0;
    double ms = 0;          // computeNormals, median of the repeats
    double maxAngleDeg = 0; // per corner, against normalize(corner position)
    double meanAngleDeg = 0;
};

// For three sphere tessellations with fixed seeds — a regular UV sphere
// (64×32), an irregular one (an icosphere, 5 subdivisions, its vertices
// jittered by up to 40 % of an edge and re-projected onto the sphere) and a
// UV sphere (128×64) decimated to a quarter with decimateMesh — computes
// normals with each method, timing each (median of `repeats` runs, ms) and
// measuring the angle at every triangle corner against the exact sphere
// normal at that corner's point (for flat too: the face's normal at each of
// its corners). Deterministic apart from the times. repeats < 1 counts as 1.
std::vector<NormalStudyRow> runNormalStudy(int repeats = 5);

} // namespace phonglab
