#pragma once
#include "BuildWorker.h"
#include "core/support/Result.h"

#include <QMutex>
#include <QObject>
#include <functional>
#include <memory>

class QOffscreenSurface;
class QOpenGLContext;
class QThread;

namespace phonglab {

// Builds lighting programs off the GUI thread. A worker QThread owns an
// OpenGL context created in the same share group as the viewport's, on a
// QOffscreenSurface (created here, on the GUI thread, as Qt requires). It
// compiles, links, warms the program with one small draw (WarmUpDraw) and
// glFinish()es; the GUI thread's receiver then gets the program, whose name
// means the same object in the viewport's context. Typing never waits on the
// driver: the GUI thread only adopts a finished program.
class BuildThread : public QObject
{
    Q_OBJECT

public:
    explicit BuildThread(QObject *parent = nullptr);
    ~BuildThread() override;

    // Creates the worker context sharing objects with `shareContext` (which
    // must exist) and starts the thread. A failure when no shared context
    // can be had.
    Result<> start(QOpenGLContext *shareContext);
    // Finishes the build in progress, frees the worker's GL objects and joins
    // the thread. Replies not delivered yet are dropped (their programs are
    // freed with the worker's context, or with the share group).
    void stop();
    bool isRunning() const { return m_worker != nullptr; }

    // Queues a build; returns its serial, which the reply carries.
    // `warmSamples`: the sample count of the framebuffer the program will
    // draw into, for the warm-up in the worker's context (setWarmUp).
    // `bindings`: the scene's explicit ones, which place vertex inputs;
    // `course`: the scene's, what the course's page adds to each stage.
    quint64 build(const ShaderSource &vertex, const ShaderSource &fragment, int warmSamples = 0,
                  const ExplicitBindings &bindings = {}, const CourseOptions &course = {});
    // Frees a program that was built here but will not be used, on the
    // worker thread (where a context of its group is current).
    void release(GlProgram program);

    // Draws `program` once in the viewport's own context, which the caller
    // has lent to workerThread(). The worker gives it back (moves it to this
    // thread, releases lent.returned); then `done` runs here with the
    // nanoseconds it took, or why it could not. Queued behind any build in
    // progress.
    using WarmDone = std::function<void(const Result<qint64> &warmNs)>;
    void warmInLentContext(const LentContext &lent, GLuint program, WarmDone done);
    QThread *workerThread() const { return m_thread.get(); }

    // Whether each build also draws once in the worker's own context before
    // handing the program over (helps drivers whose shader variants are
    // shared by the share group; not llvmpipe). Off by default: the app
    // warms in the viewport's lent context instead; bench_edit_latency
    // compares the two.
    void setWarmUp(bool warm) { m_warmUp = warm; }
    bool hasParallelShaderCompile() const { return m_parallelShaderCompile; }

    // Who gets each finished build, on the GUI thread, and owns its program
    // from then on. One receiver: the reply carries the program, which only
    // one holder can own.
    using Receiver = std::function<void(BuildReply reply)>;
    void setReceiver(Receiver receiver) { m_receiver = std::move(receiver); }

private:
    // Where the worker posts replies. Cleared under its mutex when this
    // object stops, so a worker that outlives it (stuck in the driver and
    // abandoned) never posts to a deleted object.
    struct Mailbox {
        QMutex mutex;
        BuildThread *receiver = nullptr;
    };

    void deliver(BuildReply reply, quint64 generation);

    std::shared_ptr<Mailbox> m_mailbox = std::make_shared<Mailbox>();
    Receiver m_receiver;

    std::unique_ptr<QThread> m_thread;
    std::unique_ptr<QOffscreenSurface> m_surface;
    std::unique_ptr<QOffscreenSurface> m_lentSurface; // in the viewport context's format
    std::unique_ptr<QOpenGLContext> m_context;
    BuildWorker *m_worker = nullptr; // lives on m_thread, deleted with it
    quint64 m_lastSerial = 0;
    quint64 m_generation = 0; // one per start(): a program belongs to its share group
    bool m_warmUp = false;
    bool m_parallelShaderCompile = false;
};

} // namespace phonglab
