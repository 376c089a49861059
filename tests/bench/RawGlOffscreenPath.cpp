// Plain GL entry points, as a program without Qt's wrappers calls them.
#define GL_GLEXT_PROTOTYPES 1

#include "RawGlOffscreenPath.h"

#include "RawGlCalls.h"
#include "core/ResourcePaths.h"

#include <QElapsedTimer>
#include <QFile>
#include <algorithm>
#include <cstdio>
#include <vector>

namespace phonglab::bench {

namespace {

QByteArray readShader(const char *name)
{
    QFile file(shaderPath(QString::fromLatin1(name)));
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

} // namespace

RawGlOffscreenPath::~RawGlOffscreenPath()
{
    deleteMesh();
    deleteTarget();
    if (m_program)
        glDeleteProgram(m_program);
}

bool RawGlOffscreenPath::create()
{
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
    if (!linked)
        std::fprintf(stderr, "raw GL: the shipped Phong program does not link\n");
    return linked == GL_TRUE;
}

void RawGlOffscreenPath::setMesh(const MeshData &mesh, const Scene &scene)
{
    deleteMesh();
    m_scene = scene;
    std::vector<float> interleaved;
    interleaved.reserve(mesh.positions.size() * 6);
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
        interleaved.insert(interleaved.end(),
                           {mesh.positions[i].x, mesh.positions[i].y, mesh.positions[i].z,
                            mesh.normals[i].x, mesh.normals[i].y, mesh.normals[i].z});
    glGenVertexArrays(1, &m_vao);
    glBindVertexArray(m_vao);
    glGenBuffers(1, &m_vbo);
    glBindBuffer(GL_ARRAY_BUFFER, m_vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(interleaved.size() * sizeof(float)),
                 interleaved.data(), GL_STATIC_DRAW);
    glGenBuffers(1, &m_ibo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_ibo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * 4), mesh.indices.data(),
                 GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 24, nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 24, reinterpret_cast<void *>(12));
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    m_indexCount = GLsizei(mesh.indices.size());
}

// The target QOpenGLFramebufferObject makes for OffscreenRenderer (an RGBA8
// texture and, for its Depth attachment on desktop GL, an unsized
// GL_DEPTH_COMPONENT renderbuffer), remade only when the size changes.
void RawGlOffscreenPath::bindTarget(const QSize &size)
{
    if (m_fbo && size == m_size) {
        glBindFramebuffer(GL_FRAMEBUFFER, m_fbo);
        return;
    }
    deleteTarget();
    m_size = size;
    glGenTextures(1, &m_color);
    glBindTexture(GL_TEXTURE_2D, m_color);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, size.width(), size.height(), 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, nullptr);
    glBindTexture(GL_TEXTURE_2D, 0);
    glGenRenderbuffers(1, &m_depth);
    glBindRenderbuffer(GL_RENDERBUFFER, m_depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT, size.width(), size.height());
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glGenFramebuffers(1, &m_fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, m_fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m_color, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, m_depth);
}

void RawGlOffscreenPath::drawFrame()
{
    glViewport(0, 0, m_size.width(), m_size.height());
    const glm::dvec3 bg = m_scene.background;
    glClearColor(float(bg.r), float(bg.g), float(bg.b), 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glEnable(GL_CULL_FACE); // the sphere is closed: back faces go, as the renderer culls them
    glCullFace(GL_BACK);
    glUseProgram(m_program);
    setPhongUniforms(m_program, m_scene, m_scene.objects.front(), m_size);
    glBindVertexArray(m_vao);
    glDrawElements(GL_TRIANGLES, m_indexCount, GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
}

double RawGlOffscreenPath::timeFrames(const QSize &size, int warmup, int frames)
{
    bindTarget(size);
    for (int i = 0; i < warmup; ++i) {
        drawFrame();
        glFinish();
    }
    std::vector<double> wall;
    for (int i = 0; i < frames; ++i) {
        QElapsedTimer timer;
        timer.start();
        drawFrame();
        glFinish();
        wall.push_back(double(timer.nsecsElapsed()) / 1e6);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    std::sort(wall.begin(), wall.end());
    return wall.empty() ? 0.0 : wall[wall.size() / 2];
}

double RawGlOffscreenPath::coveredShare(const QSize &size)
{
    bindTarget(size);
    drawFrame();
    std::vector<std::uint32_t> pixels(std::size_t(size.width()) * std::size_t(size.height()));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, size.width(), size.height(), GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    // The corner is background at this camera (as PhongLab's check assumes).
    const std::uint32_t background = pixels.front();
    const auto covered = std::count_if(pixels.begin(), pixels.end(),
                                       [background](std::uint32_t p) { return p != background; });
    return double(covered) / double(pixels.size());
}

void RawGlOffscreenPath::deleteMesh()
{
    if (m_vao)
        glDeleteVertexArrays(1, &m_vao);
    const GLuint buffers[] = {m_vbo, m_ibo};
    if (m_vbo || m_ibo)
        glDeleteBuffers(2, buffers);
    m_vao = m_vbo = m_ibo = 0;
}

void RawGlOffscreenPath::deleteTarget()
{
    if (m_fbo)
        glDeleteFramebuffers(1, &m_fbo);
    if (m_color)
        glDeleteTextures(1, &m_color);
    if (m_depth)
        glDeleteRenderbuffers(1, &m_depth);
    m_fbo = m_color = m_depth = 0;
}

} // namespace phonglab::bench
