#include "ViewProgram.h"

#include "CurrentContext.h"
#include "render/draw/GpuScene.h"

#include <QOpenGLContext>

namespace phonglab {

ViewProgram::ViewProgram(Viewport *viewport, GpuScene *gpu)
    : m_viewport(viewport)
    , m_gpu(gpu)
{
}

std::optional<ViewProgram::Uniforms> ViewProgram::readUniforms()
{
    if (!m_gpu->isReady())
        return std::nullopt;
    const CurrentContext current(*m_viewport);
    ShaderProgram &program = m_gpu->renderer().program();
    return Uniforms{
        activeUniformsOf(QOpenGLContext::currentContext()->extraFunctions(), program.id()),
        program.snapshot(), program.bindings()};
}

UniformSnapshot ViewProgram::values()
{
    if (!m_gpu->isReady())
        return {};
    const CurrentContext current(*m_viewport);
    return m_gpu->programSnapshot();
}

bool ViewProgram::set(const UniformValue &value)
{
    if (!m_gpu->isReady())
        return false;
    const CurrentContext current(*m_viewport);
    m_gpu->renderer().program().restore(UniformSnapshot{{value}});
    return true;
}

const ProgramBindings &ViewProgram::bindings() const
{
    return m_gpu->renderer().program().bindings();
}

GLuint ViewProgram::id() const
{
    return m_gpu->renderer().program().id();
}

} // namespace phonglab
