// Plain GL entry points, as a program without Qt's wrappers calls them.
#define GL_GLEXT_PROTOTYPES 1

#include "RawGlEditPath.h"

#include "RawGlCalls.h"

#include "core/ResourcePaths.h"
#include "render/GlFormat.h"

#include <QElapsedTimer>
#include <QFile>
#include <cstdio>

namespace phonglab::bench {

bool RawGlEditPath::create(const QSize &size, int samples, const Scene &scene, const MeshData &mesh)
{
    QFile vertex(shaderPath(QStringLiteral("phong.vert")));
    if (!vertex.open(QIODevice::ReadOnly))
        return false;
    m_vertex = vertex.readAll();
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
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, size.width(),
                                     size.height());
    glGenRenderbuffers(1, &m_depth);
    glBindRenderbuffer(GL_RENDERBUFFER, m_depth);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH24_STENCIL8, size.width(),
                                     size.height());
    glGenFramebuffers(1, &m_fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, m_fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, m_color);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                              m_depth);

    std::vector<float> interleaved;
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
    m_indexCount = GLsizei(mesh.indices.size());
    return glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
}

RawGlEditPath::~RawGlEditPath()
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

EditSample RawGlEditPath::edit(const QByteArray &fragment)
{
    m_context.makeCurrent(&m_surface);
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
    glBindFramebuffer(GL_FRAMEBUFFER, m_fbo);
    glViewport(0, 0, m_size.width(), m_size.height());
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glUseProgram(program);
    setPhongUniforms(program, m_scene, m_scene.objects.front(), m_size);
    glBindVertexArray(m_vao);
    glDrawElements(GL_TRIANGLES, m_indexCount, GL_UNSIGNED_INT, nullptr);
    glFinish();
    s.frameMs = ms(step.nsecsElapsed());
    s.totalMs = ms(total.nsecsElapsed());
    s.stallMs = s.totalMs;             // it all happens on the calling thread
    s.stallUntilCheckedMs = s.stallMs; // and there is no check
    step.restart();
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDrawElements(GL_TRIANGLES, m_indexCount, GL_UNSIGNED_INT, nullptr);
    glFinish();
    s.steadyMs = ms(step.nsecsElapsed());
    glUseProgram(0);
    glDeleteProgram(program);
    if (!linked)
        std::fprintf(stderr, "raw GL: the edited shader did not link\n");
    return s;
}

} // namespace phonglab::bench
