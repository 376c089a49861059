#pragma once
#include <EGL/egl.h>

#include <QString>
#include <QSurfaceFormat>
#include <qpa/qplatformopenglcontext.h>

namespace phonglab::headless {

// A desktop OpenGL context on a headless EGL display, made current without
// any surface (EGL_KHR_surfaceless_context): whatever it draws goes into
// framebuffer objects, as PhongLab's offscreen rendering always does.
class HeadlessGlContext : public QPlatformOpenGLContext
{
public:
    HeadlessGlContext(EGLDisplay display, const QSurfaceFormat &requested,
                      HeadlessGlContext *shareWith);
    ~HeadlessGlContext() override;

    QSurfaceFormat format() const override { return m_format; }
    void swapBuffers(QPlatformSurface *) override { } // nothing is presented
    bool makeCurrent(QPlatformSurface *surface) override;
    void doneCurrent() override;
    bool isSharing() const override { return m_shared; }
    bool isValid() const override { return m_context != EGL_NO_CONTEXT; }
    QFunctionPointer getProcAddress(const char *procName) override;

    // Why the context could not be made, for the message of whoever asked.
    QString problem() const { return m_problem; }

private:
    EGLConfig chooseConfig();
    void readActualFormat();

    EGLDisplay m_display = EGL_NO_DISPLAY;
    EGLConfig m_config = nullptr;
    EGLContext m_context = EGL_NO_CONTEXT;
    QSurfaceFormat m_format;
    bool m_shared = false;
    QString m_problem;
};

} // namespace phonglab::headless
