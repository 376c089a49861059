// Plain GL entry points, as a program without Qt's wrappers calls them.
#define GL_GLEXT_PROTOTYPES 1

#include "RawGlFramePath.h"

#include "EditSample.h"
#include "RawGlCalls.h"
#include "core/scene/ResourcePaths.h"
#include "render/gl/GlFormat.h"

#include <QCoreApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFile>
#include <QPlainTextEdit>
#include <QStatusBar>
#include <cstdio>

namespace phonglab::bench {

bool RawGlFramePath::create(const QSize &size, int samples, const Scene &scene,
                            const SceneMeshes &meshes, Placement placement,
                            Presentation presentation, QSize windowSize)
{
    m_presentation = presentation;
    const bool direct = presentation == Presentation::Direct;
    m_windowSize = direct || windowSize.isEmpty() ? size : windowSize.expandedTo(size);
    // Composing: the window has no samples (as PhongLab's, useMultisamplingInViewOnly).
    QSurfaceFormat format = phonglabSurfaceFormat(direct ? samples : 0);
    format.setSwapInterval(0); // as fast as it can present (bench_frame turns vsync off for both)
    m_ownWindow = std::make_unique<QWindow>();
    m_window = m_ownWindow.get();
    m_window->setSurfaceType(QSurface::OpenGLSurface);
    m_window->setFormat(format);
    const QSize logical = m_windowSize / m_window->devicePixelRatio();
    if (placement == Placement::InsideMainWindow) {
        m_host = std::make_unique<QMainWindow>();
        QWidget *container = QWidget::createWindowContainer(m_ownWindow.release(), m_host.get());
        container->setFixedSize(logical);
        m_host->setCentralWidget(container);
        auto *dock = new QDockWidget(QStringLiteral("Shaders"), m_host.get());
        auto *editor = new QPlainTextEdit(dock);
        editor->setPlainText(QString::fromUtf8(readShippedShader("phong.frag")));
        dock->setWidget(editor);
        m_host->addDockWidget(Qt::RightDockWidgetArea, dock);
        m_host->statusBar()->showMessage(QStringLiteral("raw GL inside a main window"));
        m_host->show();
    } else {
        m_window->resize(logical);
        m_window->setTitle(QStringLiteral("raw GL floor"));
        m_window->show();
    }
    QElapsedTimer wait;
    wait.start();
    while (!m_window->isExposed() && wait.elapsed() < 5000)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
    m_context.setFormat(format);
    if (!m_window->isExposed() || !m_context.create() || !m_context.makeCurrent(m_window)) {
        std::fprintf(stderr, "raw GL: no window or context\n");
        return false;
    }
    m_scene = scene;
    m_size = size;
    if (!direct && !createComposition(samples))
        return false;
    // The floor must resolve as many samples as the viewport does.
    GLint gotSamples = 0;
    glBindFramebuffer(GL_FRAMEBUFFER, direct ? m_context.defaultFramebufferObject() : m_sampledFbo);
    glGetIntegerv(GL_SAMPLES, &gotSamples);
    if (gotSamples != samples) {
        std::fprintf(stderr, "raw GL: the target has %d samples, not %d\n", gotSamples, samples);
        return false;
    }
    m_program = linkProgram(readShippedShader("phong.vert"), readShippedShader("phong.frag"));
    if (!m_program) {
        std::fprintf(stderr, "raw GL: the shipped Phong program does not link\n");
        return false;
    }
    for (const SceneObject &object : scene.objects) {
        const SceneMeshes::Entry entry = meshes.entries.value(meshKey(scene, object));
        if (!entry.mesh) {
            std::fprintf(stderr, "raw GL: no mesh for %s\n", qPrintable(object.mesh));
            return false;
        }
        const MeshData &mesh = *entry.mesh;
        Object o;
        o.mesh = uploadMesh(mesh);
        o.cull = entry.stats.closed; // as the renderer: only closed surfaces hide back faces
        m_objects.push_back(o);
    }
    glBindVertexArray(0);
    return true;
}

RawGlFramePath::~RawGlFramePath()
{
    if (!m_window || !m_context.isValid() || !m_context.makeCurrent(m_window))
        return;
    for (Object &o : m_objects)
        deleteMesh(o.mesh);
    glDeleteProgram(m_program);
    const GLuint framebuffers[] = {m_sampledFbo, m_viewFbo};
    glDeleteFramebuffers(2, framebuffers);
    const GLuint renderbuffers[] = {m_sampledColor, m_sampledDepth};
    glDeleteRenderbuffers(2, renderbuffers);
    const GLuint textures[] = {m_viewTexture, m_layerTexture};
    glDeleteTextures(2, textures);
    glDeleteVertexArrays(1, &m_quadVao);
    glDeleteProgram(m_quadProgram);
    m_context.doneCurrent();
}

void RawGlFramePath::drawScene()
{
    const bool direct = m_presentation == Presentation::Direct;
    glBindFramebuffer(GL_FRAMEBUFFER, direct ? m_context.defaultFramebufferObject() : m_sampledFbo);
    glViewport(0, 0, m_size.width(), m_size.height());
    const glm::dvec3 bg = m_scene.background;
    glClearColor(float(bg.r), float(bg.g), float(bg.b), 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glUseProgram(m_program);
    for (std::size_t i = 0; i < m_objects.size(); ++i) {
        const Object &o = m_objects[i];
        if (o.cull)
            glEnable(GL_CULL_FACE);
        else
            glDisable(GL_CULL_FACE);
        setPhongUniforms(m_program, m_scene, m_scene.objects[i], m_size);
        glBindVertexArray(o.mesh.vao);
        glDrawElements(GL_TRIANGLES, o.mesh.indexCount, GL_UNSIGNED_INT, nullptr);
    }
}

double RawGlFramePath::drawFrame()
{
    QElapsedTimer clock;
    clock.start();
    m_context.makeCurrent(m_window);
    drawScene();
    if (m_presentation == Presentation::ThroughTexture) {
        resolve();
        uploadLayer();
        compose();
    }
    m_context.swapBuffers(m_window); // as the viewport's frame ends: no glFinish after
    return ms(clock.nsecsElapsed());
}

RawGlFramePath::Steps RawGlFramePath::drawTimedFrame()
{
    Steps steps;
    QElapsedTimer clock;
    m_context.makeCurrent(m_window);
    glFinish();
    const auto step = [&clock](double &into, auto &&work) {
        clock.start();
        work();
        glFinish();
        into = ms(clock.nsecsElapsed());
    };
    step(steps.draw, [this] { drawScene(); });
    if (m_presentation == Presentation::ThroughTexture) {
        step(steps.resolve, [this] { resolve(); });
        step(steps.upload, [this] { uploadLayer(); });
        step(steps.compose, [this] { compose(); });
    }
    step(steps.swap, [this] { m_context.swapBuffers(m_window); });
    return steps;
}

// QOpenGLWidget's framebuffer (samples, depth and stencil) and the texture
// its samples resolve into; the backing store's texture; a program that
// draws a texture into a rectangle of the window, as Qt's compositor does.
bool RawGlFramePath::createComposition(int samples)
{
    const int w = m_size.width(), h = m_size.height();
    glGenRenderbuffers(1, &m_sampledColor);
    glBindRenderbuffer(GL_RENDERBUFFER, m_sampledColor);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, w, h);
    glGenRenderbuffers(1, &m_sampledDepth);
    glBindRenderbuffer(GL_RENDERBUFFER, m_sampledDepth);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH24_STENCIL8, w, h);
    glGenFramebuffers(1, &m_sampledFbo);
    glBindFramebuffer(GL_FRAMEBUFFER, m_sampledFbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                              m_sampledColor);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                              m_sampledDepth);
    const bool sampledComplete =
        glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;

    const auto texture = [](GLuint &name, const QSize &size) {
        glGenTextures(1, &name);
        glBindTexture(GL_TEXTURE_2D, name);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, size.width(), size.height(), 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, nullptr);
    };
    texture(m_viewTexture, m_size);
    texture(m_layerTexture, m_windowSize);
    glGenFramebuffers(1, &m_viewFbo);
    glBindFramebuffer(GL_FRAMEBUFFER, m_viewFbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m_viewTexture, 0);
    const bool viewComplete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    m_layerPixels.assign(std::size_t(w) * h * 4, 0xe0); // the window's grey, opaque

    // A rectangle of the window from gl_VertexID, textured; no buffers.
    static const char *vertex = "#version 330 core\n"
                                "uniform vec4 rect; out vec2 uv;\n"
                                "void main() {\n"
                                "  uv = vec2(gl_VertexID & 1, gl_VertexID >> 1);\n"
                                "  gl_Position = vec4(rect.xy + uv * rect.zw, 0.0, 1.0);\n"
                                "}\n";
    static const char *fragment = "#version 330 core\n"
                                  "uniform sampler2D image; in vec2 uv; out vec4 color;\n"
                                  "void main() { color = texture(image, uv); }\n";
    m_quadProgram = linkProgram(vertex, fragment);
    glGenVertexArrays(1, &m_quadVao);
    glBindFramebuffer(GL_FRAMEBUFFER, m_context.defaultFramebufferObject());
    if (!sampledComplete || !viewComplete || !m_quadProgram) {
        std::fprintf(stderr, "raw GL: the composition's framebuffers or program failed\n");
        return false;
    }
    return true;
}

