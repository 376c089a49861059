// Edit-to-pixel latency of live shader editing (prints figures; not a test).
//
//   xvfb-run -a build/tests/bench/bench_edit_latency [--edits N] [--samples S]
//
// Each edit changes a constant in the Phong fragment shader (so every text is
// new), starts the build as the debounce would (LiveShaderController::
// buildNow) and stops the clock when the viewport has finished (glFinish) its
// first frame with the new program. Compared with a raw-GL path in the same
// process: glCreateShader/glCompileShader/glLinkProgram and one draw of the
// same mesh with the same uniforms, no Qt wrappers. While each edit runs, a
// 1 ms timer on the GUI thread records the longest gap between its ticks:
// how long typing would have frozen. Mesa's shader cache is disabled so that
// every build pays the full price, as a new text does.
#define GL_GLEXT_PROTOTYPES 1

#include "core/ObjectMatrices.h"
#include "core/ResourcePaths.h"
#include "core/SceneJson.h"
#include "mesh/SceneMeshes.h"
#include "render/GlFormat.h"
#include "ui/LiveShaderController.h"
#include "ui/MainWindow.h"
#include "ui/ShaderDock.h"
#include "ui/ShaderEditor.h"
#include "ui/ShaderFileSet.h"
#include "ui/Viewport.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <cstdio>
#include <glm/gtc/type_ptr.hpp>
#include <memory>

using namespace phonglab;

namespace {

struct Sample {
    double totalMs = 0, compileMs = 0, linkMs = 0, warmMs = 0, handoverMs = 0, frameMs = 0, stallMs = 0;
};

double ms(qint64 ns) { return double(ns) / 1e6; }

double percentile(std::vector<double> v, double p)
{
    if (v.empty())
        return 0.0;
    std::sort(v.begin(), v.end());
    const std::size_t rank = std::min(v.size() - 1, std::size_t(std::ceil(p * double(v.size()))) - (p > 0 ? 1 : 0));
    return v[rank];
}

// The shipped Phong fragment shader with its output scaled by `k`.
QByteArray editedFragment(double k)
{
    QFile file(shaderPath(QStringLiteral("phong.frag")));
    file.open(QIODevice::ReadOnly);
    QByteArray text = file.readAll();
    text.replace("fragColor = vec4(clamp(I, 0.0, 1.0), 1.0);",
                 "fragColor = vec4(clamp(I * " + QByteArray::number(k, 'f', 6) + ", 0.0, 1.0), 1.0);");
    return text;
}

QByteArray shippedText(const QString &name)
{
    QFile file(shaderPath(name));
    file.open(QIODevice::ReadOnly);
    return file.readAll();
}

// ---- the raw-GL baseline: plain GL calls on a context of its own --------

class RawGlPath
{
public:
    bool create(const QSize &size, int samples, const Scene &scene, const MeshData &mesh);
    Sample edit(const QByteArray &fragment);
    ~RawGlPath();

private:
    GLuint compile(GLenum type, const QByteArray &text);
    void setUniforms(GLuint program);

    QOpenGLContext m_context;
    QOffscreenSurface m_surface;
    QSize m_size;
    Scene m_scene;
    QByteArray m_vertex = shippedText(QStringLiteral("phong.vert"));
    GLuint m_fbo = 0, m_color = 0, m_depth = 0, m_vao = 0, m_vbo = 0, m_ibo = 0;
    GLsizei m_indexCount = 0;
};

bool RawGlPath::create(const QSize &size, int samples, const Scene &scene, const MeshData &mesh)
{
    m_context.setFormat(phonglabSurfaceFormat(0));
    m_surface.setFormat(m_context.format());
    m_surface.create();
    if (!m_context.create() || !m_context.makeCurrent(&m_surface))
        return false;
    m_size = size;
    m_scene = scene;
    // The viewport's target: RGBA8 + depth-stencil, same size and samples.
    glGenRenderbuffers(1, &m_color);
    glBindRenderbuffer(GL_RENDERBUFFER, m_color);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, size.width(), size.height());
    glGenRenderbuffers(1, &m_depth);
    glBindRenderbuffer(GL_RENDERBUFFER, m_depth);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH24_STENCIL8, size.width(), size.height());
    glGenFramebuffers(1, &m_fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, m_fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, m_color);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, m_depth);

    std::vector<float> interleaved;
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
        interleaved.insert(interleaved.end(), {mesh.positions[i].x, mesh.positions[i].y, mesh.positions[i].z,
                                               mesh.normals[i].x, mesh.normals[i].y, mesh.normals[i].z});
    glGenVertexArrays(1, &m_vao);
    glBindVertexArray(m_vao);
    glGenBuffers(1, &m_vbo);
    glBindBuffer(GL_ARRAY_BUFFER, m_vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(interleaved.size() * sizeof(float)), interleaved.data(), GL_STATIC_DRAW);
    glGenBuffers(1, &m_ibo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_ibo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * 4), mesh.indices.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 24, nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 24, reinterpret_cast<void *>(12));
    m_indexCount = GLsizei(mesh.indices.size());
    return glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
}

