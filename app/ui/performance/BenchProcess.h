#pragma once
#include "bench/BenchResult.h"
#include "bench/ErrorBudget.h"
#include "core/scene/Scene.h"
#include "core/support/Result.h"

#include <QObject>
#include <QProcess>
#include <QSize>
#include <QTemporaryDir>
#include <memory>
#include <vector>

namespace phonglab {

// Runs `phonglab bench` on the scene in the window, as a child process: the
// measurement gets a context of its own, the window stays responsive, and a
// driver crash in a timed frame cannot take the user's edits with it. The
// scene goes over as a temporary file with the current camera and lights
// and absolute mesh paths; the rows come back from results.csv.
class BenchProcess : public QObject
{
    Q_OBJECT

public:
    explicit BenchProcess(QObject *parent = nullptr);
    ~BenchProcess() override;

    // The detail levels the dock measures: halving down to 1/64.
    static std::vector<double> detailLevels();

    // Measures `scene` with its own lights at `size`. A failure when the run
    // cannot start (one is running, the scene cannot be written).
    Result<> start(const Scene &scene, const QSize &size, const ErrorBudget &budget);
    bool isRunning() const;
    void cancel();

    // The `phonglab` program that measures: phonglabExecutable().
    QString executable() const;

signals:
    void progress(int done, int total, const QString &stage);
    // rows empty and error set on failure or cancel.
    void finished(const std::vector<phonglab::BenchRow> &rows, const QString &error);

private:
    void readProgress();
    void processFinished(int exitCode, QProcess::ExitStatus status);

    std::unique_ptr<QTemporaryDir> m_dir;
    QProcess *m_process = nullptr;
    QByteArray m_stderr;     // unparsed tail
    QString m_lastErrorLine; // "phonglab: error: ..." if the run printed one
    bool m_cancelled = false;
};

} // namespace phonglab
