// Plain GL entry points, as a program without Qt's wrappers calls them.
#define GL_GLEXT_PROTOTYPES 1

#include "RawGlEditPath.h"

#include "RawGlCalls.h"

#include "core/scene/ResourcePaths.h"
#include "render/gl/GlFormat.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <cstdio>

namespace phonglab::bench {

bool RawGlEditPath::create(const QSize &size, int samples, const Scene &scene, const MeshData &mesh)
{
    m_vertex = readShippedShader("phong.vert");
    if (m_vertex.isEmpty())
        return false;
    QSurfaceFormat format = phonglabSurfaceFormat(samples);
    format.setSwapInterval(0);
    m_window.setSurfaceType(QSurface::OpenGLSurface);
    m_window.setFormat(format);
    m_window.setTitle(QStringLiteral("raw GL edits"));
    m_window.resize(size / m_window.devicePixelRatio());
    m_window.show();
    QElapsedTimer wait;
    wait.start();
    while (!m_window.isExposed() && wait.elapsed() < 5000)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
    m_context.setFormat(format);
    if (!m_window.isExposed() || !m_context.create() || !m_context.makeCurrent(&m_window))
        return false;
    GLint gotSamples = 0;
    glGetIntegerv(GL_SAMPLES, &gotSamples);
    if (gotSamples != samples) {
        std::fprintf(stderr, "raw GL: the window has %d samples, not %d\n", gotSamples, samples);
        return false;
    }
    m_size = size;
    m_scene = scene;

    m_mesh = uploadMesh(mesh);
    return true;
}

RawGlEditPath::~RawGlEditPath()
{
    if (!m_context.isValid() || !m_context.makeCurrent(&m_window))
        return;
    deleteMesh(m_mesh);
    m_context.doneCurrent();
}

EditSample RawGlEditPath::edit(const QByteArray &fragment)
{
    m_context.makeCurrent(&m_window);
    EditSample s;
    QElapsedTimer total, step;
    total.start();
    step.start();
    const GLuint vs = compileShader(GL_VERTEX_SHADER, m_vertex);
    const GLuint fs = compileShader(GL_FRAGMENT_SHADER, fragment);
    s.compileMs = ms(step.nsecsElapsed());
    step.restart();
    const GLuint program = glCreateProgram();
    glAttachShader(program, vs);
    glAttachShader(program, fs);
    glLinkProgram(program);
    GLint linked = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    glDeleteShader(vs);
    glDeleteShader(fs);
    s.linkMs = ms(step.nsecsElapsed());
    step.restart();
    glBindFramebuffer(GL_FRAMEBUFFER, m_context.defaultFramebufferObject());
    glViewport(0, 0, m_size.width(), m_size.height());
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glUseProgram(program);
    setPhongUniforms(program, m_scene, m_scene.objects.front(), m_size);
    glBindVertexArray(m_mesh.vao);
    glDrawElements(GL_TRIANGLES, m_mesh.indexCount, GL_UNSIGNED_INT, nullptr);
    glFinish(); // as the viewport: the frame done, then shown
    m_context.swapBuffers(&m_window);
    s.frameMs = ms(step.nsecsElapsed());
    s.totalMs = ms(total.nsecsElapsed());
    s.stallMs = s.totalMs;             // it all happens on the calling thread
    s.stallUntilCheckedMs = s.stallMs; // and there is no check
    step.restart();
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDrawElements(GL_TRIANGLES, m_mesh.indexCount, GL_UNSIGNED_INT, nullptr);
    m_context.swapBuffers(&m_window);
    s.steadyMs = ms(step.nsecsElapsed());
    glUseProgram(0);
    glDeleteProgram(program);
    if (!linked)
        std::fprintf(stderr, "raw GL: the edited shader did not link\n");
    return s;
}

} // namespace phonglab::bench
