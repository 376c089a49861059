#pragma once
#include "core/scene/Scene.h"
#include "mesh/loading/SceneMeshes.h"

#include <QStringList>

namespace phonglab {

// Opening mesh files: they replace the scene's objects and are fitted into
// the view the scene's camera already frames.

// Every mesh's largest bounding-box extent becomes this (world units).
inline constexpr double kFittedMeshSize = 2.0;
// Centre-to-centre distance of meshes opened together, along X.
inline constexpr double kSideBySideSpacing = 2.5;

// `base` with its objects replaced by one per file (absolute paths), each
// with the material of base's first object. Camera, lights, ambient, shading
// and background stay.
Scene sceneWithMeshes(const Scene &base, const QStringList &paths);

// Uniform scale to kFittedMeshSize and the bounds' centre moved to
// (xOffset, 0, 0).
Transform fittedTransform(const MeshStats &stats, double xOffset = 0.0);

// Gives every object the fitted transform of its mesh, side by side along X
// centred on the origin, using the stats in `meshes` (by meshKey()).
Scene fittedSideBySide(Scene scene, const QHash<QString, SceneMeshes::Entry> &meshes);

} // namespace phonglab
