#pragma once
#include <QElapsedTimer>
#include <QJsonObject>
#include <QObject>
#include <QProcess>
#include <QString>
#include <QStringList>
#include <QTimer>

namespace phonglab::cli {

// One check of `grade`, drawn by a child process: `phonglab check ...
// --draw-only OUT.png`. A student's shader may loop for minutes, crash the
// driver or make the compiler eat memory; in a child that costs that
// student's verdict, never the class's. The parent watches the wall clock
// and the child's resident memory (polled, not setrlimit: GPU drivers
// reserve far more address space than they use) and kills it past either.

struct GradedChildLimits {
    int wallClockMs = 20'000;
    qint64 memoryBytes = 2048LL * 1024 * 1024;
};

struct GradedChildEnd {
    enum class Kind {
        Answered, // the child printed its drawing
        TimedOut,
        Crashed // a signal, no answer, or over the memory limit
    };
    Kind kind = Kind::Crashed;
    QJsonObject answer; // Answered: drawingJson()
    QString message;    // TimedOut and Crashed: what happened, in a sentence
    double seconds = 0.0;
};

class GradedChild : public QObject
{
    Q_OBJECT

public:
    GradedChild(const QString &executable, const QStringList &arguments,
                const GradedChildLimits &limits, QObject *parent = nullptr);
    void start();

signals:
    void ended(const phonglab::cli::GradedChildEnd &end);

private:
    void poll();
    void finish(GradedChildEnd end);
    void onFinished(int exitCode, QProcess::ExitStatus status);
    qint64 residentBytes() const;

    QProcess m_process;
    QString m_executable;
    QStringList m_arguments;
    GradedChildLimits m_limits;
    QElapsedTimer m_clock;
    QTimer m_poll;
    bool m_ended = false;
};

// The child's side, first thing in `check --draw-only`: it dies with its
// parent, and running out of memory is an exit status, not a crash dump.
void beAGradedChild();

// With PHONGLAB_GRADE_FAULTS=1 set, a fragment shader whose text holds
// "PHONGLAB_FAULT: crash" (or "oom", "hang") makes the child crash (eat
// memory, hang) on purpose: how tests show that each way a check can die
// costs one verdict. Without the variable, nothing a student writes does.
void injectGradedChildFault(const QString &fragmentPath);

// Exit status of a child that ran out of memory.
inline constexpr int kGradedChildOutOfMemory = 3;

} // namespace phonglab::cli
