#include "PageReplay.h"

#include "core/page/CaptureBounds.h"
#include "core/page/WebIdlNumbers.h"
#include "render/program/ProgramBuilder.h"

#include <QCoreApplication>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QOpenGLFramebufferObject>

#include <algorithm>
#include <map>

namespace phonglab {

struct PageReplayWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::PageReplay)
};

namespace {

constexpr GLenum kPrimitiveRestartFixedIndex = 0x8D69;

// The GL objects one replay makes, deleted with it.
class ReplayObjects
{
public:
    explicit ReplayObjects(QOpenGLExtraFunctions *gl)
        : m_gl(gl)
    {
        m_gl->glGenVertexArrays(1, &m_vao);
        m_gl->glBindVertexArray(m_vao);
    }
    ~ReplayObjects()
    {
        for (const auto &[key, name] : m_buffers)
            m_gl->glDeleteBuffers(1, &name);
        m_gl->glBindVertexArray(0);
        m_gl->glDeleteVertexArrays(1, &m_vao);
    }
    ReplayObjects(const ReplayObjects &) = delete;
    ReplayObjects &operator=(const ReplayObjects &) = delete;

    // The captured buffer `key` as a GL buffer bound to `target`.
    void bindBuffer(GLenum target, const QString &key, const PageCapture &capture)
    {
        auto it = m_buffers.find(key);
        if (it == m_buffers.end()) {
            GLuint name = 0;
            m_gl->glGenBuffers(1, &name);
            m_gl->glBindBuffer(target, name);
            const CapturedBuffer *buffer = capture.buffer(key);
            m_gl->glBufferData(target, buffer ? buffer->bytes.size() : 0,
                               buffer ? buffer->bytes.constData() : nullptr, GL_STATIC_DRAW);
            it = m_buffers.emplace(key, name).first;
        }
        m_gl->glBindBuffer(target, it->second);
    }

