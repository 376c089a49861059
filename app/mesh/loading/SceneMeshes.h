#pragma once
#include "MeshLoader.h"
#include "core/scene/Scene.h"
#include "mesh/detail/DetailLevels.h"

#include <QHash>
#include <QSet>
#include <glm/glm.hpp>
#include <memory>
#include <vector>

namespace phonglab {

// The CPU side of a scene's meshes: every distinct (file, normal options) the
// scene's objects use, loaded once. Produced on any thread, uploaded on the
// GL thread by Renderer, then released: no second copy stays after upload.
struct SceneMeshes {
    struct Entry {
        std::shared_ptr<const MeshData> mesh; // null once uploaded
        // For objects with "detail": "auto": the levels of `mesh`; null otherwise.
        std::shared_ptr<const DetailLevels> levels;
        MeshStats stats;
        QStringList warnings;
    };
    QHash<QString, Entry> entries; // by meshKey()
    QString error;                 // the first mesh that failed; nothing usable then

    bool ok() const { return error.isEmpty(); }
};

// Identifies what an object's mesh is on the GPU: the resolved file, the
// way its normals were made, and its detail (a fraction, or "auto": the full
// mesh with its levels).
QString meshKey(const Scene &scene, const SceneObject &object);

// The corners of every object's mesh bounds, placed in the world: what a
// camera has to see to show every object (objects whose mesh is not in
// `entries` are left out).
std::vector<glm::dvec3> objectBoundsCorners(const Scene &scene,
                                            const QHash<QString, SceneMeshes::Entry> &entries);

// Loads every mesh `scene` needs, skipping keys in `alreadyLoaded`.
// progress(fraction over all meshes); false cancels.
SceneMeshes loadSceneMeshes(const Scene &scene, const QSet<QString> &alreadyLoaded = {},
                            const LoadProgress &progress = {});

} // namespace phonglab
