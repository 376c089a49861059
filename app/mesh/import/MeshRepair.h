#pragma once
#include "PolygonMesh.h"

#include <QStringList>

namespace phonglab {

// What repairMesh() changed. Every non-zero count is one warning line.
struct RepairReport {
    int facesDroppedBadIndex = 0;   // a corner index >= positions.size() (readers store
                                    // unresolvable indices as 0xffffffff, so those too)
    int facesDroppedNonFinite = 0;  // a corner position with NaN or inf
    int facesDroppedDegenerate = 0; // fewer than 3 distinct corner positions, or zero area
    int normalsDiscarded = 0;       // corners whose file normal is missing, zero or not finite
    int nonManifoldEdges = 0;       // edges of 3 or more faces; kept, they render fine
    int orientationConflicts = 0;   // manifold edges no winding can agree on (Möbius-like)
    int facesFlipped = 0;           // faces reversed to agree with their neighbours
    int verticesDuplicated = 0;     // vertices split where surfaces meet only at that point
    int isolatedVerticesRemoved = 0;

    QStringList warnings() const;
};

// Makes a PolygonMesh as a reader produced it safe to triangulate, shade and
// render, dropping only what cannot be drawn and counting everything:
//  1. corners referring to a missing or unusable normal lose it (kNoNormal);
//  2. faces with an out-of-range index, a non-finite position, fewer than 3
//     distinct positions or (near-)zero area are dropped;
//  3. edges shared by 3+ faces are counted and kept;
//  4. winding is made consistent across manifold edges, per connected
//     component (breadth-first from its first face); a closed component is
//     then turned so its signed volume is positive, an open one so that the
//     fewest faces change (ties keep its first face as given);
//  5. a vertex where face fans meet at only that point (a "bowtie") gets one
//     copy per fan, so normals are not averaged across unrelated surfaces;
//  6. vertices no face uses are removed and indices remapped.
// File normals stay as given when a face is flipped. When no face is left,
// the caller reports "no usable faces".
RepairReport repairMesh(PolygonMesh &mesh);

} // namespace phonglab
