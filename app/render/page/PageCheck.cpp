#include "PageCheck.h"

#include "core/page/PageMatrices.h"
#include "core/page/PageNormals.h"
#include "core/page/PageProgram.h"
#include "core/page/PageScene.h"
#include "core/project/ProjectPrograms.h"
#include "mesh/import/MeshFilePrecheck.h"
#include "mesh/loading/MeshLoader.h"
#include "render/draw/OffscreenRenderer.h"
#include "render/gl/QtImages.h"
#include "render/page/PageReplay.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QSaveFile>

#include <tuple>

namespace phonglab {

struct PageCheckWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::PageCheck)
};

namespace {

QString key(const char *name)
{
    return QString::fromLatin1(name);
}

std::vector<CourseMesh> courseMeshes(const QString &folder, QStringList *errors)
{
    std::vector<CourseMesh> out;
    if (folder.isEmpty())
        return out;
    const QDir dir(folder);
    for (const QString &name : dir.entryList(QDir::Files, QDir::Name)) {
        if (!meshFileFormatForPath(name))
            continue;
        const MeshLoadResult loaded = loadMesh(dir.filePath(name));
        if (loaded.ok())
            out.push_back({name, *loaded.mesh});
        else
            errors->push_back(QStringLiteral("%1: %2").arg(dir.filePath(name), loaded.error));
    }
    return out;
}

void replay(PageCheck *check)
{
    OffscreenRenderer offscreen;
    if (const Result<> made = offscreen.create(); !made) {
        check->fidelityError = made.error();
        return;
    }
    offscreen.makeCurrent();
    const Result<ReplayedFrame> frame = replayCapture(check->capture);
    if (!frame) {
        check->fidelityError = frame.error();
        return;
    }
    check->notReplayed = frame->notReplayed;
    check->replayPixels = frame->pixels;
    check->fidelity =
        comparePageFrames(check->capture.pixels, frame->pixels, check->capture.canvas);
}

// Each stage of the own scene's program as the student wrote it: in its
// file where the page compiled it unchanged, else the compiled text itself,
// under the stage's name.
std::vector<ShaderStageText> stagesAsHandedIn(const PageCheck &check, const Project &project)
{
    std::vector<ShaderStageText> out;
    const std::optional<PageProgram> lit = litPageProgram(check.capture);
    if (!lit)
        return out;
    for (const auto &[stage, text] : {std::pair{ShaderStage::Vertex, lit->program->vertex},
                                      std::pair{ShaderStage::Fragment, lit->program->fragment}}) {
        const ProjectShader *shader = stageInProject(project, stage, text);
        const bool vertex = stage == ShaderStage::Vertex;
        // A project's shader laid out as in its file (ProjectShader::code):
        // every line a finding names is the file's.
        out.push_back({shader
                           ? QFileInfo(shader->file).fileName()
                           : (vertex ? QStringLiteral("page.vert") : QStringLiteral("page.frag")),
                       shader ? QString::fromUtf8(shader->code) : text, vertex});
    }
    return out;
}

std::vector<std::pair<QString, SourceLine>> ownSceneLines(const PageCheck &check,
                                                          const PageRequest &request)
{
    std::vector<std::pair<QString, SourceLine>> out;
    if (!check.ownScene || check.ownScene->passed() || request.run.folders.project.isEmpty())
        return out;
    const std::vector<ShaderStageText> stages =
        stagesAsHandedIn(check, readProject(request.run.folders.project));
    for (const MistakeFinding &f : check.ownScene->diagnosis.findings)
        for (const SourceLine &line : mistakeSourceLines(f.key, stages))
            out.emplace_back(shaderMistakeKey(f.key), line);
    return out;
}

void checkOwnScene(PageCheck *check, const PageRequest &request)
{
    Result<PageSceneCheck> checked = checkPageScene(check->capture);
    if (!checked) {
        check->ownSceneWhy = checked.error();
        return;
    }
    check->ownScene = std::move(checked->report);
    check->ownSceneLines = ownSceneLines(*check, request);
    check->ownSceneExact = std::move(checked->exact);
    check->ownSceneHeatmap = std::move(checked->heatmap);
}

Result<QByteArray> obtainCapture(const PageRequest &request, qint64 *milliseconds)
{
    if (!request.captureFile.isEmpty()) {
        QFile file(request.captureFile);
        if (!file.open(QIODevice::ReadOnly))
            return fail(QStringLiteral("%1: %2").arg(request.captureFile, file.errorString()));
        return file.readAll();
    }
    PageRunOptions options = request.run;
    options.workFolder = request.outFolder;
    if (!options.workFolder.isEmpty() && !QDir().mkpath(options.workFolder))
        return fail(PageCheckWords::tr("%1: cannot make the folder").arg(options.workFolder));
    const Result<PageRunOutput> run = runPage(options);
    if (!run)
        return fail(run.error());
    *milliseconds = run->milliseconds;
    return run->capture;
}

} // namespace

