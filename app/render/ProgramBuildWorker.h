#pragma once
#include "ProgramBuilder.h"
#include "ProgramWarmer.h"

#include <QObject>

class QOffscreenSurface;
class QOpenGLContext;

namespace phonglab {

struct ProgramBuildRequest {
    quint64 serial = 0;
    ShaderSource vertex;
    ShaderSource fragment;
    bool warm = true; // run one draw before handing the program over
};

// A finished build. `program` (0 on failure) lives in the share group and is
// owned by whoever receives the reply: adopt it or release it.
struct ProgramBuildReply {
    quint64 serial = 0;
    GLuint program = 0;
    CompileResult result;
    qint64 compileNs = 0;
    qint64 linkNs = 0;
    qint64 warmNs = 0;
    qint64 queuedAtNs = 0;   // request posted (monotonic clock, ns)
    qint64 finishedAtNs = 0; // program linked, warmed and finished
};

// The half of BackgroundProgramBuilder that lives on the worker thread:
// every member runs there, with the worker's context current from
// initialize() to shutdown().
class ProgramBuildWorker : public QObject
{
    Q_OBJECT

public:
    ProgramBuildWorker(QOpenGLContext *context, QOffscreenSurface *surface, int warmSamples);

    bool initialize(QString *error);
    ProgramBuildReply build(const ProgramBuildRequest &request);
    void release(GLuint program);
    // Frees the worker's GL objects, releases the context and hands it back
    // to `owner` (the GUI thread) so that it can be deleted there.
    void shutdown(QThread *owner);

    bool hasParallelShaderCompile() const { return m_parallelShaderCompile; }
    QString rendererName() const { return m_rendererName; }

private:
    QOpenGLContext *m_context = nullptr;
    QOffscreenSurface *m_surface = nullptr;
    int m_warmSamples = 0;
    ProgramBuilder m_builder;
    ProgramWarmer m_warmer;
    bool m_parallelShaderCompile = false;
    QString m_rendererName;
};

} // namespace phonglab
