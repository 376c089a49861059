#include "GradeRun.h"

#include "cli/check/CheckSteps.h"
#include "cli/common/CliCommon.h"
#include "cli/common/SceneStages.h"
#include "render/gl/QtImages.h"

#include <QCoreApplication>
#include <QDir>
#include <QEventLoop>
#include <QFileInfo>
#include <QImageReader>

#include <cstdio>
#include <unistd.h>

namespace phonglab::cli {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct GradeRunWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::cli::GradeRun)
};

namespace {

int enabledLights(const Scene &scene)
{
    return int(std::count_if(scene.lights.begin(), scene.lights.end(),
                             [](const PointLight &l) { return l.enabled; }));
}

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

QString submissionFolder(const GradeResults &results, int submission)
{
    return QStringLiteral("images/%1-%2")
        .arg(submission + 1, 3, 10, QLatin1Char('0'))
        .arg(fileSlug(
            results.submissions[std::size_t(submission)].name
            + (results.submissions[std::size_t(submission)].program.isEmpty()
                   ? QString()
                   : QLatin1Char('-') + results.submissions[std::size_t(submission)].program)));
}

void failRow(GradeRow &row, GradeVerdict verdict, const QString &file, const QString &message)
{
    row.verdict = verdict;
    row.outcome.errors.push_back(inputError(file, message));
}

// No image of a row that drew none (and no folder left empty for it).
void dropImage(GradeRow &row, const QString &outFolder)
{
    QDir out(outFolder);
    out.remove(row.yoursImage);
    out.rmdir(QFileInfo(row.yoursImage).path());
    row.yoursImage.clear();
}

} // namespace

GradeRun::GradeRun(GradeResults &results, QString executable, int jobs, GradedChildLimits limits)
    : m_results(results)
    , m_executable(std::move(executable))
    , m_jobs(std::max(1, jobs))
    , m_limits(limits)
    , m_tty(isatty(fileno(stderr)) != 0)
{
}

Result<> GradeRun::prepareReferences()
{
    for (std::size_t i = 0; i < m_results.scenes.size(); ++i) {
        const GradeScene &scene = m_results.scenes[i];
        QString error;
        if (!referenceFor(int(i), scene.scene, &error))
            return fail(GradeRunWords::tr("%1: no exact image: %2").arg(scene.path, error));
    }
    if (m_tty)
        std::fprintf(stderr, "\r\033[K");
    return {};
}

const CheckReference *GradeRun::referenceFor(int scene, const Scene &checked, QString *error)
{
    const std::pair key{scene, enabledLights(checked)};
    if (const auto found = m_references.find(key); found != m_references.end())
        return &found->second;
    const GradeScene &s = m_results.scenes[std::size_t(scene)];
    const auto progress = [&](double done) {
        if (m_tty)
            std::fprintf(stderr, "\r\033[K%s",
                         GradeRunWords::tr("grade: the exact image of %1, %2 %")
                             .arg(s.label, QString::number(int(done * 100)))
                             .toLocal8Bit()
                             .constData());
        return true;
    };
    Result<CheckReference> made =
        makeCheckReference(checked, s.objectMeshes, m_results.settings.size.width(),
                           m_results.settings.size.height(), progress);
    if (!made) {
        *error = made.error();
        return nullptr;
    }
    return &m_references.emplace(key, std::move(*made)).first->second;
}

QString GradeRun::exactImageFor(int scene, int lights, PhongEquation equation,
                                const CheckReference &reference)
{
    QString name = QStringLiteral("images/%1-exact").arg(m_results.scenes[std::size_t(scene)].slug);
    if (lights != enabledLights(m_results.scenes[std::size_t(scene)].scene))
        name += QStringLiteral("-%1-lights").arg(lights);
    if (equation == PhongEquation::Slide && !reference.slide.color.empty())
        name += QStringLiteral("-slide");
    name += QStringLiteral(".png");
    if (m_exactImages.count(name))
        return m_exactImages[name];
    const RgbImage exact = equation == PhongEquation::Slide && !reference.slide.color.empty()
        ? reference.slide.toImage(reference.background)
        : reference.exactImage;
    const bool written =
        bool(writePng(toQImage(exact), m_results.settings.outFolder + QLatin1Char('/') + name));
    return m_exactImages[name] = written ? name : QString();
}

