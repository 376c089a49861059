#include "WarmUpDraw.h"

#include "mesh/import/BuiltinMeshes.h"

#include <QCoreApplication>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct WarmUpDrawWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::WarmUpDraw)
};

namespace {
constexpr int kTargetSide = 8; // pixels: enough to run every stage, cheap to fill
} // namespace

WarmUpDraw::WarmUpDraw() = default;
WarmUpDraw::~WarmUpDraw() = default; // destroy() runs with the context current

Result<> WarmUpDraw::create(Target target, int samples)
{
    initializeOpenGLFunctions();
    if (target == Target::Surface)
        return m_mesh.upload(makeUvSphere(8, 4));
    // What Renderer draws into offscreen (drawIntoImage): RGBA8 colour,
    // packed depth-stencil.
    QOpenGLFramebufferObjectFormat format;
    format.setAttachment(QOpenGLFramebufferObject::CombinedDepthStencil);
    format.setInternalTextureFormat(GL_RGBA8);
    format.setSamples(samples);
    m_fbo = std::make_unique<QOpenGLFramebufferObject>(QSize(kTargetSide, kTargetSide), format);
    if (!m_fbo->isValid()) {
        m_fbo.reset();
        return fail(
            WarmUpDrawWords::tr("cannot create the %1-sample framebuffer for warming programs")
                .arg(samples));
    }
    // Same interleaved layout as every scene mesh, so the vertex fetch code
    // generated here is the one the viewport needs too.
    if (Result<> uploaded = m_mesh.upload(makeUvSphere(8, 4)); !uploaded) {
        m_fbo.reset();
        return uploaded;
    }
    return {};
}

void WarmUpDraw::destroy()
{
    m_mesh.destroy();
    m_fbo.reset();
}

void WarmUpDraw::warm(GLuint program)
{
    if (!isCreated())
        return;
    if (m_fbo)
        m_fbo->bind();
    else
        glBindFramebuffer(GL_FRAMEBUFFER,
                          QOpenGLContext::currentContext()->defaultFramebufferObject());
    glViewport(0, 0, kTargetSide, kTargetSide);
    // Renderer::render's state for a closed mesh, the scissor included: the
    // clear stays in the corner rather than filling the window's buffer.
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, kTargetSide, kTargetSide);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    glUseProgram(program);
    m_mesh.draw();
    glUseProgram(0);
    glDisable(GL_SCISSOR_TEST);
    if (m_fbo)
        m_fbo->release();
    // The hand-over contract: the program has linked and run before another
    // context touches it.
    glFinish();
}

} // namespace phonglab