bool PageCheck::ownSceneFails() const
{
    return ownScene && ownScene->comparable() && !ownScene->passed() && fidelity
        && fidelity->faithful();
}

bool PageCheck::javascriptMistakes() const
{
    return std::any_of(javascript.begin(), javascript.end(),
                       [](const JavaScriptFinding &f) { return f.mistake; });
}

void takeScenePage(PageRequest *request, const PageSettings &settings, const QString &sceneFolder)
{
    const QDir dir(sceneFolder);
    if (request->run.steps.isEmpty())
        request->run.steps = settings.steps;
    for (const QString &library : settings.libraries)
        request->run.folders.libraries.push_back(QDir::cleanPath(dir.absoluteFilePath(library)));
    if (request->meshesFolder.isEmpty() && !settings.meshes.isEmpty())
        request->meshesFolder = QDir::cleanPath(dir.absoluteFilePath(settings.meshes));
    if (!request->framesGiven && settings.frame > 0)
        request->run.frames = settings.frame;
}

PageCapturing capturePage(const PageRequest &request)
{
    PageCapturing out;
    Result<QByteArray> json = obtainCapture(request, &out.milliseconds);
    if (json)
        out.json = std::move(*json);
    else
        out.error = json.error();
    return out;
}

PageCheck checkCapturedPage(const PageCapturing &captured, const PageRequest &request)
{
    PageCheck check;
    check.milliseconds = captured.milliseconds;
    if (!captured.error.isEmpty()) {
        check.error = captured.error;
        return check;
    }
    Result<PageCapture> capture = readPageCapture(captured.json);
    if (!capture) {
        check.error = request.captureFile.isEmpty()
            ? capture.error()
            : QStringLiteral("%1: %2").arg(request.captureFile, capture.error());
        return check;
    }
    check.captureJson = captured.json;
    check.capture = std::move(*capture);
    if (check.capture.pixels.isEmpty()) {
        check.fidelityError = PageCheckWords::tr("the page drew nothing to its canvas");
        check.ownSceneWhy = check.fidelityError;
    } else {
        replay(&check);
        checkOwnScene(&check, request);
    }
    check.javascript =
        checkPageNormals(check.capture, courseMeshes(request.meshesFolder, &check.meshErrors));
    const std::vector<JavaScriptFinding> matrices = checkPageMatrices(check.capture);
    check.javascript.insert(check.javascript.end(), matrices.begin(), matrices.end());
    return check;
}

PageCheck checkPage(const PageRequest &request)
{
    return checkCapturedPage(capturePage(request), request);
}

