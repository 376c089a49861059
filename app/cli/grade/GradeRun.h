#pragma once
#include "GradeJournal.h"
#include "GradeRows.h"
#include "cli/check/GradedChild.h"
#include "core/check/ShaderCheck.h"

#include <QElapsedTimer>
#include <QObject>

#include <deque>
#include <map>

namespace phonglab::cli {

// The checks of `grade`: one child per submission × scene, `jobs` at once,
// each checked here as it ends against the exact image of its scene, made
// once (once per number of lights a shader can take, where one takes fewer
// than the scene has). Fills results.rows; writes each student's image and
// heatmap under the out folder's images/. A progress line on a terminal.
class GradeRun : public QObject
{
    Q_OBJECT

public:
    GradeRun(GradeResults &results, QString executable, int jobs, GradedChildLimits limits);

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
    struct Job {
        int row;
    };
    void startNext();
    void onEnded(int row, const GradedChildEnd &end);
    void check(GradeRow &row, const GradedChildEnd &end);
    const CheckReference *referenceFor(int scene, const Scene &checked, QString *error);
    QString exactImageFor(int scene, int lights, PhongEquation equation,
                          const CheckReference &reference);
    QStringList childArguments(const GradeRow &row) const;
    void showProgress();

    GradeResults &m_results;
    QString m_executable;
    int m_jobs = 1;
    GradedChildLimits m_limits;
    std::deque<Job> m_waiting;
    int m_running = 0;
    int m_done = 0;
    double m_childSeconds = 0.0;
    QElapsedTimer m_clock;
    bool m_tty = false;
    // By scene, then the number of lights it is checked with.
    std::map<std::pair<int, int>, CheckReference> m_references;
    std::map<QString, QString> m_exactImages; // written once each
    GradeJournal *m_journal = nullptr;
    QHash<QString, GradedChildEnd> m_finished;
};

} // namespace phonglab::cli
