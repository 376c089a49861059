#pragma once
#include "PageServer.h"
#include "core/support/Result.h"

#include <QByteArray>
#include <QSize>
#include <QString>
#include <QStringList>

#include <functional>
#include <vector>

namespace phonglab {

// How a student's page is run (phonglab check --page, grade --pages, the
// window's "Run the page"). Deterministic by construction: a fixed window,
// a virtual clock (core/page/capture.js), a seeded Math.random, the time
// zone UTC, the locale en-US, no antialiasing.
struct PageRunOptions {
    PageFolders folders;
    QString pageFile;  // relative to the project; empty: index.html, or its only page
    QStringList steps; // what a student would do first: "select #shading=phong", "click #go"
    int frames = 5;    // the frame captured (fewer when the page stops drawing)
    QSize window{800, 600};
    qint64 timeLimitMs = 20000;
    quint32 seed = 1;
    QString browser;    // empty: BrowserPipe::executable()
    QString workFolder; // the throwaway profile goes under it; empty: a temporary folder
    // Asked now and then from the run's thread: true stops it ("cancelled").
    std::function<bool()> cancelled;
};

// One file the page asked for, and what answered it.
struct PageFetch {
    QString url;
    QString file;    // the file served; empty when refused
    QString refusal; // why not
};

struct PageRunOutput {
    QByteArray capture; // core/page/capture.js's JSON (core/page/PageCapture reads it)
    QString pageFile;   // the page run, relative to the project
    std::vector<PageFetch> requests;
    qint64 milliseconds = 0; // browser start to capture, stop included
};

// The page, or the one page of the project, relative to it; why not.
Result<QString> choosePageFile(const QString &project, const QString &pageFile);

// Runs the page in headless Chromium and captures what it drew. A failure
// says why in words for the student or teacher: no browser (and how to
// install it), no page, a page that did not finish in time.
Result<PageRunOutput> runPage(const PageRunOptions &options);

// The sentence for a machine without Chromium.
QString browserMissingMessage();

} // namespace phonglab
