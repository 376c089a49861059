#pragma once
#include "BenchHelpers.h"
#include "mesh/import/BuiltinMeshes.h"
#include "mesh/loading/SceneMeshes.h"

#include <algorithm>
#include <cmath>
#include <memory>

// The mesh the scaling benches grow: the built-in UV sphere, finer and finer.
namespace phonglab::bench {

// The UV sphere with about `triangles` triangles (slices = 2 stacks).
inline std::shared_ptr<const MeshData> sphereOf(double triangles)
{
    const int stacks = std::max(3, int(std::lround(std::sqrt(triangles / 4.0))));
    return std::make_shared<const MeshData>(makeUvSphere(2 * stacks, stacks));
}

// One name per tessellation: the renderer keeps a mesh it has by its key.
inline Scene sphereScene(const MeshData &mesh)
{
    return litObjectScene(QStringLiteral("uv-sphere-%1.mesh").arg(mesh.triangleCount()));
}

// What loadSceneMeshes() would hand the renderer for `scene`'s one object.
inline SceneMeshes meshesOf(const Scene &scene, const std::shared_ptr<const MeshData> &mesh)
{
    SceneMeshes meshes;
    SceneMeshes::Entry entry;
    entry.mesh = mesh;
    entry.stats.triangles = qint64(mesh->triangleCount());
    entry.stats.vertices = qint64(mesh->positions.size());
    entry.stats.closed = true;
    entry.stats.boundsMin = glm::vec3(-1.0f); // the unit sphere: the fitted depth range needs it
    entry.stats.boundsMax = glm::vec3(1.0f);
    meshes.entries.insert(meshKey(scene, scene.objects.front()), entry);
    return meshes;
}

// The least a mesh can be held in: positions and normals as floats, 32-bit
// indices.
inline double minimumBytes(const MeshData &mesh)
{
    return double(mesh.positions.size()) * 24.0 + double(mesh.indices.size()) * 4.0;
}

} // namespace phonglab::bench
