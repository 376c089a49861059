#include "PageOptions.h"

#include "cli/common/CliCommon.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace phonglab::cli {

struct PageOptionsWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::cli::PageOptions)
};

namespace {

QCommandLineOption pageOption(PageOptions::Use use)
{
    if (use == PageOptions::Use::Grade)
        return QCommandLineOption(QStringLiteral("pages"),
                                  PageOptionsWords::tr("run each submission's page in headless "
                                                       "Chromium and check what it drew"));
    return QCommandLineOption(QStringLiteral("page"),
                              PageOptionsWords::tr("run the project's page in headless Chromium "
                                                   "and check what it drew"),
                              QStringLiteral("PROJECT"));
}

} // namespace

PageOptions::PageOptions(Use use)
    : use(use)
    , page(pageOption(use))
    , pageFile(QStringLiteral("page-file"),
               PageOptionsWords::tr("which page of the project, default index.html or its only "
                                    "page"),
               QStringLiteral("FILE"))
    , library(QStringLiteral("library"),
              PageOptionsWords::tr("a folder of the course's starter files the page loads "
                                   "(Common/, webgl-utils, gl-matrix); repeatable"),
              QStringLiteral("DIR"))
    , urlMap(QStringLiteral("url-map"),
             PageOptionsWords::tr("answer an outside address (a CDN's link) from a local file "
                                  "or folder; repeatable"),
             QStringLiteral("PREFIX=PATH"))
    , step(QStringLiteral("page-step"),
           PageOptionsWords::tr("what a student does before looking: 'click SELECTOR', 'select "
                                "SELECTOR=VALUE', 'check SELECTOR', 'set SELECTOR=VALUE'; "
                                "repeatable"),
           QStringLiteral("STEP"))
    , frame(QStringLiteral("page-frame"),
            PageOptionsWords::tr("the frame captured, default 5 (fewer when the page stops "
                                 "drawing)"),
            QStringLiteral("N"))
    , timeout(QStringLiteral("page-timeout"),
              PageOptionsWords::tr("the time limit of one run of the page, default 20 s"),
              QStringLiteral("SECONDS"))
    , capture(QStringLiteral("capture"),
              PageOptionsWords::tr("check a capture.json of an earlier run again, without the "
                                   "browser"),
              QStringLiteral("FILE"))
    , meshes(QStringLiteral("meshes"),
             PageOptionsWords::tr("the course's meshes (the Blender cloud and tree) the page's "
                                  "normals are compared with"),
             QStringLiteral("DIR"))
    , out(QStringLiteral("page-out"),
          PageOptionsWords::tr("write capture.json and the browser's, PhongLab's and the "
                               "difference frames here"),
          QStringLiteral("DIR"))
{
}

QString pageOptionsHelp(const PageOptions &options)
{
    return PageOptionsWords::tr(
               "\nRunning the page (--page): the project's page runs in headless Chromium "
               "(WebGL on SwiftShader,\n"
               "a fixed window, a virtual clock, no network), and what it hands WebGL is "
               "captured. Then\n"
               "PhongLab draws the captured frame again and compares it with the browser's "
               "(fidelity),\n"
               "checks the normals and matrices the JavaScript sent, and with SCENE.json checks "
               "the course\n"
               "scene with the program and the values the page used. JSON adds \"page\" (keys: "
               "file, webgl,\n"
               "frame, animated, canvas, milliseconds, steps, served, refused, errors, "
               "console_errors,\n"
               "fidelity, javascript, mesh_errors).\n")
        + helpLines(options.all());
}

namespace {

QString readNumber(const QCommandLineParser &parser, const QCommandLineOption &option, int low,
                   int high, int *out)
{
    if (!parser.isSet(option))
        return {};
    bool ok = false;
    const int value = parser.value(option).toInt(&ok);
    if (!ok || value < low || value > high)
        return PageOptionsWords::tr("--%1: expected %2..%3, got '%4'")
            .arg(option.names().first())
            .arg(low)
            .arg(high)
            .arg(parser.value(option));
    *out = value;
    return {};
}

} // namespace

QString readPageOptions(const QCommandLineParser &parser, const PageOptions &options,
                        PageRequest *out)
{
    const bool check = options.use == PageOptions::Use::Check;
    out->wanted = parser.isSet(options.page) || (check && parser.isSet(options.capture));
    if (check && parser.isSet(options.page) && parser.isSet(options.capture))
        return PageOptionsWords::tr("--page runs the page, --capture checks an earlier run: "
                                    "give one");
    for (const QCommandLineOption *o :
         {&options.library, &options.urlMap, &options.step, &options.frame, &options.timeout})
        if (parser.isSet(*o) && !parser.isSet(options.page))
            return PageOptionsWords::tr("--%1 is about the page of --%2")
                .arg(o->names().first(), options.page.names().first());
    if (options.use == PageOptions::Use::Check)
        out->run.folders.project = parser.value(options.page);
    if (!out->run.folders.project.isEmpty() && !QFileInfo(out->run.folders.project).isDir())
        return PageOptionsWords::tr("--page: %1 is not a folder").arg(out->run.folders.project);
    if (check) {
        if (parser.isSet(options.pageFile) && !parser.isSet(options.page))
            return PageOptionsWords::tr("--page-file is about the page of --page");
        out->run.pageFile = parser.value(options.pageFile);
        out->captureFile = parser.value(options.capture);
        out->outFolder = parser.value(options.out);
    }
    for (const QString &library : parser.values(options.library)) {
        if (!QFileInfo(library).isDir())
            return PageOptionsWords::tr("--library: %1 is not a folder").arg(library);
        out->run.folders.libraries.push_back(library);
    }
    for (const QString &entry : parser.values(options.urlMap)) {
        const qsizetype at = entry.indexOf(QLatin1Char('='));
        if (at <= 0 || !QFileInfo::exists(entry.mid(at + 1)))
            return PageOptionsWords::tr("--url-map: expected PREFIX=PATH of an existing file or "
                                        "folder, got '%1'")
                .arg(entry);
        out->run.folders.urlMap.emplace_back(entry.left(at), entry.mid(at + 1));
    }
    out->run.steps = parser.values(options.step);
    int seconds = 20;
    for (const QString &wrong : {readNumber(parser, options.frame, 1, 600, &out->run.frames),
                                 readNumber(parser, options.timeout, 1, 600, &seconds)})
        if (!wrong.isEmpty())
            return wrong;
    out->run.timeLimitMs = qint64(seconds) * 1000;
    out->framesGiven = parser.isSet(options.frame);
    out->meshesFolder = parser.value(options.meshes);
    if (!out->meshesFolder.isEmpty() && !QFileInfo(out->meshesFolder).isDir())
        return PageOptionsWords::tr("--meshes: %1 is not a folder").arg(out->meshesFolder);
    if (parser.isSet(options.meshes) && !out->wanted)
        return PageOptionsWords::tr("--meshes compares a page's normals: give --%1")
            .arg(options.use == PageOptions::Use::Grade ? QStringLiteral("pages")
                                                        : QStringLiteral("page or --capture"));
    return {};
}

} // namespace phonglab::cli