QStringList GradeRun::childArguments(const GradeRow &row) const
{
    const GradeScene &scene = m_results.scenes[std::size_t(row.scene)];
    const Submission &s = m_results.submissions[std::size_t(row.submission)];
    const QSize size = m_results.settings.size;
    // --shading: a stage the student left out is the method's shipped one,
    // never the shader a teacher's scene names.
    QStringList args{QStringLiteral("check"),
                     QFileInfo(scene.path).absoluteFilePath(),
                     QStringLiteral("--shading"),
                     shadingName(scene.scene.shading),
                     QStringLiteral("--size"),
                     QStringLiteral("%1x%2").arg(size.width()).arg(size.height()),
                     QStringLiteral("--draw-only"),
                     m_results.settings.outFolder + QLatin1Char('/') + row.yoursImage};
    if (!s.vertex.isEmpty())
        args << QStringLiteral("--vertex") << s.vertex;
    if (!s.fragment.isEmpty())
        args << QStringLiteral("--fragment") << s.fragment;
    // The page's values, where the teacher's --bind says nothing of them.
    for (const auto &[name, value] : s.pageConstants) {
        if (m_results.settings.overrides.bindings.count(name)
            || m_results.settings.overrides.constants.count(name))
            continue;
        QStringList numbers;
        for (double v : value)
            numbers << QString::number(v, 'g', 17);
        args << QStringLiteral("--bind")
             << name + QLatin1Char('=') + numbers.join(QLatin1Char(','));
    }
    return args + m_results.settings.overrides.arguments();
}

void GradeRun::setJournal(GradeJournal *journal, QHash<QString, GradedChildEnd> finished)
{
    m_journal = journal;
    m_finished = std::move(finished);
}

QString GradeRun::rowKey(const GradeRow &row) const
{
    const Submission &s = m_results.submissions[std::size_t(row.submission)];
    return QStringList{s.name, s.program, m_results.scenes[std::size_t(row.scene)].label}.join(
        QLatin1Char('\x1f'));
}

void GradeRun::run()
{
    m_clock.start();
    std::vector<GradeRow> &rows = m_results.rows;
    rows.clear();
    for (std::size_t s = 0; s < m_results.submissions.size(); ++s)
        for (std::size_t c = 0; c < m_results.scenes.size(); ++c) {
            GradeRow row;
            row.submission = int(s);
            row.scene = int(c);
            const Submission &submission = m_results.submissions[s];
            if (!submission.error.isEmpty()) {
                failRow(row, GradeVerdict::Error, submission.name, submission.error);
                ++m_done;
            } else {
                const QString folder = submissionFolder(m_results, int(s));
                QDir(m_results.settings.outFolder).mkpath(folder);
                row.yoursImage =
                    QStringLiteral("%1/%2-yours.png").arg(folder, m_results.scenes[c].slug);
                // Finished by a stopped run: checked again from its journal.
                const auto done = m_finished.constFind(rowKey(row));
                if (done != m_finished.constEnd()
                    && (done->kind != GradedChildEnd::Kind::Answered
                        || QFileInfo::exists(m_results.settings.outFolder + QLatin1Char('/')
                                             + row.yoursImage))) {
                    row.seconds = done->seconds;
                    m_childSeconds += done->seconds;
                    check(row, *done);
                    ++m_done;
                } else {
                    m_waiting.push_back({int(rows.size())});
                }
            }
            rows.push_back(std::move(row));
        }
    QEventLoop loop;
    while (m_running < m_jobs && !m_waiting.empty())
        startNext();
    while (m_running > 0)
        loop.processEvents(QEventLoop::WaitForMoreEvents);
    if (m_tty)
        std::fprintf(stderr, "\r\033[K");
}

void GradeRun::startNext()
{
    const Job job = m_waiting.front();
    m_waiting.pop_front();
    ++m_running;
    auto *child = new GradedChild(
        m_executable, childArguments(m_results.rows[std::size_t(job.row)]), m_limits, this);
    connect(child, &GradedChild::ended, this,
            [this, child, row = job.row](const GradedChildEnd &end) {
                child->deleteLater();
                onEnded(row, end);
            });
    child->start();
    showProgress();
}