RawGlPath::~RawGlPath()
{
    if (!m_context.makeCurrent(&m_surface))
        return;
    glDeleteVertexArrays(1, &m_vao);
    GLuint buffers[] = {m_vbo, m_ibo};
    glDeleteBuffers(2, buffers);
    glDeleteFramebuffers(1, &m_fbo);
    GLuint renderbuffers[] = {m_color, m_depth};
    glDeleteRenderbuffers(2, renderbuffers);
    m_context.doneCurrent();
}

GLuint RawGlPath::compile(GLenum type, const QByteArray &text)
{
    const GLuint shader = glCreateShader(type);
    const char *source = text.constData();
    const GLint length = GLint(text.size());
    glShaderSource(shader, 1, &source, &length);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    return ok ? shader : 0;
}

void RawGlPath::setUniforms(GLuint p)
{
    const auto at = [p](const char *name) { return glGetUniformLocation(p, name); };
    const double aspect = double(m_size.width()) / m_size.height();
    const glm::dmat4 view = m_scene.camera.viewMatrix();
    const glm::dmat4 projection = m_scene.camera.projectionMatrix(aspect);
    const SceneObject &object = m_scene.objects.front();
    const ObjectMatrices m = ObjectMatrices::make(object.transform.matrix(), view, projection);
    glUniformMatrix4fv(at("viewMatrix"), 1, GL_FALSE, glm::value_ptr(glm::mat4(view)));
    glUniformMatrix4fv(at("projectionMatrix"), 1, GL_FALSE, glm::value_ptr(glm::mat4(projection)));
    glUniformMatrix4fv(at("modelViewMatrix"), 1, GL_FALSE, glm::value_ptr(glm::mat4(m.modelView)));
    glUniformMatrix3fv(at("normalMatrix"), 1, GL_FALSE, glm::value_ptr(glm::mat3(m.normalMatrix)));
    glUniform3fv(at("Ia"), 1, glm::value_ptr(glm::vec3(m_scene.ambient)));
    glUniform3fv(at("ka"), 1, glm::value_ptr(glm::vec3(object.material.ka)));
    glUniform3fv(at("kd"), 1, glm::value_ptr(glm::vec3(object.material.kd)));
    glUniform3fv(at("ks"), 1, glm::value_ptr(glm::vec3(object.material.ks)));
    glUniform1f(at("shininess"), float(object.material.shininess));
    const int count = std::min<int>(int(m_scene.lights.size()), kMaxLights);
    glUniform1i(at("lightCount"), count);
    for (int i = 0; i < count; ++i) {
        const PointLight &l = m_scene.lights[i];
        const auto element = [&](const char *name) { return at(QByteArray(name).append('[').append(QByteArray::number(i)).append(']')); };
        glUniform3fv(element("lightPosition"), 1, glm::value_ptr(glm::vec3(l.position)));
        glUniform3fv(element("Id"), 1, glm::value_ptr(glm::vec3(l.diffuse)));
        glUniform3fv(element("Is"), 1, glm::value_ptr(glm::vec3(l.specular)));
        glUniform3fv(element("attenuation"), 1, glm::value_ptr(glm::vec3(l.attenuation)));
    }
}

Sample RawGlPath::edit(const QByteArray &fragment)
{
    m_context.makeCurrent(&m_surface);
    Sample s;
    QElapsedTimer total, step;
    total.start();
    step.start();
    const GLuint vs = compile(GL_VERTEX_SHADER, m_vertex);
    const GLuint fs = compile(GL_FRAGMENT_SHADER, fragment);
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
    glBindFramebuffer(GL_FRAMEBUFFER, m_fbo);
    glViewport(0, 0, m_size.width(), m_size.height());
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glUseProgram(program);
    setUniforms(program);
    glBindVertexArray(m_vao);
    glDrawElements(GL_TRIANGLES, m_indexCount, GL_UNSIGNED_INT, nullptr);
    glFinish();
    s.frameMs = ms(step.nsecsElapsed());
    s.totalMs = ms(total.nsecsElapsed());
    s.stallMs = s.totalMs; // it all happens on the calling thread
    glUseProgram(0);
    glDeleteProgram(program);
    if (!linked)
        std::fprintf(stderr, "raw GL: the edited shader did not link\n");
    return s;
}

