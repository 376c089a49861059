#pragma once
#include "ProgramBuilder.h"
#include "WarmUpDraw.h"
#include "core/support/Result.h"
#include "render/gl/LentContext.h"

#include <QObject>

class QOffscreenSurface;
class QOpenGLContext;

namespace phonglab {

struct BuildJob {
    quint64 serial = 0;
    ShaderSource vertex;
    ShaderSource fragment;
    bool warm = true;          // run one draw before handing the program over
    int warmSamples = 0;       // ... into a framebuffer with this many samples
    ExplicitBindings bindings; // the scene's: they place the vertex inputs at link time
    CourseOptions course;      // the scene's: what the course's page adds at compile time
};

// Where a build's time went, carried to the status bar and the benchmarks.
struct BuildTimings {
    qint64 compileNs = 0;
    qint64 linkNs = 0;
    qint64 warmNs = 0;
    qint64 queuedAtNs = 0;   // request posted (monotonic clock, ns)
    qint64 finishedAtNs = 0; // program linked, warmed and finished
};

// A finished build: move-only, because it carries the program (empty on
// failure), which lives in the share group and belongs to whoever holds the
// reply: adopt it, or let the reply go on a thread with a context of the
// group current (BuildThread::release from the GUI thread).
struct BuildReply {
    quint64 serial = 0;
    GlProgram program;
    BuildReport report;
    BuildTimings timings;
};

// The half of BuildThread that lives on the worker thread:
// every member runs there, with the worker's context current from
// initialize() to shutdown() (but for the time a lent context is).
class BuildWorker : public QObject
{
    Q_OBJECT

public:
    BuildWorker(QOpenGLContext *context, QOffscreenSurface *surface);

    Result<> initialize();
    BuildReply build(const BuildJob &request);
    // Makes a context lent to this thread (see LentContext) current on
    // `surface`, runs lent.whileCurrent, draws `program` once, then hands the
    // context back to `owner` and makes the worker's own context current
    // again. The nanoseconds it took, or why the lent context could not be
    // used.
    Result<qint64> warmInLentContext(const LentContext &lent, QOffscreenSurface *surface,
                                     GLuint program, QThread *owner);
    // Frees the worker's GL objects, releases the context and hands it back
    // to `owner` (the GUI thread) so that it can be deleted there.
    void shutdown(QThread *owner);

    bool hasParallelShaderCompile() const { return m_parallelShaderCompile; }

private:
    QOpenGLContext *m_context = nullptr;
    QOffscreenSurface *m_surface = nullptr;
    int m_warmSamples = -1; // of m_warmer's framebuffer
    ProgramBuilder m_builder;
    WarmUpDraw m_warmer;
    bool m_parallelShaderCompile = false;
};

} // namespace phonglab