    std::map<int, BuiltProgram> programs;

private:
    QOpenGLExtraFunctions *m_gl;
    GLuint m_vao = 0;
    std::map<QString, GLuint> m_buffers;
};

void applyState(QOpenGLExtraFunctions *gl, const CapturedState &s)
{
    const auto toggle = [gl](GLenum cap, bool on) { on ? gl->glEnable(cap) : gl->glDisable(cap); };
    gl->glViewport(s.viewport[0], s.viewport[1], s.viewport[2], s.viewport[3]);
    toggle(GL_DEPTH_TEST, s.depthTest);
    gl->glDepthFunc(s.depthFunc);
    gl->glDepthMask(s.depthMask);
    toggle(GL_CULL_FACE, s.cullFace);
    gl->glCullFace(s.cullMode);
    gl->glFrontFace(s.frontFace);
    toggle(GL_BLEND, s.blend);
    gl->glBlendFuncSeparate(s.blendFunc[0], s.blendFunc[1], s.blendFunc[2], s.blendFunc[3]);
    gl->glColorMask(s.colorMask[0], s.colorMask[1], s.colorMask[2], s.colorMask[3]);
    toggle(GL_SCISSOR_TEST, s.scissorTest);
    gl->glScissor(s.scissor[0], s.scissor[1], s.scissor[2], s.scissor[3]);
}

// The captured numbers as GL takes them, converted as WebGL converted them.
template <typename T> std::vector<T> asGl(const std::vector<double> &v, T (*convert)(double))
{
    std::vector<T> out(v.size());
    std::transform(v.begin(), v.end(), out.begin(), convert);
    return out;
}

// One element of a uniform, by its WebGL type; false for a type not replayed.
bool setUniform(QOpenGLExtraFunctions *gl, GLint location, unsigned type,
                const std::vector<double> &v)
{
    const std::vector<GLfloat> f = asGl<GLfloat>(v, webIdlFloat);
    const std::vector<GLint> i = asGl<GLint>(v, webIdlLong);
    const std::vector<GLuint> u = asGl<GLuint>(v, webIdlUnsignedLong);
    const auto enough = [&v](std::size_t n) { return v.size() >= n; };
    switch (type) {
    case GL_FLOAT: return enough(1) && (gl->glUniform1fv(location, 1, f.data()), true);
    case GL_FLOAT_VEC2: return enough(2) && (gl->glUniform2fv(location, 1, f.data()), true);
    case GL_FLOAT_VEC3: return enough(3) && (gl->glUniform3fv(location, 1, f.data()), true);
    case GL_FLOAT_VEC4: return enough(4) && (gl->glUniform4fv(location, 1, f.data()), true);
    case GL_INT:
    case GL_BOOL:
    case GL_SAMPLER_2D:
    case GL_SAMPLER_CUBE: return enough(1) && (gl->glUniform1iv(location, 1, i.data()), true);
    case GL_INT_VEC2:
    case GL_BOOL_VEC2: return enough(2) && (gl->glUniform2iv(location, 1, i.data()), true);
    case GL_INT_VEC3:
    case GL_BOOL_VEC3: return enough(3) && (gl->glUniform3iv(location, 1, i.data()), true);
    case GL_INT_VEC4:
    case GL_BOOL_VEC4: return enough(4) && (gl->glUniform4iv(location, 1, i.data()), true);
    case GL_UNSIGNED_INT: return enough(1) && (gl->glUniform1uiv(location, 1, u.data()), true);
    case GL_UNSIGNED_INT_VEC2: return enough(2) && (gl->glUniform2uiv(location, 1, u.data()), true);
    case GL_UNSIGNED_INT_VEC3: return enough(3) && (gl->glUniform3uiv(location, 1, u.data()), true);
    case GL_UNSIGNED_INT_VEC4: return enough(4) && (gl->glUniform4uiv(location, 1, u.data()), true);
    case GL_FLOAT_MAT2:
        return enough(4) && (gl->glUniformMatrix2fv(location, 1, GL_FALSE, f.data()), true);
    case GL_FLOAT_MAT3:
        return enough(9) && (gl->glUniformMatrix3fv(location, 1, GL_FALSE, f.data()), true);
    case GL_FLOAT_MAT4:
        return enough(16) && (gl->glUniformMatrix4fv(location, 1, GL_FALSE, f.data()), true);
    default: return false;
    }
}

void setUniforms(QOpenGLExtraFunctions *gl, GLuint program, const CapturedOp &draw,
                 QStringList *notes)
{
    for (const CapturedUniform &u : draw.uniforms) {
        if (u.glType == GL_SAMPLER_2D || u.glType == GL_SAMPLER_CUBE)
            notes->push_back(
                PageReplayWords::tr("%1 samples a texture, which is not captured").arg(u.name));
        for (std::size_t k = 0; k < u.values.size(); ++k) {
            const QByteArray name =
                (u.isArray ? QStringLiteral("%1[%2]").arg(u.name).arg(k) : u.name).toUtf8();
            const GLint location = gl->glGetUniformLocation(program, name.constData());
            if (location >= 0 && !setUniform(gl, location, u.glType, u.values[k]))
                notes->push_back(PageReplayWords::tr("uniform %1 has a type PhongLab does not "
                                                     "set again")
                                     .arg(u.name));
        }
    }
}

void setAttributes(QOpenGLExtraFunctions *gl, GLuint program, const CapturedOp &draw,
                   const PageCapture &capture, ReplayObjects *objects)
{
    GLint count = 0;
    gl->glGetIntegerv(GL_MAX_VERTEX_ATTRIBS, &count);
    for (GLint i = 0; i < count; ++i)
        gl->glDisableVertexAttribArray(GLuint(i));
    for (const CapturedAttribute &a : draw.attributes) {
        const GLint location = gl->glGetAttribLocation(program, a.name.toUtf8().constData());
        if (location < 0)
            continue;
        if (!a.enabled) {
            const GLfloat v[4] = {GLfloat(a.value[0]), GLfloat(a.value[1]), GLfloat(a.value[2]),
                                  GLfloat(a.value[3])};
            gl->glVertexAttrib4fv(GLuint(location), v);
            continue;
        }
        objects->bindBuffer(GL_ARRAY_BUFFER, a.buffer, capture);
        const auto offset = reinterpret_cast<const void *>(quintptr(a.offset));
        if (a.integer)
            gl->glVertexAttribIPointer(GLuint(location), a.size, a.component, a.stride, offset);
        else
            gl->glVertexAttribPointer(GLuint(location), a.size, a.component, a.normalized, a.stride,
                                      offset);
        gl->glVertexAttribDivisor(GLuint(location), GLuint(a.divisor));
        gl->glEnableVertexAttribArray(GLuint(location));
    }
}

const BuiltProgram *programFor(const PageCapture &capture, int id, ReplayObjects *objects,
                               QString *problem)
{
    if (const auto it = objects->programs.find(id); it != objects->programs.end())
        return it->second.ok() ? &it->second : nullptr;
    const CapturedProgram *captured = capture.program(id);
    BuiltProgram built;
    if (captured) {
        ProgramBuilder builder;
        built = builder.build(
            {QStringLiteral("vertex shader %1").arg(id), captured->vertex.toUtf8()},
            {QStringLiteral("fragment shader %1").arg(id), captured->fragment.toUtf8()});
    }
    if (!built.ok())
        *problem = captured ? PageReplayWords::tr("program %1 does not build here: %2")
                                  .arg(id)
                                  .arg(built.report.errorSummary())
                            : PageReplayWords::tr("program %1 is not in the capture").arg(id);
    return &objects->programs.emplace(id, std::move(built)).first->second;
}

void draw(QOpenGLExtraFunctions *gl, const CapturedOp &op, const PageCapture &capture,
          ReplayObjects *objects)
{
    if (op.indexed()) {
        objects->bindBuffer(GL_ELEMENT_ARRAY_BUFFER, op.indices, capture);
        const auto offset = reinterpret_cast<const void *>(quintptr(op.offset));
        gl->glDrawElementsInstanced(op.mode, op.count, op.indexType, offset, op.instances);
    } else {
        gl->glDrawArraysInstanced(op.mode, op.first, op.count, op.instances);
    }
}

void clear(QOpenGLExtraFunctions *gl, const CapturedOp &op)
{
    gl->glClearColor(GLfloat(op.clearColor[0]), GLfloat(op.clearColor[1]),
                     GLfloat(op.clearColor[2]), GLfloat(op.clearColor[3]));
    gl->glClearDepthf(GLfloat(op.clearDepth));
    gl->glClear(op.clearMask & (GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT));
}

// Every captured clear and draw on the bound framebuffer; what cannot be
// drawn goes to `notReplayed`. The GL objects made for it are gone on return.
void replayOps(QOpenGLExtraFunctions *gl, const PageCapture &capture, QStringList *notReplayed)
{
    ReplayObjects objects(gl);
    // The drawing buffer as the browser hands it: transparent black, depth 1.
    gl->glDisable(GL_SCISSOR_TEST);
    gl->glColorMask(true, true, true, true);
    gl->glDepthMask(true);
    gl->glClearColor(0, 0, 0, 0);
    gl->glClearDepthf(1);
    gl->glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    if (capture.webgl == 2)
        gl->glEnable(kPrimitiveRestartFixedIndex);
    for (const CapturedOp &op : capture.ops) {
        applyState(gl, op.state);
        if (op.kind == CapturedOp::Kind::Clear) {
            clear(gl, op);
            continue;
        }
        QString problem = drawOutOfBounds(capture, op);
        const BuiltProgram *program =
            problem.isEmpty() ? programFor(capture, op.program, &objects, &problem) : nullptr;
        if (!program) {
            notReplayed->push_back(callSiteText(op.stack).isEmpty()
                                       ? problem
                                       : callSiteText(op.stack) + QStringLiteral(": ") + problem);
            continue;
        }
        gl->glUseProgram(program->program.id());
        setUniforms(gl, program->program.id(), op, notReplayed);
        setAttributes(gl, program->program.id(), op, capture, &objects);
        draw(gl, op, capture, &objects);
    }
    gl->glDisable(kPrimitiveRestartFixedIndex);
    gl->glUseProgram(0);
}

} // namespace

