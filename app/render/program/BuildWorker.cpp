#include "BuildWorker.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QThread>

namespace phonglab {

BuildWorker::BuildWorker(QOpenGLContext *context, QOffscreenSurface *surface)
    : m_context(context)
    , m_surface(surface)
{
}

Result<> BuildWorker::initialize()
{
    if (!m_context->makeCurrent(m_surface))
        return fail(BuildWorker::tr(
            "the shared OpenGL context cannot be made current on the compile thread"));
    m_parallelShaderCompile =
        m_context->hasExtension(QByteArrayLiteral("GL_KHR_parallel_shader_compile"))
        || m_context->hasExtension(QByteArrayLiteral("GL_ARB_parallel_shader_compile"));
    return {};
}

BuildReply BuildWorker::build(const BuildJob &request)
{
    BuildReply reply;
    reply.serial = request.serial;
    BuiltProgram built =
        m_builder.build(request.vertex, request.fragment, {}, request.bindings, request.course);
    reply.report = std::move(built.report);
    reply.program = std::move(built.program);
    reply.timings.compileNs = built.compileNs;
    reply.timings.linkNs = built.linkNs;
    QElapsedTimer timer;
    timer.start();
    const bool ok = bool(reply.program);
    if (ok && request.warm && m_warmSamples != request.warmSamples) {
        m_warmer.destroy(); // the viewport's framebuffer changed (or this is the first warm-up)
        m_warmSamples = m_warmer.create(WarmUpDraw::Target::OwnFramebuffer, request.warmSamples)
            ? request.warmSamples
            : -1;
    }
    if (ok && request.warm && m_warmer.isCreated())
        m_warmer.warm(reply.program.id()); // ends in glFinish
    else
        m_context->functions()
            ->glFinish(); // the program object is complete before it changes hands
    reply.timings.warmNs = request.warm && ok ? timer.nsecsElapsed() : 0;
    return reply;
}

Result<qint64> BuildWorker::warmInLentContext(const LentContext &lent, QOffscreenSurface *surface,
                                              GLuint program, QThread *owner)
{
    QElapsedTimer timer;
    timer.start();
    // On the lender's window, when it has one: its framebuffer is the one
    // whose shader variant the viewport's next frame needs.
    Result<> ready = lent.context->makeCurrent(lent.surface ? lent.surface : surface)
        ? Result<>()
        : fail(
            BuildWorker::tr("the viewport's context cannot be made current on the build thread"));
    if (ready && lent.whileCurrent)
        lent.whileCurrent();
    if (ready && !lent.warmer->isCreated())
        ready = lent.warmer->create(lent.surface ? WarmUpDraw::Target::Surface
                                                 : WarmUpDraw::Target::OwnFramebuffer,
                                    lent.samples);
    if (ready)
        lent.warmer->warm(program); // ends in glFinish
    if (ready && lent.afterWarm)
        lent.afterWarm(lent);
    lent.context->doneCurrent();
    lent.context->moveToThread(owner);
    m_context->makeCurrent(m_surface); // ready for the next build
    if (!ready)
        return fail(ready.error());
    return timer.nsecsElapsed();
}

void BuildWorker::shutdown(QThread *owner)
{
    if (m_context->makeCurrent(m_surface)) {
        m_warmer.destroy();
        m_context->doneCurrent();
    }
    m_context->moveToThread(owner);
}

} // namespace phonglab