// ---- PhongLab's path: the real window, dock, controller and viewport ------

class PhongLabPath
{
public:
    PhongLabPath(const Scene &scene, const QSize &size, bool guiThread, bool warmUp);
    bool isReady() const { return m_ready; }
    bool buildsOnWorker() const { return m_window->liveShaders()->buildsOnWorker(); }
    QSize viewportPixels() const { return m_window->viewport()->size() * m_window->viewport()->devicePixelRatioF(); }
    Sample edit(const QByteArray &fragment);

private:
    std::unique_ptr<MainWindow> m_window;
    bool m_ready = false;
};

PhongLabPath::PhongLabPath(const Scene &scene, const QSize &size, bool guiThread, bool warmUp)
{
    if (guiThread)
        qputenv("PHONGLAB_COMPILE_ON_GUI_THREAD", "1");
    else
        qunsetenv("PHONGLAB_COMPILE_ON_GUI_THREAD");
    m_window = std::make_unique<MainWindow>();
    m_window->liveShaders()->setWarmUp(warmUp);
    QString error;
    if (!m_window->viewport()->setScene(scene, &error)) {
        std::fprintf(stderr, "cannot show the scene: %s\n", qPrintable(error));
        return;
    }
    m_window->viewport()->setShowLightMarkers(false); // the same single draw as the raw path
    m_window->viewport()->setFixedSize(size); // the raw path's framebuffer size
    m_window->show();
    QElapsedTimer wait;
    wait.start();
    while (m_window->viewport()->framesRendered() == 0 && wait.elapsed() < 10000)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
    m_ready = m_window->viewport()->framesRendered() > 0;
}

Sample PhongLabPath::edit(const QByteArray &fragment)
{
    LiveShaderController *live = m_window->liveShaders();
    Viewport *viewport = m_window->viewport();
    m_window->shaderDock()->editor(ShaderStage::Fragment)->setText(QString::fromUtf8(fragment));

    QEventLoop loop;
    QElapsedTimer clock;
    qint64 appliedAt = -1, frameAt = -1, lastTick = 0, maxGap = 0;
    ProgramBuildReply timings;
    qint64 handoverNs = 0;
    QTimer ticker;
    ticker.setTimerType(Qt::PreciseTimer);
    ticker.setInterval(1);
    QObject::connect(&ticker, &QTimer::timeout, [&] {
        const qint64 now = clock.nsecsElapsed();
        maxGap = std::max(maxGap, now - lastTick);
        lastTick = now;
    });
    auto applied = QObject::connect(live, &LiveShaderController::programApplied,
                                    [&](const QByteArray &, const ProgramBuildReply &reply) {
        appliedAt = clock.nsecsElapsed();
        timings = reply;
        if (reply.finishedAtNs > 0)
            handoverNs = std::chrono::duration_cast<std::chrono::nanoseconds>(
                             std::chrono::steady_clock::now().time_since_epoch()).count() - reply.finishedAtNs;
    });
    auto framed = QObject::connect(viewport, &Viewport::frameRendered, [&] {
        if (appliedAt >= 0 && frameAt < 0) {
            frameAt = clock.nsecsElapsed();
            loop.quit();
        }
    });
    QTimer::singleShot(20000, &loop, &QEventLoop::quit); // a build that never comes back
    clock.start();
    ticker.start();
    live->buildNow(); // where the debounce would fire
    if (frameAt < 0)
        loop.exec();
    QObject::disconnect(applied);
    QObject::disconnect(framed);
    Sample s;
    if (frameAt < 0) {
        std::fprintf(stderr, "an edit never reached the screen\n");
        return s;
    }
    maxGap = std::max(maxGap, frameAt - lastTick); // the stretch ending in the frame itself
    s.totalMs = ms(frameAt);
    s.compileMs = ms(timings.compileNs);
    s.linkMs = ms(timings.linkNs);
    s.warmMs = ms(timings.warmNs);
    s.handoverMs = ms(handoverNs);
    s.frameMs = ms(frameAt - appliedAt);
    s.stallMs = ms(maxGap);
    return s;
}

struct Row {
    QString name;
    std::vector<Sample> samples;
};

double column(const std::vector<Sample> &samples, double Sample::*field, double p)
{
    std::vector<double> values;
    for (const Sample &s : samples)
        values.push_back(s.*field);
    return percentile(values, p);
}