void RawGlFramePath::resolve()
{
    glBindFramebuffer(GL_READ_FRAMEBUFFER, m_sampledFbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, m_viewFbo);
    glBlitFramebuffer(0, 0, m_size.width(), m_size.height(), 0, 0, m_size.width(), m_size.height(),
                      GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

// The repaint of the view's region marks it dirty in the backing store,
// whose texture then takes that region again.
void RawGlFramePath::uploadLayer()
{
    glBindTexture(GL_TEXTURE_2D, m_layerTexture);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, m_size.width(), m_size.height(), GL_RGBA,
                    GL_UNSIGNED_BYTE, m_layerPixels.data());
}

void RawGlFramePath::compose()
{
    glBindFramebuffer(GL_FRAMEBUFFER, m_context.defaultFramebufferObject());
    glViewport(0, 0, m_windowSize.width(), m_windowSize.height());
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glUseProgram(m_quadProgram);
    glBindVertexArray(m_quadVao);
    const GLint rect = glGetUniformLocation(m_quadProgram, "rect");
    // The whole window's widgets, then the view in its top-left corner
    // (clip space: y up, so its rectangle starts at the top edge).
    glUniform4f(rect, -1.0f, -1.0f, 2.0f, 2.0f);
    glBindTexture(GL_TEXTURE_2D, m_layerTexture);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    const float w = 2.0f * float(m_size.width()) / float(m_windowSize.width());
    const float h = 2.0f * float(m_size.height()) / float(m_windowSize.height());
    glUniform4f(rect, -1.0f, 1.0f - h, w, h);
    glBindTexture(GL_TEXTURE_2D, m_viewTexture);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

} // namespace phonglab::bench
