#include "GradeRun.h"

#include "GradeRowCheck.h"
#include "cli/check/CheckSteps.h"
#include "cli/common/CliCommon.h"

#include <QCoreApplication>
#include <QDir>
#include <QEventLoop>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QtConcurrent/QtConcurrentRun>

#include <cassert>

namespace phonglab::cli {

namespace {

QString submissionFolder(const GradeResults &results, int submission)
{
    const Submission &s = results.submissions[std::size_t(submission)];
    return QStringLiteral("images/%1-%2")
        .arg(submission + 1, 3, 10, QLatin1Char('0'))
        .arg(fileSlug(s.name + (s.program.isEmpty() ? QString() : QLatin1Char('-') + s.program)));
}

} // namespace

GradeRun::GradeRun(GradeResults &results, QString executable, int jobs, GradedChildLimits limits)
    : m_results(results)
    , m_executable(std::move(executable))
    , m_jobs(std::max(1, jobs))
    , m_limits(limits)
{
    m_checkers.setMaxThreadCount(m_jobs);
}

GradeRun::~GradeRun()
{
    m_checkers.waitForDone(); // the checks write into m_results
}

Result<> GradeRun::prepareReferences()
{
    const Result<> prepared =
        m_references.prepare([this](const QString &line) { m_progress.show(line); });
    m_progress.clear();
    return prepared;
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
    // Every row first: the checking threads hold references into `rows`,
    // which must not grow under them.
    std::vector<std::pair<int, GradedChildEnd>> resumed;
    for (std::size_t s = 0; s < m_results.submissions.size(); ++s)
        for (std::size_t c = 0; c < m_results.scenes.size(); ++c) {
            GradeRow row;
            row.submission = int(s);
            row.scene = int(c);
            const Submission &submission = m_results.submissions[s];
            const int index = int(rows.size());
            if (!submission.error.isEmpty()) {
                row.findings.errors.push_back(inputError(submission.name, submission.error));
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
                    resumed.emplace_back(index, *done);
                } else {
                    m_waiting.push_back(index);
                }
            }
            rows.push_back(std::move(row));
        }
    for (const auto &[index, end] : resumed)
        checkInBackground(index, end);
    startChildren();
    QEventLoop loop;
    while (m_running > 0 || m_checking > 0)
        loop.processEvents(QEventLoop::WaitForMoreEvents);
    assert(m_waiting.empty() && m_done == int(rows.size()));
    // No folder left empty for a submission none of whose rows drew.
    for (std::size_t s = 0; s < m_results.submissions.size(); ++s)
        QDir(m_results.settings.outFolder).rmdir(submissionFolder(m_results, int(s)));
    m_progress.clear();
}

void GradeRun::startChildren()
{
    while (m_running < m_jobs && !m_waiting.empty())
        startNext();
}

void GradeRun::startNext()
{
    const int row = m_waiting.front();
    m_waiting.pop_front();
    ++m_running;
    assert(m_running <= m_jobs); // a slot of the pool per child
    auto *child = new GradedChild(m_executable, childArguments(m_results.rows[std::size_t(row)]),
                                  m_limits, this);
    connect(child, &GradedChild::ended, this, [this, child, row](const GradedChildEnd &end) {
        child->deleteLater();
        onEnded(row, end);
    });
    child->start();
    showProgress();
}

void GradeRun::onEnded(int rowIndex, const GradedChildEnd &end)
{
    assert(m_running > 0);
    --m_running;
    GradeRow &row = m_results.rows[std::size_t(rowIndex)];
    row.seconds = end.seconds;
    if (m_journal)
        m_journal->record(rowKey(row), end);
    checkInBackground(rowIndex, end);
    startChildren();
}

void GradeRun::checkInBackground(int rowIndex, const GradedChildEnd &end)
{
    ++m_checking;
    auto *watcher = new QFutureWatcher<void>(this);
    connect(watcher, &QFutureWatcher<void>::finished, this, [this, watcher] {
        watcher->deleteLater();
        assert(m_checking > 0);
        --m_checking;
        ++m_done;
        showProgress();
    });
    GradeRow *row = &m_results.rows[std::size_t(rowIndex)];
    watcher->setFuture(QtConcurrent::run(
        &m_checkers, [this, row, end] { checkRow(*row, end, m_results, m_references); }));
}

void GradeRun::showProgress()
{
    if (!m_progress.onTerminal())
        return;
    const int total = int(m_results.rows.size());
    const int checked = m_done;
    QString text = GradeRun::tr("grade: %1 of %2 checked").arg(checked).arg(total);
    if (checked > 0 && checked < total) {
        const double perCheck = m_clock.elapsed() / 1000.0 / checked;
        text += GradeRun::tr(", about %1 s left").arg(qRound(perCheck * (total - checked)));
    }
    m_progress.show(text);
}

} // namespace phonglab::cli
