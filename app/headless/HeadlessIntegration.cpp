#include "HeadlessIntegration.h"

#include "HeadlessBackingStore.h"
#include "HeadlessGlContext.h"
#include "HeadlessOffscreenSurface.h"
#include "HeadlessPlatform.h"
#include "HeadlessScreen.h"
#include "HeadlessTheme.h"

#include <QMutexLocker>
#include <QOpenGLContext>
#include <QtGui/private/qgenericunixeventdispatcher_p.h>
#include <QtGui/private/qgenericunixfontdatabase_p.h>
#include <qpa/qplatformwindow.h>
#include <qpa/qwindowsysteminterface.h>

namespace phonglab::headless {

namespace {

HeadlessIntegration *g_instance = nullptr;

} // namespace

HeadlessIntegration::HeadlessIntegration()
    : m_egl(openHeadlessEglDisplay())
    , m_fontDatabase(new QGenericUnixFontDatabase)
{
    g_instance = this;
    m_screen = new HeadlessScreen;
    QWindowSystemInterface::handleScreenAdded(m_screen); // Qt owns it from here
}

HeadlessIntegration::~HeadlessIntegration()
{
    QWindowSystemInterface::handleScreenRemoved(m_screen);
    if (m_egl.display != EGL_NO_DISPLAY)
        eglTerminate(m_egl.display);
    g_instance = nullptr;
}

HeadlessIntegration *HeadlessIntegration::instance()
{
    return g_instance;
}

QString HeadlessIntegration::problem() const
{
    if (m_egl.display == EGL_NO_DISPLAY)
        return m_egl.problem;
    const QMutexLocker lock(&m_contextProblemMutex);
    return m_contextProblem;
}

bool HeadlessIntegration::hasCapability(Capability cap) const
{
    switch (cap) {
    case OpenGL:
    case ThreadedOpenGL:
    case ThreadedPixmaps:
    case MultipleWindows: return true;
    case RhiBasedRendering: return false;
    default: return QPlatformIntegration::hasCapability(cap);
    }
}

QPlatformWindow *HeadlessIntegration::createPlatformWindow(QWindow *window) const
{
    return new QPlatformWindow(window);
}

QPlatformBackingStore *HeadlessIntegration::createPlatformBackingStore(QWindow *window) const
{
    return new HeadlessBackingStore(window);
}

QPlatformOpenGLContext *HeadlessIntegration::createPlatformOpenGLContext(
    QOpenGLContext *context) const
{
    if (m_egl.display == EGL_NO_DISPLAY)
        return nullptr;
    auto *share =
        context->shareHandle() ? static_cast<HeadlessGlContext *>(context->shareHandle()) : nullptr;
    auto *glContext = new HeadlessGlContext(m_egl.display, context->format(), share);
    const QMutexLocker lock(&m_contextProblemMutex); // contexts are made on any thread
    m_contextProblem = glContext->problem();
    return glContext;
}

QPlatformOffscreenSurface *HeadlessIntegration::createPlatformOffscreenSurface(
    QOffscreenSurface *surface) const
{
    return new HeadlessOffscreenSurface(surface);
}

QAbstractEventDispatcher *HeadlessIntegration::createEventDispatcher() const
{
    return createUnixEventDispatcher();
}

QPlatformFontDatabase *HeadlessIntegration::fontDatabase() const
{
    return m_fontDatabase.data();
}

QStringList HeadlessIntegration::themeNames() const
{
    return {QLatin1String(kHeadlessPlatformName)};
}

QPlatformTheme *HeadlessIntegration::createPlatformTheme(const QString &name) const
{
    return name == QLatin1String(kHeadlessPlatformName) ? new HeadlessTheme : nullptr;
}

} // namespace phonglab::headless
