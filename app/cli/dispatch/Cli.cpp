#include "Cli.h"

#include "cli/check/CheckCommand.h"
#include "cli/common/CliCommon.h"
#include "cli/common/ProgramSynopsis.h"
#include "cli/grade/GradeCommand.h"
#include "cli/mesh/ImportMeshCommand.h"
#include "cli/mesh/MeshInfoCommand.h"
#include "cli/render/RenderCommand.h"
#include "core/support/NearestSpelling.h"
#include "headless/HeadlessPlatform.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QGuiApplication>

#include <QString>
#include <string_view>

namespace phonglab::cli {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct CliWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::cli::Cli)
};

namespace {

// grade's parent draws nothing, but with --pages it draws each page's
// captured frame again (cli/grade/GradePages): that takes OpenGL.
std::unique_ptr<QCoreApplication> makeGradeApplication(int &argc, char **argv)
{
    for (int i = 1; i < argc; ++i)
        if (std::string_view(argv[i]) == "--pages")
            return makeGuiApplication(argc, argv);
    return makeCoreApplication(argc, argv);
}

constexpr Subcommand kSubcommands[] = {
    {"render", QT_TRANSLATE_NOOP("phonglab::cli::Cli", "render a scene offscreen into a PNG"),
     runRender, makeGuiApplication},
    {"check",
     QT_TRANSLATE_NOOP(
         "phonglab::cli::Cli",
         "check a shader against the exact image and name the mistake that explains a wrong one"),
     runCheck, makeGuiApplication},
    {"grade",
     QT_TRANSLATE_NOOP(
         "phonglab::cli::Cli",
         "check a class folder of submissions, each in a process of its own; a report"),
     runGrade, makeGradeApplication},
    {"mesh-info",
     QT_TRANSLATE_NOOP("phonglab::cli::Cli",
                       "load a mesh and report its size, normals, bounds and warnings"),
     runMeshInfo},
};

void printHelp(std::span<const Subcommand> more)
{
    QString text = programSynopsis() + CliWords::tr("\n\ncommands:\n");
    for (const auto &commands : {std::span<const Subcommand>(kSubcommands), more})
        for (const Subcommand &c : commands)
            text += QStringLiteral("  %1  %2\n")
                        .arg(QString::fromLatin1(c.name), -11)
                        .arg(QCoreApplication::translate("phonglab::cli::Cli", c.summary));
    text += CliWords::tr("\n--lang en|de on any command or the window chooses the language of "
                         "that run (else the locale's: LANGUAGE, LC_ALL, LC_MESSAGES, LANG).");
    text += CliWords::tr("\n'phonglab <command> --help' describes a command's options.");
    text += CliWords::tr("\n'phonglab --version' prints the version.");
    printLine(text);
}

// The options `phonglab` itself knows, before any command or file.
QStringList topLevelOptions()
{
    return {QStringLiteral("--help"), QStringLiteral("--version"), QStringLiteral("--lang"),
            QStringLiteral("--vertex"), QStringLiteral("--fragment")};
}

// `phonglab CMD ... --help`: the words of a command's help, wherever they
// stand before a `--`.
bool asksForHelp(int argc, char **argv)
{
    for (int i = 2; i < argc; ++i) {
        const std::string_view a(argv[i]);
        if (a == "--")
            return false;
        if (a == "--help" || a == "-h")
            return true;
    }
    return false;
}

} // namespace

std::unique_ptr<QCoreApplication> makeCoreApplication(int &argc, char **argv)
{
    return std::make_unique<QCoreApplication>(argc, argv);
}

std::unique_ptr<QCoreApplication> makeGuiApplication(int &argc, char **argv)
{
    return std::make_unique<QGuiApplication>(argc, argv);
}

std::optional<int> dispatch(int argc, char **argv, std::span<const Subcommand> more)
{
    if (argc < 2)
        return std::nullopt;
    const QString first = QString::fromLocal8Bit(argv[1]);
    if (first == QLatin1String("--help") || first == QLatin1String("-h")
        || first == QLatin1String("help")) {
        const QCoreApplication app(argc, argv); // its start installs the run's language
        printHelp(more);
        return kExitOk;
    }
    if (first == QLatin1String("--version")) {
        printLine(QStringLiteral("phonglab " PHONGLAB_VERSION));
        return kExitOk;
    }
    for (const auto &commands : {std::span<const Subcommand>(kSubcommands), more})
        for (const Subcommand &c : commands)
            if (first == QLatin1String(c.name)) {
                // A command's help draws nothing: no display, no GL driver
                // loaded (and nothing of the driver's left behind at exit).
                if (asksForHelp(argc, argv)) {
                    const QCoreApplication app(argc, argv);
                    return c.run(argc, argv);
                }
                // Commands draw only into framebuffer objects: without a
                // (reachable) display server they render through EGL.
                chooseCommandPlatform();
                const std::unique_ptr<QCoreApplication> app = c.makeApplication(argc, argv);
                return c.run(argc, argv);
            }
    if (first == QLatin1String("__import-mesh")) { // internal, not in --help
        const QCoreApplication app(argc, argv);    // its messages in the parent's language
        return runImportMesh(argc, argv);
    }
    // The window's own options (GuiArguments) may come before the scene.
    for (const QLatin1String option : {QLatin1String("--vertex"), QLatin1String("--fragment")})
        if (first == option || first.startsWith(option + QLatin1Char('=')))
            return std::nullopt;
    if (first.startsWith(QLatin1Char('-'))) {
        const QCoreApplication app(argc, argv); // the message in the run's language
        return usageError(unknownOptionMessage(first, topLevelOptions()), programSynopsis());
    }
    // A word that is neither a command nor a file is a slip: `meshinfo`.
    if (!QFileInfo::exists(first)) {
        const QCoreApplication app(argc, argv);
        QStringList commands;
        for (const auto &list : {std::span<const Subcommand>(kSubcommands), more})
            for (const Subcommand &c : list)
                commands << QString::fromLatin1(c.name);
        const bool looksLikeAFile =
            first.contains(QLatin1Char('.')) || first.contains(QLatin1Char('/'));
        return usageError(looksLikeAFile
                              ? CliWords::tr("%1: no such file, and not a command").arg(first)
                              : unknownCommandMessage(first, commands),
                          programSynopsis());
    }
    return std::nullopt; // a scene file for the GUI
}

} // namespace phonglab::cli
