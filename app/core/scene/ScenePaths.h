#pragma once
#include "Scene.h"

#include <QString>
#include <QStringList>

namespace phonglab {

// Where a scene's files are, as the scene file says them: paths relative to
// the scene file's folder unless they lie outside it.

// The mesh formats a scene's "mesh" may name (loadMesh reads them), by file
// name suffix, case-insensitive: "obj", "ply", "off", "stl", "om".
QStringList meshFileSuffixes();
bool isMeshFile(const QString &path);

// Scenes embedded in the binary (":/...") can be opened but not written.
bool isWritableLocation(const QString &path);

// `scene` as it must be written to `sceneFilePath`: relative mesh paths are
// relative to the scene file, so saving into another folder rewrites them
// to keep pointing at the same meshes.
Scene rebasedOnto(Scene scene, const QString &sceneFilePath);

// How a scene saved at `sceneFilePath` names `file`: relative when it lies
// under the scene's folder, else absolute.
QString pathFromScene(const QString &file, const QString &sceneFilePath);

} // namespace phonglab
