#pragma once
#include "core/scene/ScenePaths.h" // meshFileSuffixes(), isMeshFile()

#include <QString>
#include <QStringList>

namespace phonglab {

// What the window opens, by file name suffix (case-insensitive): scenes
// (.json) and the mesh formats (core/scene/ScenePaths).
bool isSceneFile(const QString &path);

// Why `paths` cannot be opened together (unsupported types, a scene mixed
// with other files, nothing given); empty when they can.
QString whyNotOpenable(const QStringList &paths);
// "tree.obj, cloud.obj"
QString fileNameList(const QStringList &paths);

// QFileDialog name filters.
QString sceneFileFilter();
QString meshFileFilter();

} // namespace phonglab
