#include "ViewProgram.h"

#include "CurrentContext.h"
#include "Viewport.h"
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

void ViewProgram::adopt(GlProgram program)
{
    if (!m_gpu->isInitialized())
        return; // no context to free it with either; it goes with its share group
    {
        const CurrentContext current(*m_viewport);
        m_gpu->renderer().adoptProgram(std::move(program));
    }
    ViewportSurface &surface = *m_viewport->m_surface;
    surface.presentNextOffThread(); // the frame after an edit: typing goes on meanwhile
    surface.releaseHold();          // a new program is drawn once at least
    surface.requestFrame();
}

void ViewProgram::setShading(ShadingMethod method)
{
    m_gpu->setShading(method);
    m_viewport->cameraMoved(); // the parameters changed; repaint
}

void ViewProgram::setBindings(const ExplicitBindings &bindings)
{
    m_gpu->setBindings(bindings);
    m_viewport->parametersChanged();
    emit m_viewport->sceneParametersChanged();
}

GLuint ViewProgram::id() const
{
    return m_gpu->renderer().program().id();
}

} // namespace phonglab