PageStages pageStagesForScene(const PageCheck &check, const QString &project,
                              const QString &compiledFolder)
{
    PageStages stages;
    const std::optional<PageProgram> lit = litPageProgram(check.capture);
    if (!lit) {
        stages.note = PageCheckWords::tr("the page drew no program that lights: the course scene "
                                         "is not checked");
        return stages;
    }
    const Project files = readProject(project);
    const auto stagePath = [&](ShaderStage stage, const QString &text, const char *name) {
        const QString locator = stageLocatorInProject(files, stage, text);
        if (!locator.isEmpty())
            return locator;
        const QString path = QDir(compiledFolder).filePath(QString::fromLatin1(name));
        QSaveFile file(path);
        if (file.open(QIODevice::WriteOnly) && file.write(text.toUtf8()) >= 0)
            file.commit();
        return path;
    };
    stages.vertexPath = stagePath(ShaderStage::Vertex, lit->program->vertex, "page.vert");
    stages.fragmentPath = stagePath(ShaderStage::Fragment, lit->program->fragment, "page.frag");
    stages.constants = lit->constants;
    stages.note = PageCheckWords::tr("the course scene is checked with program %1 as the page "
                                     "compiled it: %2 and %3")
                      .arg(lit->program->id)
                      .arg(QFileInfo(stages.vertexPath).fileName(),
                           QFileInfo(stages.fragmentPath).fileName());
    return stages;
}

QImage pageFrameImage(const QByteArray &rgba, QSize size)
{
    if (rgba.size() != qsizetype(size.width()) * size.height() * 4)
        return {};
    // Bottom row first, as readPixels; alpha dropped: a picture of the colours.
    return QImage(reinterpret_cast<const uchar *>(rgba.constData()), size.width(), size.height(),
                  QImage::Format_RGBA8888)
        .mirrored()
        .convertToFormat(QImage::Format_RGB888);
}

QImage pageDifferenceImage(const PageCheck &check)
{
    const QImage a = pageFrameImage(check.capture.pixels, check.capture.canvas);
    const QImage b = pageFrameImage(check.replayPixels, check.capture.canvas);
    if (a.isNull() || b.isNull())
        return {};
    QImage out(a.size(), QImage::Format_RGB888);
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            const int d = std::max({std::abs(qRed(p) - qRed(q)), std::abs(qGreen(p) - qGreen(q)),
                                    std::abs(qBlue(p) - qBlue(q))});
            out.setPixel(x, y,
                         d == 0                             ? qRgb(0, 60, 0)
                             : d <= kFidelityToleranceSteps ? qRgb(0, 200, 0)
                             : d < 8                        ? qRgb(230, 220, 0)
                                                            : qRgb(230, 30, 30));
        }
    return out;
}

QString writePageOutputs(const PageCheck &check, const QString &folder)
{
    if (folder.isEmpty() || !check.ok())
        return {};
    const QDir dir(folder);
    if (!dir.mkpath(key(".")))
        return PageCheckWords::tr("%1: cannot make the folder").arg(folder);
    QSaveFile capture(dir.filePath(key("capture.json")));
    if (!capture.open(QIODevice::WriteOnly) || capture.write(check.captureJson) < 0
        || !capture.commit())
        return PageCheckWords::tr("%1: cannot write").arg(capture.fileName());
    const std::pair<const char *, QImage> pictures[] = {
        {"browser.png", pageFrameImage(check.capture.pixels, check.capture.canvas)},
        {"phonglab.png", pageFrameImage(check.replayPixels, check.capture.canvas)},
        {"difference.png", pageDifferenceImage(check)},
        {"exact.png", check.ownSceneExact.isNull() ? QImage() : toQImage(check.ownSceneExact)},
        {"heatmap.png",
         check.ownSceneHeatmap.isNull() ? QImage() : toQImage(check.ownSceneHeatmap)}};
    for (const auto &[name, image] : pictures)
        if (!image.isNull() && !image.save(dir.filePath(key(name))))
            return PageCheckWords::tr("%1: cannot write").arg(dir.filePath(key(name)));
    return {};
}

} // namespace phonglab
