#include "GradeRowCheck.h"

#include "cli/check/CheckSteps.h"
#include "cli/common/PngFiles.h"
#include "render/gl/QtImages.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QImageReader>

namespace phonglab::cli {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct GradeRowCheckWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::cli::GradeRowCheck)
};

namespace {

// Paths inside the class folder, as the teacher reads them: "alice/phong.frag"
// (a link error names both stages' files in one label).
QString classRelative(const QString &path, const QString &classRoot)
{
    return QString(path).replace(classRoot + QLatin1Char('/'), QString());
}

void makeRelative(CheckFindings *outcome, const QString &classRoot)
{
    for (ShaderDiagnostic &e : outcome->errors)
        e.file = classRelative(e.file, classRoot);
    for (ShaderStageText &s : outcome->stages)
        s.path = classRelative(s.path, classRoot);
    // "FILE:LINE:COL: warning: ..." and notes name files too.
    for (QStringList *texts : {&outcome->warnings, &outcome->notes})
        for (QString &text : *texts)
            text.replace(classRoot + QLatin1Char('/'), QString());
}

void failRow(GradeRow &row, Verdict verdict, const QString &message)
{
    row.verdict = verdict;
    row.findings.errors.push_back(inputError(QString(), message));
}

// No image of a row that drew none. Its folder stays: the submission's
// other scenes may still draw into it (GradeRun removes it if it ends empty).
void dropImage(GradeRow &row, const QString &outFolder)
{
    QDir(outFolder).remove(row.yoursImage);
    row.yoursImage.clear();
}

// The child's findings, with the submission's notes and paths relative to
// the class folder. False where they end the row (the program's errors).
bool takeFindings(GradeRow &row, const CheckDrawing &drawing, const GradeResults &results)
{
    // cleanPath: "class/" as typed would leave "class//alice" unmatched.
    const QString classRoot =
        QDir::cleanPath(QFileInfo(results.settings.classRoot).absoluteFilePath());
    row.findings = drawing.findings;
    // What the project said beside (an unlit program left out) goes with it.
    row.findings.notes =
        results.submissions[std::size_t(row.submission)].notes + row.findings.notes;
    makeRelative(&row.findings, classRoot);
    row.verdict = Verdict::Error;
    return row.findings.errors.empty();
}

// The verdict of the drawn `image` against its scene, and the exact image
// and heatmap beside it.
void judge(GradeRow &row, const QImage &image, std::optional<int> lightCapacity,
           const GradeResults &results, GradeReferences &references)
{
    const GradeScene &scene = results.scenes[std::size_t(row.scene)];
    const Scene checked = sceneForCheck(scene.scene, lightCapacity);
    const Result<const CheckReference *> found = references.referenceFor(row.scene, checked);
    if (!found) {
        row.verdict = Verdict::Error;
        row.findings.errors.push_back(
            inputError(scene.path, GradeRowCheckWords::tr("no reference: %1").arg(found.error())));
        return;
    }
    const CheckReference *reference = *found;
    const GradeSettings &settings = results.settings;
    const Verdict verdict = checkDrawing(&row.findings, image, *reference, settings.toleranceSteps,
                                         settings.equation, scene.path);
    if (verdict == Verdict::Error)
        return;
    row.verdict = verdict == Verdict::Pass ? Verdict::Pass : Verdict::Fail;
    const PhongEquation equation = row.findings.report.equation;
    row.exactImage =
        references.exactImageFor(row.scene, checked.enabledLightCount(), equation, *reference);
    const QString heatmap =
        QString(row.yoursImage).replace(QLatin1String("-yours.png"), QLatin1String("-heatmap.png"));
    if (writePng(toQImage(checkHeatmap(toRgbImage(image), *reference, equation)),
                 settings.outFolder + QLatin1Char('/') + heatmap))
        row.heatmapImage = heatmap;
}

} // namespace

void checkRow(GradeRow &row, const GradedChildEnd &end, const GradeResults &results,
              GradeReferences &references)
{
    const QString outFolder = results.settings.outFolder;
    if (end.kind != GradedChildEnd::Kind::Answered) {
        failRow(row, end.kind == GradedChildEnd::Kind::TimedOut ? Verdict::Timeout : Verdict::Crash,
                end.message);
        dropImage(row, outFolder);
        return;
    }
    const CheckDrawing drawing = drawingFromJson(end.answer);
    if (!takeFindings(row, drawing, results)) {
        dropImage(row, outFolder);
        return;
    }
    QImageReader reader(outFolder + QLatin1Char('/') + row.yoursImage);
    const QImage image = reader.read();
    if (image.isNull() || image.size() != results.settings.size) {
        failRow(row, Verdict::Crash,
                GradeRowCheckWords::tr("the check drew no image (%1)").arg(reader.errorString()));
        dropImage(row, outFolder);
        return;
    }
    judge(row, image, drawing.lightCapacity, results, references);
}

} // namespace phonglab::cli
