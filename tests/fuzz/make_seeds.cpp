// Writes the binary seeds of tests/fuzz/corpus/ that cannot be typed in: OM
// files, binary PLY/STL/OFF (OpenMesh's writers) and mesh cache entries
// (MeshCache::encode). The text seeds are checked in as they are.
//   build-sanitize/tests/fuzz/fuzz_make_seeds tests/fuzz/corpus
// (scripts/fuzz.sh --make-seeds). The output is deterministic.
#include "mesh/loading/MeshCache.h"
#include "mesh/loading/MeshLoader.h"

#include "mesh/import/OpenMeshHeaders.h"

#include <QBuffer>
#include <QDir>
#include <QFile>

#include <cstdio>

namespace {

using Mesh = OpenMesh::PolyMesh_ArrayKernelT<>;

Mesh tetrahedron(bool quadBase)
{
    Mesh mesh;
    std::vector<Mesh::VertexHandle> v;
    v.push_back(mesh.add_vertex({0, 0, 0}));
    v.push_back(mesh.add_vertex({1, 0, 0}));
    v.push_back(mesh.add_vertex({0, 1, 0}));
    v.push_back(mesh.add_vertex({0, 0, 1}));
    if (quadBase) { // a square pyramid: one quad, four triangles
        v.push_back(mesh.add_vertex({1, 1, 0}));
        mesh.add_face(std::vector<Mesh::VertexHandle>{v[0], v[2], v[4], v[1]});
        mesh.add_face(v[0], v[1], v[3]);
        mesh.add_face(v[1], v[4], v[3]);
        mesh.add_face(v[4], v[2], v[3]);
        mesh.add_face(v[2], v[0], v[3]);
    } else {
        mesh.add_face(v[0], v[2], v[1]);
        mesh.add_face(v[0], v[1], v[3]);
        mesh.add_face(v[1], v[2], v[3]);
        mesh.add_face(v[2], v[0], v[3]);
    }
    mesh.request_vertex_normals();
    mesh.request_face_normals();
    mesh.update_normals();
    return mesh;
}

bool write(const Mesh &mesh, const QString &path, OpenMesh::IO::Options options)
{
    if (!OpenMesh::IO::write_mesh(mesh, QFile::encodeName(path).toStdString(), options)) {
        std::fprintf(stderr, "make_seeds: cannot write %s\n", qPrintable(path));
        return false;
    }
    return true;
}

bool writeCacheEntry(const QString &meshFile, const QString &path)
{
    const phonglab::MeshLoadResult result = phonglab::importMeshFile(meshFile);
    QFile out(path);
    if (!result.ok() || !out.open(QIODevice::WriteOnly)
        || !phonglab::MeshCache::encode(out, QByteArrayLiteral("fuzz-seed"), result)) {
        std::fprintf(stderr, "make_seeds: cannot make a cache entry from %s\n",
                     qPrintable(meshFile));
        return false;
    }
    return true;
}

} // namespace

int main(int argc, char **argv)
{
    if (argc != 3) {
        std::fprintf(stderr, "usage: fuzz_make_seeds CORPUS_DIR TEST_DATA_DIR\n");
        return 2;
    }
    const QDir corpus(QString::fromLocal8Bit(argv[1]));
    const QDir data(QString::fromLocal8Bit(argv[2]));
    for (const char *d : {"om", "ply", "stl", "off", "meshcache"})
        corpus.mkpath(QString::fromLatin1(d));
    using O = OpenMesh::IO::Options;
    const Mesh tetra = tetrahedron(false), pyramid = tetrahedron(true);
    bool ok = write(tetra, corpus.filePath("om/tetra.om"), O::Default)
        && write(pyramid, corpus.filePath("om/pyramid_normals.om"), O(O::VertexNormal))
        && write(tetra, corpus.filePath("ply/tetra_binary_le.ply"), O(O::Binary | O::LSB))
        && write(pyramid, corpus.filePath("ply/pyramid_binary_be_normals.ply"),
                 O(O::Binary | O::MSB | O::VertexNormal))
        && write(tetra, corpus.filePath("stl/tetra_binary.stl"), O(O::Binary))
        && write(pyramid, corpus.filePath("off/pyramid_binary.off"), O(O::Binary))
        && writeCacheEntry(data.filePath("meshes/formats/tetra.obj"),
                           corpus.filePath("meshcache/tetra.phmc"))
        && writeCacheEntry(data.filePath("meshes/blender/cube_flat.obj"),
                           corpus.filePath("meshcache/cube_flat.phmc"));
    return ok ? 0 : 1;
}
