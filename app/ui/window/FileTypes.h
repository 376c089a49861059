#pragma once
#include <QString>
#include <QStringList>

namespace phonglab {

// What the window opens, by file name suffix (case-insensitive): scenes
// (.json) and the mesh formats loadMesh reads.
bool isSceneFile(const QString &path);
bool isMeshFile(const QString &path);
QStringList meshFileSuffixes(); // "obj", "ply", ...

// Why `paths` cannot be opened together (unsupported types, a scene mixed
// with other files, nothing given); empty when they can.
QString whyNotOpenable(const QStringList &paths);
// "tree.obj, cloud.obj"
QString fileNameList(const QStringList &paths);

// QFileDialog name filters.
QString sceneFileFilter();
QString meshFileFilter();

} // namespace phonglab
