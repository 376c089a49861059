#pragma once
#include "core/scene/ShadingMethod.h"

#include <QObject>
#include <optional>

namespace phonglab {

class ShaderDock;
class ShaderRecovery;
class Viewport;

// The shading method the Shaders dock's text is of, and what a change of
// method does. The user's choice (the dock's box, a scene's shader files)
// loads that method's shipped shaders and the scene follows it. A scene's
// own (a scene opened) replaces the dock's text only when it holds no
// unsaved edits; otherwise the edits stay and the scene follows them. What
// is built is LiveShaderController's: this only says when.
class ShadingChoice : public QObject
{
    Q_OBJECT

public:
    // Shows the shipped shaders of the viewport's scene's method.
    ShadingChoice(ShaderDock *dock, ShaderRecovery *recovery, Viewport *viewport,
                  QObject *parent = nullptr);

    ShadingMethod method() const { return m_method; }
    // Puts `method`'s shipped shaders into the dock without building them
    // (the viewport builds its scene's program itself).
    void showShipped(ShadingMethod method);
    // The user chose `method`: its shipped shaders load and the scene
    // follows (so Save writes the method in use); chosen() asks for the build.
    void choose(ShadingMethod method);
    // The viewport's scene changed its shading method (a scene was opened).
    void followScene(ShadingMethod method);
    // The dock holds text restored from a dead session's journal, of `method`.
    void takeRestored(ShadingMethod method);

signals:
    // The user chose a method: its shipped shaders are to be built at once.
    void chosen();
    // The dock now shows the shipped text the viewport has just loaded: that
    // text is what is applied.
    void followedScene();
    // The scene's `sceneMethod` came with unsaved edits in the dock: they
    // stay, the scene follows them, and they are to be built again.
    void editsKept(phonglab::ShadingMethod sceneMethod);

private:
    ShaderDock *m_dock = nullptr;
    ShaderRecovery *m_recovery = nullptr;
    Viewport *m_viewport = nullptr;
    ShadingMethod m_method = ShadingMethod::Phong;
};

} // namespace phonglab
