#pragma once
#include "core/program/ShaderBindings.h"
#include "core/scene/ShadingMethod.h"
#include "render/gl/SharedGlObject.h"
#include "render/program/UniformIntrospection.h"
#include "render/program/UniformSnapshot.h"

#include <optional>
#include <vector>

namespace phonglab {

class GpuScene;
class Viewport;

// The program the view draws with, as the window sees it: its uniforms, read
// and set, and what its variables are bound to. What reaches GL takes the
// view's context first (CurrentContext), lent or not. Handed out by
// Viewport::program(), so that nothing outside the view reaches its renderer.
class ViewProgram
{
public:
    ViewProgram(Viewport *viewport, GpuScene *gpu);

    // One reading of the uniforms: the active ones as the driver lists them,
    // their values, and what each is bound to.
    struct Uniforms {
        std::vector<ActiveUniformInfo> active;
        UniformSnapshot values;
        ProgramBindings bindings;
    };
    // None before GL is up and a scene is shown.
    std::optional<Uniforms> readUniforms();
    // The uniforms' values (empty before GL is up).
    UniformSnapshot values();
    // Sets `value` where its name and type still match the program
    // (ShaderProgram::restore); the frame is the caller's to ask for. False,
    // and nothing set, before GL is up.
    bool set(const UniformValue &value);
    // What each of the program's variables is bound to (core/program/ShaderBindings.h).
    const ProgramBindings &bindings() const;
    // Switches to a program linked on a context sharing the view's objects
    // (the build thread's) and owns it from then on; uniforms the user set
    // carry over. Does nothing before GL is up (Viewport::glInitialized()).
    void adopt(GlProgram program);
    // The scene's shading method changes without touching the program: the
    // live shader controller builds it (so Save writes the method in use).
    void setShading(ShadingMethod method);
    // The scene's explicit bindings (its "bindings"): the uniforms' new
    // meanings apply from the next frame; vertex inputs keep theirs until
    // the program is linked again.
    void setBindings(const ExplicitBindings &bindings);
    // The program's GL name, which tells one program from the next (0 before GL).
    GLuint id() const;

private:
    Viewport *m_viewport = nullptr;
    GpuScene *m_gpu = nullptr;
};

} // namespace phonglab
