#include "ShadingChoice.h"

#include "ShaderDock.h"
#include "ShaderRecovery.h"
#include "render/program/ShaderSource.h"
#include "ui/viewport/Viewport.h"

namespace phonglab {

ShadingChoice::ShadingChoice(ShaderDock *dock, ShaderRecovery *recovery, Viewport *viewport,
                             QObject *parent)
    : QObject(parent)
    , m_dock(dock)
    , m_recovery(recovery)
    , m_viewport(viewport)
{
    connect(m_dock, &ShaderDock::shadingMethodRequested, this, &ShadingChoice::choose);
    showShipped(m_viewport->currentScene().shading);
}

void ShadingChoice::showShipped(ShadingMethod method)
{
    const Result<StageSources> shipped = readShippedStages(method);
    if (!shipped) {
        m_dock->setCompileStatus(shipped.error(), false);
        return;
    }
    m_dock->setSources(shipped->vertex, shipped->fragment);
    m_dock->selectShadingMethod(method);
    m_method = method;
    m_recovery->setShading(shadingName(method));
}

void ShadingChoice::choose(ShadingMethod method)
{
    showShipped(method);
    m_viewport->program().setShading(method);
    emit chosen();
}

void ShadingChoice::followScene(ShadingMethod method)
{
    if (method == m_method)
        return;
    if (!m_dock->hasUnsavedChanges()) {
        showShipped(method); // what the viewport has just loaded
        emit followedScene();
        return;
    }
    // Unsaved edits are never replaced behind the user's back: they stay,
    // are built again over the scene's program, and the scene follows them.
    m_viewport->program().setShading(m_method);
    emit editsKept(method);
}

void ShadingChoice::takeRestored(ShadingMethod method)
{
    m_method = method;
    m_dock->selectShadingMethod(method);
}

} // namespace phonglab
