#pragma once
#include "core/scene/Scene.h"
#include "core/support/Result.h"

#include <QCoreApplication>
#include <QStringList>

namespace phonglab {

class LiveShaderController;
class ShaderDock;

// A scene's "shaders" and the Shaders dock, both ways: a scene being saved
// names the dock's files (their unsaved edits saved first), and an opened
// scene's files are opened in the dock and built.
class SceneShaderFiles
{
    Q_DECLARE_TR_FUNCTIONS(SceneShaderFiles)

public:
    SceneShaderFiles(ShaderDock *dock, LiveShaderController *liveShaders);

    // Saves both stages' unsaved edits (a shipped shader's go to its user
    // copy); the first failure, named by stage.
    Result<> saveEdits();
    // Sets scene.vertexShader/fragmentShader to the dock's files as a scene
    // saved at `sceneFilePath` names them; empty for shipped ones.
    void nameIn(Scene &scene, const QString &sceneFilePath) const;
    // Opens and builds `scene`'s files, if it names any. The shading
    // method's shipped shaders stand in for a missing one; unsaved edits in
    // the dock are never replaced.
    struct Opened {
        QString note;         // for the status bar; empty when there is nothing to say
        QStringList unusable; // one line per file that could not be used
    };
    Opened open(const Scene &scene);

private:
    ShaderDock *m_dock;
    LiveShaderController *m_liveShaders;
};

} // namespace phonglab
