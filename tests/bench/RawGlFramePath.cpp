// Plain GL entry points, as a program without Qt's wrappers calls them.
#define GL_GLEXT_PROTOTYPES 1

#include "RawGlFramePath.h"

#include "EditSample.h"
#include "RawGlCalls.h"
#include "core/ResourcePaths.h"
#include "render/GlFormat.h"

#include <QCoreApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFile>
#include <QPlainTextEdit>
#include <QStatusBar>
#include <cstdio>

namespace phonglab::bench {

namespace {

QByteArray readShader(const char *name)
{
    QFile file(shaderPath(QString::fromLatin1(name)));
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

} // namespace

bool RawGlFramePath::create(const QSize &size, int samples, const Scene &scene,
                            const SceneMeshes &meshes, Placement placement)
{
    QSurfaceFormat format = phonglabSurfaceFormat(samples);
    format.setSwapInterval(0); // as fast as it can present (bench_frame turns vsync off for both)
    m_ownWindow = std::make_unique<QWindow>();
    m_window = m_ownWindow.get();
    m_window->setSurfaceType(QSurface::OpenGLSurface);
    m_window->setFormat(format);
    const QSize logical = size / m_window->devicePixelRatio();
    if (placement == Placement::InsideMainWindow) {
        m_host = std::make_unique<QMainWindow>();
        QWidget *container = QWidget::createWindowContainer(m_ownWindow.release(), m_host.get());
        container->setFixedSize(logical);
        m_host->setCentralWidget(container);
        auto *dock = new QDockWidget(QStringLiteral("Shaders"), m_host.get());
        auto *editor = new QPlainTextEdit(dock);
        editor->setPlainText(QString::fromUtf8(readShader("phong.frag")));
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
    // The floor must resolve as many samples as the viewport does.
    GLint gotSamples = 0;
    glGetIntegerv(GL_SAMPLES, &gotSamples);
    if (gotSamples != samples) {
        std::fprintf(stderr, "raw GL: the window has %d samples, not %d\n", gotSamples, samples);
        return false;
    }
    m_scene = scene;
    m_size = size;
    const GLuint vs = compileShader(GL_VERTEX_SHADER, readShader("phong.vert"));
    const GLuint fs = compileShader(GL_FRAGMENT_SHADER, readShader("phong.frag"));
    m_program = glCreateProgram();
    glAttachShader(m_program, vs);
    glAttachShader(m_program, fs);
    glLinkProgram(m_program);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint linked = GL_FALSE;
    glGetProgramiv(m_program, GL_LINK_STATUS, &linked);
    if (!linked) {
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
        std::vector<float> interleaved;
        interleaved.reserve(mesh.positions.size() * 6);
        for (std::size_t i = 0; i < mesh.positions.size(); ++i)
            interleaved.insert(interleaved.end(),
                               {mesh.positions[i].x, mesh.positions[i].y, mesh.positions[i].z,
                                mesh.normals[i].x, mesh.normals[i].y, mesh.normals[i].z});
        Object o;
        glGenVertexArrays(1, &o.vao);
        glBindVertexArray(o.vao);
        glGenBuffers(1, &o.vbo);
        glBindBuffer(GL_ARRAY_BUFFER, o.vbo);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(interleaved.size() * sizeof(float)),
                     interleaved.data(), GL_STATIC_DRAW);
        glGenBuffers(1, &o.ibo);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, o.ibo);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * 4),
                     mesh.indices.data(), GL_STATIC_DRAW);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 24, nullptr);
        glEnableVertexAttribArray(1);
        glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 24, reinterpret_cast<void *>(12));
        o.indexCount = GLsizei(mesh.indices.size());
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
    for (const Object &o : m_objects) {
        glDeleteVertexArrays(1, &o.vao);
        const GLuint buffers[] = {o.vbo, o.ibo};
        glDeleteBuffers(2, buffers);
    }
    glDeleteProgram(m_program);
    m_context.doneCurrent();
}

double RawGlFramePath::drawFrame()
{
    QElapsedTimer clock;
    clock.start();
    m_context.makeCurrent(m_window);
    glBindFramebuffer(GL_FRAMEBUFFER, m_context.defaultFramebufferObject());
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
        glBindVertexArray(o.vao);
        glDrawElements(GL_TRIANGLES, o.indexCount, GL_UNSIGNED_INT, nullptr);
    }
    m_context.swapBuffers(m_window); // as the viewport's frame ends: no glFinish after
    return ms(clock.nsecsElapsed());
}

} // namespace phonglab::bench
