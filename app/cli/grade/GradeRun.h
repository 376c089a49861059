#pragma once
#include "GradeJournal.h"
#include "GradeReferences.h"
#include "GradeRows.h"
#include "cli/check/GradedChild.h"
#include "cli/common/ProgressLine.h"

#include <QElapsedTimer>
#include <QObject>
#include <QThreadPool>

#include <deque>

namespace phonglab::cli {

// The checks of `grade`, as a pool: one child per submission × scene, `jobs`
// at once, and each row checked (checkRow) on a thread of its own as its
// child ends, while the next child already draws; the exact images come
// from one GradeReferences. Fills results.rows. A progress line on a
// terminal.
class GradeRun : public QObject
{
    Q_OBJECT

public:
    GradeRun(GradeResults &results, QString executable, int jobs, GradedChildLimits limits);
    ~GradeRun() override;

    // The exact images of every scene, before any child starts (they use
    // every core). Errors name the scene.
    Result<> prepareReferences();
    // Each child's end goes to `journal` as it comes; the rows in
    // `finished` (by rowKey) are checked from it and drawn no more (--resume).
    void setJournal(GradeJournal *journal, QHash<QString, GradedChildEnd> finished);
    // Runs every check; returns when the last has ended.
    void run();
    // What names a row in the journal: submission, program and scene.
    QString rowKey(const GradeRow &row) const;

private:
    void startNext();
    void onEnded(int row, const GradedChildEnd &end);
    // checkRow() on the checking threads; the row counts as done when it returns.
    void checkInBackground(int row, const GradedChildEnd &end);
    void startChildren();
    QStringList childArguments(const GradeRow &row) const;
    void showProgress();

    GradeResults &m_results;
    GradeReferences m_references{m_results};
    QString m_executable;
    int m_jobs = 1;
    GradedChildLimits m_limits;
    std::deque<int> m_waiting; // rows whose child has not started
    int m_running = 0;         // children drawing
    int m_checking = 0;        // rows being checked
    int m_done = 0;
    QElapsedTimer m_clock;
    ProgressLine m_progress{ProgressLine::Elsewhere::Nothing};
    QThreadPool m_checkers; // as many threads as jobs: a check beside each child
    GradeJournal *m_journal = nullptr;
    QHash<QString, GradedChildEnd> m_finished;
};

} // namespace phonglab::cli
