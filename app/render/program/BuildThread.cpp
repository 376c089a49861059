#include "BuildThread.h"

#include <QCoreApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QThread>
#include <atomic>
#include <chrono>

namespace phonglab {

namespace {

// How long stop() waits for the worker. A shader stuck in an endless loop
// keeps the worker in the driver forever; the app must still be able to quit.
constexpr unsigned long kJoinTimeoutMs = 3000;

qint64 monotonicNs()
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

} // namespace

BuildThread::BuildThread(QObject *parent)
    : QObject(parent)
{
}

BuildThread::~BuildThread()
{
    stop();
}

Result<> BuildThread::start(QOpenGLContext *shareContext)
{
    stop();
    if (!shareContext)
        return fail(BuildThread::tr("the viewport has no OpenGL context yet"));
    auto context = std::make_unique<QOpenGLContext>();
    context->setFormat(shareContext->format());
    context->setShareContext(shareContext);
    if (!context->create() || !QOpenGLContext::areSharing(context.get(), shareContext))
        return fail(
            BuildThread::tr("the driver cannot create an OpenGL context sharing the viewport's"));
    // QOffscreenSurface must be created (and destroyed) on the GUI thread.
    auto surface = std::make_unique<QOffscreenSurface>();
    surface->setFormat(context->format());
    surface->create();
    if (!surface->isValid())
        return fail(BuildThread::tr("cannot create an offscreen surface for the compile thread"));
    // For the viewport's own context when it is lent: a surface of its format.
    auto lentSurface = std::make_unique<QOffscreenSurface>();
    lentSurface->setFormat(shareContext->format());
    lentSurface->create();

    auto thread = std::make_unique<QThread>();
    thread->setObjectName(QStringLiteral("phonglab-shader-build"));
    auto *worker = new BuildWorker(context.get(), surface.get());
    worker->moveToThread(thread.get());
    connect(thread.get(), &QThread::finished, worker, &QObject::deleteLater);
    context->moveToThread(thread.get());
    thread->start();

    Result<> initialized;
    QThread *gui = this->thread();
    QMetaObject::invokeMethod(
        worker,
        [&] {
            initialized = worker->initialize();
            if (!initialized)
                worker->shutdown(gui);
        },
        Qt::BlockingQueuedConnection);
    if (!initialized) {
        thread->quit();
        thread->wait();
        return initialized;
    }
    m_parallelShaderCompile = worker->hasParallelShaderCompile();
    m_thread = std::move(thread);
    m_surface = std::move(surface);
    m_lentSurface = std::move(lentSurface);
    m_context = std::move(context);
    m_worker = worker;
    ++m_generation;
    QMutexLocker lock(&m_mailbox->mutex);
    m_mailbox->receiver = this;
    return {};
}

void BuildThread::stop()
{
    if (!m_worker)
        return;
    BuildWorker *worker = m_worker;
    QThread *gui = thread();
    m_worker = nullptr;
    {
        QMutexLocker lock(&m_mailbox->mutex);
        m_mailbox->receiver = nullptr;
    }
    // Queued behind any build still waiting, which then runs to completion;
    // its reply is dropped because this object no longer has a worker.
    QMetaObject::invokeMethod(
        worker,
        [worker, gui] {
            worker->shutdown(gui);
            QThread::currentThread()->quit();
        },
        Qt::QueuedConnection);
    if (!m_thread->wait(kJoinTimeoutMs)) {
        // Stuck in the driver (an endless loop in a shader). Joining would
        // hang the GUI and deleting a running QThread aborts, so leave the
        // thread, its context and surface to the process exit.
        qWarning("phonglab: the shader build thread did not stop (a shader that never finishes?); "
                 "leaving it running");
        (void)m_thread.release();
        (void)m_context.release();
        (void)m_surface.release();
        (void)m_lentSurface.release();
        return;
    }
    m_thread.reset();
    m_context.reset(); // moved back to this thread by shutdown()
    m_surface.reset();
    m_lentSurface.reset();
}

quint64 BuildThread::build(const ShaderSource &vertex, const ShaderSource &fragment,
                           int warmSamples, const ExplicitBindings &bindings,
                           const CourseOptions &course)
{
    BuildJob request{++m_lastSerial, vertex, fragment, m_warmUp, warmSamples, bindings, course};
    if (!m_worker)
        return request.serial;
    const qint64 queuedAt = monotonicNs();
    BuildWorker *worker = m_worker;
    QMetaObject::invokeMethod(
        worker,
        [mailbox = m_mailbox, worker, request, queuedAt, generation = m_generation] {
            BuildReply reply = worker->build(request);
            reply.timings.queuedAtNs = queuedAt;
            reply.timings.finishedAtNs = monotonicNs();
            QMutexLocker lock(&mailbox->mutex);
            // When stopping (no receiver) the reply ends here, with the
            // worker's context current, and frees its program.
            if (BuildThread *receiver = mailbox->receiver)
                QMetaObject::invokeMethod(
                    receiver,
                    [receiver, reply = std::move(reply), generation]() mutable {
                        receiver->deliver(std::move(reply), generation);
                    },
                    Qt::QueuedConnection);
        },
        Qt::QueuedConnection);
    return request.serial;
}

void BuildThread::deliver(BuildReply reply, quint64 generation)
{
    // Posted just before a stop(): the reply goes here, and its program is
    // freed if a context of its group is current on this thread, else left
    // to that group (possibly gone with the viewport's old context).
    if (!m_worker || generation != m_generation || !m_receiver)
        return;
    m_receiver(std::move(reply));
}

void BuildThread::warmInLentContext(const LentContext &lent, GLuint program, WarmDone done)
{
    if (!m_worker) {
        done(fail(BuildThread::tr("the build thread is not running")));
        return;
    }
    BuildWorker *worker = m_worker;
    QOffscreenSurface *surface = m_lentSurface.get();
    QThread *owner = thread();
    QMetaObject::invokeMethod(
        worker,
        [mailbox = m_mailbox, worker, lent, surface, program, owner, done] {
            const Result<qint64> warmed = worker->warmInLentContext(lent, surface, program, owner);
            lent.returned->release(); // the context is back on the owner's thread
            QMutexLocker lock(&mailbox->mutex);
            if (BuildThread *receiver = mailbox->receiver)
                QMetaObject::invokeMethod(
                    receiver, [done, warmed] { done(warmed); }, Qt::QueuedConnection);
        },
        Qt::QueuedConnection);
}

void BuildThread::release(GlProgram program)
{
    if (!m_worker || !program)
        return; // left to the share group
    QMetaObject::invokeMethod(
        m_worker, [program = std::move(program)]() mutable { program.reset(); },
        Qt::QueuedConnection);
}

} // namespace phonglab
