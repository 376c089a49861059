// Plain GL entry points, as a program without Qt's wrappers calls them.
#define GL_GLEXT_PROTOTYPES 1

#include "RawGlOffscreenPath.h"

#include "RawGlCalls.h"

#include <QElapsedTimer>
#include <algorithm>
#include <cstdio>

namespace phonglab::bench {

RawGlOffscreenPath::~RawGlOffscreenPath()
{
    deleteMesh(m_mesh);
    deleteTarget();
    if (m_program)
        glDeleteProgram(m_program);
}

bool RawGlOffscreenPath::create()
{
    m_program = linkProgram(readShippedShader("phong.vert"), readShippedShader("phong.frag"));
    if (!m_program)
        std::fprintf(stderr, "raw GL: the shipped Phong program does not link\n");
    return m_program != 0;
}

void RawGlOffscreenPath::setMesh(const MeshData &mesh, const Scene &scene)
{
    deleteMesh(m_mesh);
    m_scene = scene;
    m_mesh = uploadMesh(mesh);
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
    glBindVertexArray(m_mesh.vao);
    glDrawElements(GL_TRIANGLES, m_mesh.indexCount, GL_UNSIGNED_INT, nullptr);
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