void printTable(const std::vector<Row> &rows)
{
    std::printf("\n| path | edit→pixel median | p95 | compile | link | warm-up draw (worker) | hand-over + adopt "
                "| first frame (GUI) | longest GUI stall median | p95 |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
    for (const Row &row : rows) {
        const auto &v = row.samples;
        std::printf("| %s | %.1f ms | %.1f ms | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f ms | %.1f ms |\n",
                    qPrintable(row.name), column(v, &Sample::totalMs, 0.5), column(v, &Sample::totalMs, 0.95),
                    column(v, &Sample::compileMs, 0.5), column(v, &Sample::linkMs, 0.5),
                    column(v, &Sample::warmMs, 0.5), column(v, &Sample::handoverMs, 0.5),
                    column(v, &Sample::frameMs, 0.5), column(v, &Sample::stallMs, 0.5),
                    column(v, &Sample::stallMs, 0.95));
    }
    const double raw = column(rows.front().samples, &Sample::totalMs, 0.5);
    std::printf("\n");
    for (std::size_t i = 1; i < rows.size(); ++i)
        std::printf("%s / raw GL (medians): %.2fx\n", qPrintable(rows[i].name),
                    column(rows[i].samples, &Sample::totalMs, 0.5) / raw);
}

} // namespace

int main(int argc, char **argv)
{
    // Every edit is a new text; a cached shader would hide the cost measured.
    qputenv("MESA_SHADER_CACHE_DISABLE", "true");
    QTemporaryDir recovery;
    qputenv("PHONGLAB_RECOVERY_DIR", recovery.path().toUtf8());
    QApplication app(argc, argv);
    QStandardPaths::setTestModeEnabled(true); // user copies of the shaders go to a test folder
    QCommandLineParser parser;
    parser.addHelpOption();
    parser.addOption({QStringLiteral("edits"), QStringLiteral("Edits per path (default 50)."), QStringLiteral("N"), QStringLiteral("50")});
    parser.addOption({QStringLiteral("samples"), QStringLiteral("MSAA samples of the viewport (default 4, as the app)."),
                      QStringLiteral("S"), QStringLiteral("4")});
    parser.process(app);
    const int edits = std::max(1, parser.value(QStringLiteral("edits")).toInt());
    const int samples = std::max(0, parser.value(QStringLiteral("samples")).toInt());
    QSurfaceFormat::setDefaultFormat(phonglabSurfaceFormat(samples));

    // The default scene's tree alone: one mesh, one draw.
    SceneLoadResult loaded = loadSceneFile(defaultScenePath());
    if (!loaded.ok()) {
        std::fprintf(stderr, "%s\n", qPrintable(loaded.error));
        return 1;
    }
    Scene scene = *loaded.scene;
    scene.objects.resize(1);
    SceneMeshes meshes = loadSceneMeshes(scene);
    const auto mesh = meshes.entries.value(meshKey(scene, scene.objects.front())).mesh;
    const QSize size(800, 600);

    constexpr int kWarmUpEdits = 3;
    int serial = 0;
    const auto run = [&](const QString &name, const std::function<Sample(const QByteArray &)> &edit) {
        Row row{name, {}};
        for (int i = 0; i < kWarmUpEdits + edits; ++i) {
            const Sample s = edit(editedFragment(0.5 + 0.0001 * ++serial));
            if (i >= kWarmUpEdits)
                row.samples.push_back(s);
        }
        return row;
    };

    std::vector<Row> rows;
    {
        RawGlPath raw;
        if (!mesh || !raw.create(size, samples, scene, *mesh)) {
            std::fprintf(stderr, "cannot set up the raw GL path\n");
            return 1;
        }
        rows.push_back(run(QStringLiteral("raw GL (no Qt)"), [&](const QByteArray &f) { return raw.edit(f); }));
    }
    struct Mode { QString name; bool guiThread; bool warmUp; };
    const Mode modes[] = {{QStringLiteral("PhongLab, worker + warm-up draw"), false, true},
                          {QStringLiteral("PhongLab, worker, no warm-up"), false, false},
                          {QStringLiteral("PhongLab, GUI thread"), true, false}};
    for (const Mode &mode : modes) {
        PhongLabPath path(scene, size, mode.guiThread, mode.warmUp);
        if (!path.isReady() || path.buildsOnWorker() == mode.guiThread) {
            std::fprintf(stderr, "%s: could not start\n", qPrintable(mode.name));
            return 1;
        }
        if (rows.size() == 1)
            std::printf("viewport %dx%d px, %d samples, %d edits per path (+%d warm-up)\n",
                        path.viewportPixels().width(), path.viewportPixels().height(), samples, edits, kWarmUpEdits);
        rows.push_back(run(mode.name, [&](const QByteArray &f) { return path.edit(f); }));
    }
    printTable(rows);
    QDir(ShaderFileSet::userFolder()).removeRecursively();
    return 0;
}
