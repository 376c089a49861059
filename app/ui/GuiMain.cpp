#include "GuiMain.h"

#include "MainWindow.h"
#include "core/ResourcePaths.h"
#include "render/GlFormat.h"

#include <QApplication>
#include <QDir>
#include <QMessageBox>
#include <QSurfaceFormat>
#include <cstdio>

namespace phonglab {

namespace {

constexpr int kExitFailure = 1;
constexpr int kViewportSamples = 4;

void printError(const QString &message)
{
    std::fprintf(stderr, "phonglab: error: %s\n", message.toLocal8Bit().constData());
    std::fflush(stderr);
}

// Without a display Qt's platform plugin aborts the process; say so plainly
// instead. An explicit QT_QPA_PLATFORM (offscreen, vnc, eglfs...) is trusted.
bool displayConfigured()
{
#if defined(Q_OS_UNIX) && !defined(Q_OS_DARWIN)
    return qEnvironmentVariableIsSet("QT_QPA_PLATFORM") || !qEnvironmentVariableIsEmpty("DISPLAY")
        || !qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY");
#else
    return true;
#endif
}

// DISPLAY can be set yet unreachable (a stale value, a dead Xvfb), which Qt
// would also abort on. In the plain X11 case let Qt fall back to the offscreen
// platform instead, and treat landing there as "no display".
bool armX11Fallback()
{
#if defined(Q_OS_UNIX) && !defined(Q_OS_DARWIN)
    if (qEnvironmentVariableIsSet("QT_QPA_PLATFORM")
        || !qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY")
        || qEnvironmentVariable("XDG_SESSION_TYPE") == QLatin1String("wayland"))
        return false;
    qputenv("QT_QPA_PLATFORM", "xcb;offscreen"); // Qt tries each in turn
    return true;
#else
    return false;
#endif
}

// The default scene is small and open before the window shows, so there is
// never an empty window; a broken default is fatal.
bool openDefaultScene(MainWindow &window)
{
    const QString path = defaultScenePath();
    const Result<> opened = window.openScene(path);
    if (opened)
        return true;
    const QString message =
        QObject::tr("cannot open the default scene %1: %2").arg(path, opened.error());
    printError(message);
    QMessageBox::critical(nullptr, QObject::tr("PhongLab"), message);
    return false;
}

// The file named on the command line (a scene or a mesh) then loads in the
// background like any opened file; a load failing reports itself.
void openRequestedFile(MainWindow &window, const QString &path)
{
    if (const Result<> opened = window.openFiles({path}); !opened)
        QMessageBox::warning(&window, QObject::tr("Cannot open"),
                             QObject::tr("%1\n\n%2\n\nShowing the default scene instead.")
                                 .arg(QDir::toNativeSeparators(path), opened.error()));
}

} // namespace

int runGui(int argc, char **argv)
{
    if (!displayConfigured()) {
        printError(
            QStringLiteral("no display to open a window on (neither DISPLAY nor WAYLAND_DISPLAY is "
                           "set); run it inside a desktop session or under xvfb-run, or use "
                           "'phonglab render' to render without a window"));
        return kExitFailure;
    }
    // Must precede QApplication: the global share context is created with it.
    QSurfaceFormat::setDefaultFormat(phonglabSurfaceFormat(kViewportSamples));
    const bool x11FallbackArmed = armX11Fallback();
    QApplication app(argc, argv);
    if (x11FallbackArmed) {
        qunsetenv("QT_QPA_PLATFORM"); // not for child processes
        if (QGuiApplication::platformName() == QLatin1String("offscreen")) {
            printError(QStringLiteral("cannot connect to the X display '%1' (DISPLAY)")
                           .arg(qEnvironmentVariable("DISPLAY")));
            return kExitFailure;
        }
    }
    QApplication::setApplicationName(QStringLiteral("PhongLab"));
    QApplication::setOrganizationName(QStringLiteral("PhongLab"));

    MainWindow window;
    window.restoreWindowSettings(); // geometry and docks as the last session left them
    if (!openDefaultScene(window))
        return kExitFailure;
    window.show();
    if (argc > 1)
        openRequestedFile(window, QString::fromLocal8Bit(argv[1]));
    return app.exec();
}

} // namespace phonglab
