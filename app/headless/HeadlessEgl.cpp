#include "HeadlessEgl.h"

#include <EGL/eglext.h>

#include <QByteArray>
#include <QStringList>
#include <vector>

namespace phonglab::headless {

namespace {

bool hasClientExtension(const char *name)
{
    const char *all = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    return all && QByteArray(all).split(' ').contains(QByteArray(name));
}

// eglInitialize, then desktop OpenGL (not GLES) must be bindable on it.
bool initialize(EGLDisplay display, QString *problem)
{
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor)) {
        *problem = QStringLiteral("eglInitialize failed (%1)").arg(eglErrorName(eglGetError()));
        return false;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
        *problem = QStringLiteral("the display offers no desktop OpenGL");
        eglTerminate(display);
        return false;
    }
    return true;
}

EGLDisplay openDevicePlatform(QString *problem)
{
    if (!hasClientExtension("EGL_EXT_platform_device")) {
        *problem = QStringLiteral("EGL_EXT_platform_device is not offered");
        return EGL_NO_DISPLAY;
    }
    auto queryDevices =
        reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    if (!queryDevices) {
        *problem = QStringLiteral("eglQueryDevicesEXT is missing");
        return EGL_NO_DISPLAY;
    }
    EGLint count = 0;
    if (!queryDevices(0, nullptr, &count) || count <= 0) {
        *problem = QStringLiteral("no EGL device");
        return EGL_NO_DISPLAY;
    }
    std::vector<EGLDeviceEXT> devices(std::size_t(count), nullptr);
    queryDevices(count, devices.data(), &count);
    // The first device whose display initializes: a GPU's comes before
    // Mesa's software device.
    QStringList failures;
    for (EGLDeviceEXT device : devices) {
        EGLDisplay display = eglGetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
        QString why;
        if (display != EGL_NO_DISPLAY && initialize(display, &why))
            return display;
        failures << (why.isEmpty() ? QStringLiteral("no display") : why);
    }
    *problem = QStringLiteral("%1 device(s), none usable: %2")
                   .arg(count)
                   .arg(failures.join(QStringLiteral("; ")));
    return EGL_NO_DISPLAY;
}

EGLDisplay openSurfacelessPlatform(QString *problem)
{
    if (!hasClientExtension("EGL_MESA_platform_surfaceless")) {
        *problem = QStringLiteral("EGL_MESA_platform_surfaceless is not offered (Mesa's EGL, "
                                  "package libegl-mesa0, provides it)");
        return EGL_NO_DISPLAY;
    }
    EGLDisplay display =
        eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display == EGL_NO_DISPLAY) {
        *problem =
            QStringLiteral("eglGetPlatformDisplay failed (%1)").arg(eglErrorName(eglGetError()));
        return EGL_NO_DISPLAY;
    }
    return initialize(display, problem) ? display : EGL_NO_DISPLAY;
}

} // namespace

EglDisplayChoice openHeadlessEglDisplay()
{
    // Without client extensions there is no EGL 1.5 loader at all.
    if (!eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS))
        return {EGL_NO_DISPLAY,
                QStringLiteral("no EGL 1.5 client library with platform "
                               "extensions (packages libegl1 and libegl-mesa0)")};
    const QByteArray wanted = qgetenv("PHONGLAB_EGL_PLATFORM");
    struct Platform {
        const char *name;
        EGLDisplay (*open)(QString *);
    };
    const Platform platforms[] = {{"device", openDevicePlatform},
                                  {"surfaceless", openSurfacelessPlatform}};
    QStringList failures, names;
    for (const Platform &platform : platforms) {
        names << QLatin1String(platform.name);
        if (!wanted.isEmpty() && wanted != platform.name)
            continue;
        QString why;
        const EGLDisplay display = platform.open(&why);
        if (display != EGL_NO_DISPLAY)
            return {display, {}};
        failures << QStringLiteral("%1 platform: %2").arg(QLatin1String(platform.name), why);
    }
    if (failures.isEmpty())
        failures << QStringLiteral("PHONGLAB_EGL_PLATFORM=%1 names no platform (%2)")
                        .arg(QString::fromLocal8Bit(wanted), names.join(QStringLiteral(", ")));
    return {EGL_NO_DISPLAY, failures.join(QStringLiteral("; "))};
}

QString eglErrorName(EGLint error)
{
    switch (error) {
    case EGL_SUCCESS: return QStringLiteral("EGL_SUCCESS");
    case EGL_NOT_INITIALIZED: return QStringLiteral("EGL_NOT_INITIALIZED");
    case EGL_BAD_ACCESS: return QStringLiteral("EGL_BAD_ACCESS");
    case EGL_BAD_ALLOC: return QStringLiteral("EGL_BAD_ALLOC");
    case EGL_BAD_ATTRIBUTE: return QStringLiteral("EGL_BAD_ATTRIBUTE");
    case EGL_BAD_CONFIG: return QStringLiteral("EGL_BAD_CONFIG");
    case EGL_BAD_CONTEXT: return QStringLiteral("EGL_BAD_CONTEXT");
    case EGL_BAD_DISPLAY: return QStringLiteral("EGL_BAD_DISPLAY");
    case EGL_BAD_MATCH: return QStringLiteral("EGL_BAD_MATCH");
    case EGL_BAD_PARAMETER: return QStringLiteral("EGL_BAD_PARAMETER");
    case EGL_BAD_SURFACE: return QStringLiteral("EGL_BAD_SURFACE");
    default: return QStringLiteral("EGL error 0x%1").arg(error, 0, 16);
    }
}

} // namespace phonglab::headless
