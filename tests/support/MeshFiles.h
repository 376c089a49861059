#pragma once
#include "mesh/import/OpenMeshHeaders.h"

#include <QByteArray>
#include <QString>

class QTemporaryDir;

// Mesh files made by the tests: OpenMesh's own writers and raw bytes.
namespace phonglab::test {

using TriMesh = OpenMesh::TriMesh_ArrayKernelT<>;

// The unit tetrahedron, outward faces: (0,0,0) (1,0,0) (0,1,0) (0,0,1).
TriMesh referenceTetra();

// Writes `m` with OpenMesh's writer for the suffix of `path`, its console
// chatter silenced.
bool writeMesh(const TriMesh &m, const QString &path, OpenMesh::IO::Options options);

// The reference tetrahedron written to dir/name; the path, or empty on failure.
QString writeTetra(const QTemporaryDir &dir, const QString &name, bool binary);

void writeBytes(const QString &path, const QByteArray &bytes);
QByteArray readBytes(const QString &path);

} // namespace phonglab::test
