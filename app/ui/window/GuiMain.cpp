#include "GuiMain.h"

#include "core/project/ProjectPrograms.h"

#include "GuiArguments.h"
#include "LanguageMenu.h"
#include "MainWindow.h"
#include "SceneDocument.h"
#include "core/scene/ResourcePaths.h"
#include "core/support/Language.h"
#include "render/gl/GlFormat.h"
#include "ui/viewport/Viewport.h"

#include <QApplication>
#include <QDir>
#include <QIcon>
#include <QMessageBox>
#include <QSurfaceFormat>
#include <cstdio>

namespace phonglab {

namespace {

constexpr int kExitFailure = 1;
constexpr int kExitUsage = 2;
// Said instead of Qt's abort when there is nowhere to open the window.
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
    const Result<> opened = window.document()->openAndWait(path);
    if (opened)
        return true;
    // The error names the file.
    const QString message = QObject::tr("cannot open the default scene: %1").arg(opened.error());
    printError(message);
    QMessageBox::critical(nullptr, QObject::tr("PhongLab"), message);
    return false;
}

// The files named on the command line (a scene, or meshes: what a desktop
// passes for its entry's %F) then load in the background like any opened
// files; a load failing reports itself.
void openRequestedFiles(MainWindow &window, const QStringList &paths)
{
    if (const Result<> opened = window.document()->openFiles(paths); !opened)
        QMessageBox::warning(
            &window, QObject::tr("Cannot open"),
            QObject::tr("%1\n\n%2\n\nShowing the default scene instead.")
                .arg(QDir::toNativeSeparators(paths.join(QLatin1Char('\n'))), opened.error()));
}

// A scene with a student's shaders (a grading report's command): a failure
// says why and leaves the default scene.
void openSubmission(MainWindow &window, const GuiArguments &requested)
{
    QString vertex = requested.vertexShader, fragment = requested.fragmentShader;
    Result<> opened;
    if (!requested.project.isEmpty()) {
        // A WebGL project's program: its stages where the page or script has them.
        const Result<ProjectProgram> chosen =
            chooseProgram(readProject(requested.project), requested.program);
        if (chosen) {
            vertex = shaderLocator(chosen->vertex);
            fragment = shaderLocator(chosen->fragment);
        } else {
            opened = fail(chosen.error());
        }
    }
    if (opened)
        opened = window.document()->openSubmission(requested.files.front(), vertex, fragment);
    if (!opened)
        QMessageBox::warning(
            &window, QObject::tr("Cannot open"),
            QObject::tr("%1\n\nShowing the default scene instead.").arg(opened.error()));
}

} // namespace

void useMultisamplingInViewOnly(MainWindow &window, int viewportSamples)
{
    window.viewport()->frames().setFormat(phonglabSurfaceFormat(viewportSamples));
    QSurfaceFormat single = QSurfaceFormat::defaultFormat();
    single.setSamples(0);
    QSurfaceFormat::setDefaultFormat(single);
}

int runGui(int argc, char **argv, const QString &synopsis)
{
    // A slip in the arguments is a usage error with or without a display.
    GuiArguments requested;
    {
        const QCoreApplication words(argc, argv); // the run's language, for the message
        requested = parseGuiArguments(QCoreApplication::arguments().mid(1));
        if (!requested.error.isEmpty()) {
            printError(requested.error);
            std::fprintf(stderr, "%s\n", synopsis.toLocal8Bit().constData());
            return kExitUsage;
        }
        if (!displayConfigured()) {
            std::fprintf(stderr, "%s\n",
                         QObject::tr("phonglab: the editor window needs a display (X11 or "
                                     "Wayland), and DISPLAY is not set.\nThe commands render, "
                                     "check, grade, mesh-info and bench run without one "
                                     "(phonglab --help).")
                             .toLocal8Bit()
                             .constData());
            return kExitFailure;
        }
    }
    // Must precede QApplication: the global share context is created with it.
    QSurfaceFormat::setDefaultFormat(phonglabSurfaceFormat(kViewportSamples));
    const bool x11FallbackArmed = armX11Fallback();
    QApplication app(argc, argv);
    if (x11FallbackArmed) {
        qunsetenv("QT_QPA_PLATFORM"); // not for child processes
        if (QGuiApplication::platformName() == QLatin1String("offscreen")) {
            printError(QObject::tr("cannot connect to the X display '%1' (DISPLAY)")
                           .arg(qEnvironmentVariable("DISPLAY")));
            return kExitFailure;
        }
    }
    QApplication::setApplicationName(QStringLiteral("PhongLab"));
    QApplication::setOrganizationName(QStringLiteral("PhongLab"));
    // The project's version, as `phonglab --version` prints it (About).
    QApplication::setApplicationVersion(QStringLiteral(PHONGLAB_VERSION));
    QApplication::setWindowIcon(QIcon(QStringLiteral(":/packaging/org.phonglab.PhongLab.svg")));
    // Docks and task bars (Wayland's app id, X11's WM_CLASS) match the
    // window to the installed .desktop file, and so to its icon, by this.
    QGuiApplication::setDesktopFileName(QStringLiteral("org.phonglab.PhongLab"));
    // The language chosen in the window (View → Language), unless --lang
    // said otherwise for this run; else the locale's (core/support/Language).
    if (const QString remembered = LanguageMenu::rememberedLanguage();
        !languageRequested() && !remembered.isEmpty())
        useLanguage(remembered);

    MainWindow window;
    useMultisamplingInViewOnly(window, kViewportSamples);
    window.restoreWindowSettings(); // geometry and docks as the last session left them
    if (!openDefaultScene(window))
        return kExitFailure;
    window.show();
    if (requested.hasShaders())
        openSubmission(window, requested);
    else if (!requested.files.isEmpty())
        openRequestedFiles(window, requested.files);
    return app.exec();
}

} // namespace phonglab
