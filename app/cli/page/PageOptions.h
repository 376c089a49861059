#pragma once
#include "core/scene/PageSettings.h"
#include "render/page/PageCheck.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QString>
#include <QStringList>

namespace phonglab::cli {

// Running the student's page in the browser (core/page/PageRun), the one
// way `check` and `grade` take it:
//   --page PROJECT        run the project's page in headless Chromium
//   --page-file FILE      which page of it (default index.html, or its only page)
//   --library DIR         the course's starter files the page loads (repeatable)
//   --url-map PREFIX=PATH an outside address answered from a local file or folder
//   --page-step STEP      what a student would do first (repeatable)
//   --page-frame N        the frame captured, default 5
//   --page-timeout S      the time limit of one run, default 20 s
//   --capture FILE        check a capture.json again, without the browser
//   --meshes DIR          the course's meshes the normals are compared with
//   --page-out DIR        where capture.json and the frames' pictures go
// `grade` takes --pages (each submission's page) for --page and no
// --page-file, --capture or --page-out (each submission's go to its row).
struct PageOptions {
    enum class Use {
        Check,
        Grade
    };
    explicit PageOptions(Use use = Use::Check);
    Use use;
    QCommandLineOption page;
    QCommandLineOption pageFile;
    QCommandLineOption library;
    QCommandLineOption urlMap;
    QCommandLineOption step;
    QCommandLineOption frame;
    QCommandLineOption timeout;
    QCommandLineOption capture;
    QCommandLineOption meshes;
    QCommandLineOption out;

    QList<QCommandLineOption> all() const
    {
        if (use == Use::Grade)
            return {page, library, urlMap, step, frame, timeout, meshes};
        return {page, pageFile, library, urlMap, step, frame, timeout, capture, meshes, out};
    }
    static QStringList repeatable()
    {
        return {QStringLiteral("library"), QStringLiteral("url-map"), QStringLiteral("page-step")};
    }
};

// What --help says of running the page, and the options' lines.
QString pageOptionsHelp(const PageOptions &options);

// Reads them: empty, or the message for usage().
QString readPageOptions(const QCommandLineParser &parser, const PageOptions &options,
                        PageRequest *out);

} // namespace phonglab::cli