Result<ReplayedFrame> replayCapture(const PageCapture &capture)
{
    if (capture.canvas.isEmpty() || capture.pixels.isEmpty())
        return fail(PageReplayWords::tr("the page drew nothing to its canvas"));
    QOpenGLContext *context = QOpenGLContext::currentContext();
    if (!context)
        return fail(QStringLiteral("no current OpenGL context"));
    QOpenGLExtraFunctions *gl = context->extraFunctions();
    QOpenGLFramebufferObjectFormat format;
    format.setAttachment(QOpenGLFramebufferObject::CombinedDepthStencil);
    format.setInternalTextureFormat(GL_RGBA8);
    QOpenGLFramebufferObject target(capture.canvas, format);
    if (!target.isValid() || !target.bind())
        return fail(PageReplayWords::tr("no %1x%2 framebuffer here")
                        .arg(capture.canvas.width())
                        .arg(capture.canvas.height()));
    ReplayedFrame frame;
    replayOps(gl, capture, &frame.notReplayed);
    frame.pixels.resize(qsizetype(capture.canvas.width()) * capture.canvas.height() * 4);
    gl->glPixelStorei(GL_PACK_ALIGNMENT, 1);
    gl->glReadPixels(0, 0, capture.canvas.width(), capture.canvas.height(), GL_RGBA,
                     GL_UNSIGNED_BYTE, frame.pixels.data());
    target.release();
    frame.notReplayed.removeDuplicates();
    return frame;
}

} // namespace phonglab
