#pragma once
#include "Scene.h"
#include "core/support/Result.h"

#include <QByteArray>
#include <QString>
#include <QStringList>
#include <optional>

namespace phonglab {

// Reading and writing scene files (JSON). The format is described field by
// field in docs/scene-format.md; keep the two in step.
//
// Errors are meant to be shown to the person who wrote the file, so every
// message starts with the JSON path of the offending field, e.g.
//   "lights[1].attenuation: c1 + c2 + c3 must be positive (got 0)"
//   "camera.fov_deg: must be in (0, 180) degrees (got 180)"
// The two exceptions are malformed JSON ("JSON syntax error at line L, ...")
// and a top level that is not an object ("top level: ...").
struct SceneLoadResult {
    std::optional<Scene> scene; // set on success
    QString error;              // set on failure
    int errorLine = 0;          // where a JSON syntax error is (1-based); 0: no text position
    int errorColumn = 0;
    QStringList warnings; // non-fatal findings, e.g. "camera.fovy: unknown key, ignored"

    bool ok() const { return scene.has_value(); }
};

// The scene format this PhongLab writes ("format"). A file without the
// field is format 1; format 2 made "flat" mean flat shading once per face
// (format 1's "flat", the per-fragment shader, loads as "faceted").
inline constexpr int kSceneFormat = 2;

// Parses and validates a scene. `baseDir` becomes Scene::baseDir, the folder
// relative mesh paths resolve against.
SceneLoadResult parseScene(const QByteArray &json, const QString &baseDir = {});

// Reads `path` and parses it with baseDir = the file's folder (absolute).
SceneLoadResult loadSceneFile(const QString &path);

// Indented JSON that parseScene reads back into an equal Scene. Writes the
// single-object form when the scene has exactly one object without its own
// shading, else "objects".
QByteArray sceneToJson(const Scene &scene);

// Writes sceneToJson(scene) to `path` atomically (QSaveFile): on any failure
// the previous file, if any, is left untouched. A scene that would not load
// back (e.g. no objects, a zero scale) is refused rather than written.
Result<> saveSceneFile(const Scene &scene, const QString &path);

} // namespace phonglab
