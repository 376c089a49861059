#pragma once
#include "HeadlessEgl.h"

#include <QMutex>
#include <QScopedPointer>
#include <qpa/qplatformintegration.h>

class QPlatformFontDatabase;

namespace phonglab::headless {

class HeadlessScreen;

// The Qt platform "phonglab-headless": OpenGL through EGL without a display
// server, one virtual screen, windows that are never shown. Qt's own
// "offscreen" platform can only make a context through GLX, i.e. with an X
// server; this one serves `phonglab render`, `check` and `bench` and the GL
// tests where there is none.
class HeadlessIntegration : public QPlatformIntegration
{
public:
    HeadlessIntegration();
    ~HeadlessIntegration() override;

    bool hasCapability(Capability cap) const override;
    QPlatformWindow *createPlatformWindow(QWindow *window) const override;
    QPlatformBackingStore *createPlatformBackingStore(QWindow *window) const override;
    QPlatformOpenGLContext *createPlatformOpenGLContext(QOpenGLContext *context) const override;
    QPlatformOffscreenSurface *createPlatformOffscreenSurface(
        QOffscreenSurface *surface) const override;
    QAbstractEventDispatcher *createEventDispatcher() const override;
    QPlatformFontDatabase *fontDatabase() const override;
    QStringList themeNames() const override;
    QPlatformTheme *createPlatformTheme(const QString &name) const override;

    // The integration in use, or null when the application runs on another
    // platform.
    static HeadlessIntegration *instance();
    // Why no OpenGL context can be made, or empty when it can: the EGL
    // display's problem, else the last context's.
    QString problem() const;

private:
    EglDisplayChoice m_egl;
    HeadlessScreen *m_screen = nullptr;
    QScopedPointer<QPlatformFontDatabase> m_fontDatabase;
    mutable QMutex m_contextProblemMutex;
    mutable QString m_contextProblem;
};

} // namespace phonglab::headless
