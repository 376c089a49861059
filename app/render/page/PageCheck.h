#pragma once
#include "core/check/MistakeSourceLines.h"
#include "core/check/ShaderCheck.h"
#include "core/page/JavaScriptFinding.h"
#include "core/page/PageCapture.h"
#include "core/page/PageFidelity.h"
#include "core/page/PageRun.h"
#include "core/scene/PageSettings.h"

#include <QByteArray>
#include <QImage>
#include <QJsonObject>
#include <QStringList>

#include <map>
#include <optional>
#include <vector>

namespace phonglab {

// What is run and checked: the page (or a capture file), the course's
// meshes, where the capture and frames go. cli/page/PageOptions reads it
// from the command line; `grade --pages` fills `run.folders.project` per
// submission; the window from its project.
struct PageRequest {
    bool wanted = false; // --page or --capture given
    PageRunOptions run;
    QString captureFile;      // --capture
    QString meshesFolder;     // --meshes
    QString outFolder;        // --page-out
    bool framesGiven = false; // --page-frame
};

// A student's page checked as the browser ran it (phonglab check --page,
// grade --pages, the window's Run the Page): the capture (core/page), then
//  - fidelity: PhongLab draws the captured frame again and compares it with
//    the browser's (a difference is PhongLab's, never the student's);
//  - the JavaScript half: the normals sent against the course's meshes,
//    the normal matrix against the model-view sent, the light's w.
// The course scene checked with the page's program and values is the
// caller's (CheckCommand), from litPageProgram().
struct PageCheck {
    QString error; // the page could not be run or its capture read: nothing checked
    QByteArray captureJson;
    PageCapture capture;
    qint64 milliseconds = 0; // the browser's run, start to stop; 0 for --capture
    std::optional<PageFidelity> fidelity;
    QString fidelityError; // why the frame could not be drawn again
    QStringList notReplayed;
    QByteArray replayPixels; // RGBA, bottom row first
    std::vector<JavaScriptFinding> javascript;
    QStringList meshErrors; // --meshes files that could not be read
    // The student's own scene (core/page/PageScene) against the browser's
    // pixels; `ownSceneWhy` says why it was not checked.
    std::optional<CheckReport> ownScene;
    QString ownSceneWhy;
    RgbImage ownSceneExact;   // its exact image
    RgbImage ownSceneHeatmap; // the browser's frame against it
    // The lines of the files handed in that compute what the own scene's
    // mistakes break (core/check/MistakeSourceLines), by mistake key.
    std::vector<std::pair<QString, SourceLine>> ownSceneLines;

    bool ok() const { return error.isEmpty(); }
    bool javascriptMistakes() const;
    // The own scene checked and off, where PhongLab draws the page as the
    // browser did (else the difference may be PhongLab's).
    bool ownSceneFails() const;
};

// The scene's "page" under the command line's (or the window's): its steps where no
// --page-step is given, its libraries after --library's, its meshes and
// frame where the options name none; paths relative to `sceneFolder`.
void takeScenePage(PageRequest *request, const PageSettings &settings, const QString &sceneFolder);

PageCheck checkPage(const PageRequest &request);

// The same in two halves: the capture (the browser run, or the file read;
// safe on any thread, so that grade runs several pages at once), then its
// checks (on the thread that may make GL contexts).
struct PageCapturing {
    QByteArray json;
    qint64 milliseconds = 0;
    QString error;
};
PageCapturing capturePage(const PageRequest &request);
PageCheck checkCapturedPage(const PageCapturing &captured, const PageRequest &request);

// A captured RGBA frame (bottom row first) as a picture, row 0 on top;
// null when the bytes are not the size's. And the fidelity's difference:
// dark green equal, green within its tolerance, yellow to red beyond.
QImage pageFrameImage(const QByteArray &rgba, QSize size);
QImage pageDifferenceImage(const PageCheck &check);

// --page-out: capture.json, browser.png, phonglab.png and difference.png
// (the fidelity: green where equal, yellow to red where not), and where the
// own scene was checked exact.png and heatmap.png (as check --diff draws it).
QString writePageOutputs(const PageCheck &check, const QString &folder);

// For a check of the course scene with the page's program
// (core/page/PageProgram): its stages as compiled, on the student's own
// lines ("FILE#KEY") where the page compiled them unchanged, else files in
// `compiledFolder` (page.vert, page.frag); the values the page gave the uniforms no meaning binds (a
// mode switch: no --bind mode=1 needed). Empty paths, and a note saying
// why, when the page drew no program that lights.
struct PageStages {
    QString vertexPath;
    QString fragmentPath;
    std::map<QString, std::vector<double>> constants;
    QString note;
};
PageStages pageStagesForScene(const PageCheck &check, const QString &project,
                              const QString &compiledFolder);

} // namespace phonglab
