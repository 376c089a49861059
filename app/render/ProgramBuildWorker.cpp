#include "ProgramBuildWorker.h"

#include <QElapsedTimer>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QThread>

namespace phonglab {

ProgramBuildWorker::ProgramBuildWorker(QOpenGLContext *context, QOffscreenSurface *surface, int warmSamples)
    : m_context(context)
    , m_surface(surface)
    , m_warmSamples(warmSamples)
{
}

bool ProgramBuildWorker::initialize(QString *error)
{
    if (!m_context->makeCurrent(m_surface)) {
        if (error)
            *error = QStringLiteral("the shared OpenGL context cannot be made current on the compile thread");
        return false;
    }
    m_parallelShaderCompile = m_context->hasExtension(QByteArrayLiteral("GL_KHR_parallel_shader_compile"))
        || m_context->hasExtension(QByteArrayLiteral("GL_ARB_parallel_shader_compile"));
    m_rendererName = QString::fromLatin1(
        reinterpret_cast<const char *>(m_context->functions()->glGetString(GL_RENDERER)));
    return m_warmer.create(m_warmSamples, error);
}

ProgramBuildReply ProgramBuildWorker::build(const ProgramBuildRequest &request)
{
    ProgramBuildReply reply;
    reply.serial = request.serial;
    ProgramBuild built = m_builder.build(request.vertex, request.fragment);
    reply.result = std::move(built.result);
    reply.program = built.program;
    reply.compileNs = built.compileNs;
    reply.linkNs = built.linkNs;
    QElapsedTimer timer;
    timer.start();
    if (built.ok() && request.warm)
        m_warmer.warm(built.program); // ends in glFinish
    else
        m_context->functions()->glFinish(); // the program object is complete before it changes hands
    reply.warmNs = request.warm && built.ok() ? timer.nsecsElapsed() : 0;
    return reply;
}

void ProgramBuildWorker::release(GLuint program)
{
    if (program)
        m_context->extraFunctions()->glDeleteProgram(program);
}

void ProgramBuildWorker::shutdown(QThread *owner)
{
    if (m_context->makeCurrent(m_surface)) {
        m_warmer.destroy();
        m_context->doneCurrent();
    }
    m_context->moveToThread(owner);
}

} // namespace phonglab