void GradeRun::onEnded(int rowIndex, const GradedChildEnd &end)
{
    --m_running;
    GradeRow &row = m_results.rows[std::size_t(rowIndex)];
    row.seconds = end.seconds;
    m_childSeconds += end.seconds;
    if (m_journal)
        m_journal->record(rowKey(row), end);
    check(row, end);
    ++m_done;
    while (m_running < m_jobs && !m_waiting.empty())
        startNext();
    showProgress();
}

void GradeRun::check(GradeRow &row, const GradedChildEnd &end)
{
    const QString out = m_results.settings.outFolder + QLatin1Char('/');
    if (end.kind != GradedChildEnd::Kind::Answered) {
        failRow(row,
                end.kind == GradedChildEnd::Kind::TimedOut ? GradeVerdict::Timeout
                                                           : GradeVerdict::Crash,
                QString(), end.message);
        dropImage(row, m_results.settings.outFolder);
        return;
    }
    // cleanPath: "class/" as typed would leave "class//alice" unmatched.
    const QString classRoot =
        QDir::cleanPath(QFileInfo(m_results.settings.classRoot).absoluteFilePath());
    CheckDrawing drawing = drawingFromJson(end.answer);
    row.outcome = std::move(drawing.outcome);
    // What the project said beside (an unlit program left out) goes with it.
    row.outcome.notes =
        m_results.submissions[std::size_t(row.submission)].notes + row.outcome.notes;
    makeRelative(&row.outcome, classRoot);
    row.verdict = GradeVerdict::Error;
    if (!row.outcome.errors.empty()) {
        dropImage(row, m_results.settings.outFolder);
        return;
    }
    QImageReader reader(out + row.yoursImage);
    const QImage image = reader.read();
    if (image.isNull() || image.size() != m_results.settings.size) {
        failRow(row, GradeVerdict::Crash, QString(),
                GradeRunWords::tr("the check drew no image (%1)").arg(reader.errorString()));
        dropImage(row, m_results.settings.outFolder);
        return;
    }
    const GradeScene &scene = m_results.scenes[std::size_t(row.scene)];
    const Scene checked = sceneForCheck(scene.scene, drawing.lightCapacity);
    QString error;
    const CheckReference *reference = referenceFor(row.scene, checked, &error);
    if (!reference) {
        failRow(row, GradeVerdict::Error, scene.path,
                GradeRunWords::tr("no reference: %1").arg(error));
        return;
    }
    const GradeSettings &settings = m_results.settings;
    const CheckOutcome::Verdict verdict = checkDrawing(
        &row.outcome, image, *reference, settings.toleranceSteps, settings.equation, scene.path);
    if (verdict == CheckOutcome::Verdict::Error)
        return;
    row.verdict = verdict == CheckOutcome::Verdict::Pass ? GradeVerdict::Pass : GradeVerdict::Fail;
    const PhongEquation equation = row.outcome.report.equation;
    row.exactImage = exactImageFor(row.scene, enabledLights(checked), equation, *reference);
    const QString heatmap =
        QString(row.yoursImage).replace(QLatin1String("-yours.png"), QLatin1String("-heatmap.png"));
    if (writePng(toQImage(checkHeatmap(toRgbImage(image), *reference, equation)), out + heatmap))
        row.heatmapImage = heatmap;
}

void GradeRun::showProgress()
{
    if (!m_tty)
        return;
    const int total = int(m_results.rows.size());
    const int checked = m_done;
    QString text = GradeRunWords::tr("grade: %1 of %2 checked").arg(checked).arg(total);
    if (checked > 0 && checked < total) {
        const double perCheck = m_clock.elapsed() / 1000.0 / checked;
        text += GradeRunWords::tr(", about %1 s left").arg(qRound(perCheck * (total - checked)));
    }
    std::fprintf(stderr, "\r\033[K%s", text.toLocal8Bit().constData());
    std::fflush(stderr);
}

} // namespace phonglab::cli
