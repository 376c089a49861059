#include "HeadlessGlContext.h"

#include "HeadlessEgl.h"

#include <EGL/eglext.h>
#include <QByteArray>
#include <QList>

namespace phonglab::headless {

namespace {

// The GL entry points needed to read the context's real version; resolved
// through EGL so that nothing links libGL directly.
constexpr unsigned kGlMajorVersion = 0x821B;
constexpr unsigned kGlMinorVersion = 0x821C;
constexpr unsigned kGlContextProfileMask = 0x9126;
constexpr int kGlCoreProfileBit = 0x1;
using GetIntegerv = void (*)(unsigned, int *);

// The context current on this thread, put back after a temporary switch.
struct CurrentEgl {
    EGLDisplay display = eglGetCurrentDisplay();
    EGLContext context = eglGetCurrentContext();
    EGLSurface draw = eglGetCurrentSurface(EGL_DRAW);
    EGLSurface read = eglGetCurrentSurface(EGL_READ);

    void restore() const
    {
        if (context == EGL_NO_CONTEXT)
            eglMakeCurrent(eglGetCurrentDisplay(), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        else
            eglMakeCurrent(display, draw, read, context);
    }
};

} // namespace

HeadlessGlContext::HeadlessGlContext(EGLDisplay display, const QSurfaceFormat &requested,
                                     HeadlessGlContext *shareWith)
    : m_display(display)
    , m_format(requested)
{
    eglBindAPI(EGL_OPENGL_API);
    m_config = chooseConfig();
    QList<EGLint> attributes{EGL_CONTEXT_MAJOR_VERSION, requested.majorVersion(),
                             EGL_CONTEXT_MINOR_VERSION, requested.minorVersion()};
    if (requested.version() >= qMakePair(3, 2)) {
        attributes << EGL_CONTEXT_OPENGL_PROFILE_MASK
                   << (requested.profile() == QSurfaceFormat::CompatibilityProfile
                           ? EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT
                           : EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT);
    }
    if (requested.testOption(QSurfaceFormat::DebugContext))
        attributes << EGL_CONTEXT_OPENGL_DEBUG << EGL_TRUE;
    attributes << EGL_NONE;
    const EGLContext share = shareWith ? shareWith->m_context : EGL_NO_CONTEXT;
    m_context = eglCreateContext(m_display, m_config, share, attributes.constData());
    if (m_context == EGL_NO_CONTEXT) {
        m_problem = QStringLiteral("eglCreateContext for OpenGL %1.%2 failed (%3)")
                        .arg(requested.majorVersion())
                        .arg(requested.minorVersion())
                        .arg(eglErrorName(eglGetError()));
        return;
    }
    m_shared = share != EGL_NO_CONTEXT;
    readActualFormat();
}

HeadlessGlContext::~HeadlessGlContext()
{
    if (m_context == EGL_NO_CONTEXT)
        return;
    if (eglGetCurrentContext() == m_context)
        eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(m_display, m_context);
}

// Any config that can render desktop OpenGL: the context never draws into
// an EGL surface, so its colour and depth sizes do not matter. Without one,
// a context with no config (EGL_KHR_no_config_context).
EGLConfig HeadlessGlContext::chooseConfig()
{
    const EGLint wanted[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (eglChooseConfig(m_display, wanted, &config, 1, &count) && count > 0)
        return config;
    return EGL_NO_CONFIG_KHR;
}

// QOpenGLContext reports the version and profile the platform says; ask the
// driver rather than echo the request.
void HeadlessGlContext::readActualFormat()
{
    const CurrentEgl previous;
    if (!eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, m_context)) {
        m_problem = QStringLiteral("the context cannot be made current without a surface (%1)")
                        .arg(eglErrorName(eglGetError()));
        eglDestroyContext(m_display, m_context);
        m_context = EGL_NO_CONTEXT;
        previous.restore();
        return;
    }
    if (auto getIntegerv = reinterpret_cast<GetIntegerv>(eglGetProcAddress("glGetIntegerv"))) {
        int major = 0, minor = 0, profile = 0;
        getIntegerv(kGlMajorVersion, &major);
        getIntegerv(kGlMinorVersion, &minor);
        if (major > 0)
            m_format.setVersion(major, minor);
        if (m_format.version() >= qMakePair(3, 2)) {
            getIntegerv(kGlContextProfileMask, &profile);
            m_format.setProfile((profile & kGlCoreProfileBit)
                                    ? QSurfaceFormat::CoreProfile
                                    : QSurfaceFormat::CompatibilityProfile);
        }
    }
    m_format.setRenderableType(QSurfaceFormat::OpenGL);
    previous.restore();
}

bool HeadlessGlContext::makeCurrent(QPlatformSurface *)
{
    eglBindAPI(EGL_OPENGL_API);
    if (eglGetCurrentContext() == m_context)
        return true;
    return eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, m_context);
}

void HeadlessGlContext::doneCurrent()
{
    eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
}

QFunctionPointer HeadlessGlContext::getProcAddress(const char *procName)
{
    return eglGetProcAddress(procName);
}

} // namespace phonglab::headless
