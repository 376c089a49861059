#include "SceneShaderFiles.h"

#include "core/project/ProjectShader.h"

#include "LiveShaderController.h"
#include "ShaderDock.h"
#include "ShaderEditor.h"
#include "ShaderFileSet.h"
#include "core/scene/ScenePaths.h"

#include <QDir>
#include <QFileInfo>
#include <QTabWidget>

namespace phonglab {

SceneShaderFiles::SceneShaderFiles(ShaderDock *dock, LiveShaderController *liveShaders)
    : m_dock(dock)
    , m_liveShaders(liveShaders)
{
}

Result<> SceneShaderFiles::saveEdits()
{
    for (const ShaderStage stage : {ShaderStage::Vertex, ShaderStage::Fragment}) {
        if (!m_dock->isDirty(stage))
            continue;
        if (const Result<> saved = m_dock->save(stage); !saved)
            return fail(tr("Cannot save the %1 shader: %2").arg(stageName(stage), saved.error()));
    }
    return {};
}

void SceneShaderFiles::nameIn(Scene &scene, const QString &sceneFilePath) const
{
    const auto entry = [&](ShaderStage stage) {
        const QString file = m_dock->filePath(stage);
        if (file.isEmpty() || !isWritableLocation(file) || m_dock->files()->isShipped(file))
            return QString();
        return pathFromScene(file, sceneFilePath);
    };
    scene.vertexShader = entry(ShaderStage::Vertex);
    scene.fragmentShader = entry(ShaderStage::Fragment);
}

SceneShaderFiles::Opened SceneShaderFiles::open(const Scene &scene)
{
    if (scene.vertexShader.isEmpty() && scene.fragmentShader.isEmpty())
        return {};
    if (m_dock->hasUnsavedChanges())
        return {tr("Kept your unsaved shader edits; the scene's shader files were not loaded"), {}};
    const std::pair<ShaderStage, QString> files[] = {{ShaderStage::Vertex, scene.vertexShader},
                                                     {ShaderStage::Fragment, scene.fragmentShader}};
    QStringList missing;
    for (const auto &[stage, name] : files) {
        const QString path = scene.resolveShaderPath(name);
        if (!name.isEmpty() && !QFileInfo(path).isFile() && !isShaderLocator(path))
            missing << tr("shaders.%1: %2: file not found")
                           .arg(stageName(stage), QDir::toNativeSeparators(path));
    }
    // The shading method's shipped shaders, shown and built, under whatever is missing.
    if (!missing.isEmpty())
        m_liveShaders->shading()->choose(scene.shading);
    bool opened = false;
    for (const auto &[stage, name] : files) {
        const QString path = scene.resolveShaderPath(name);
        if (name.isEmpty() || (!QFileInfo(path).isFile() && !isShaderLocator(path)))
            continue;
        // One at a time, each into its stage, whatever its suffix.
        if (const Result<> read = m_dock->openFile(stage, path))
            opened = true;
        else
            missing << tr("shaders.%1: %2").arg(stageName(stage), read.error());
    }
    if (opened)
        m_liveShaders->buildNow(); // a failure shows in the dock; the last good program stays
    return {QString(), missing};
}

} // namespace phonglab
