#pragma once
#include "core/session/RecoveryJournal.h"

#include <QElapsedTimer>
#include <QObject>

class QTimer;
class QWidget;

namespace phonglab {

class ShaderDock;

// Keeps the Shaders dock's buffers in a RecoveryJournal so that no edit is
// lost to a crash or a kill: written before every compile and every 2 s while
// edits are unjournaled; cleared when everything is saved or the app exits
// cleanly. At start it offers what a dead session left behind. It also keeps
// the journal's "new program running" sentinel: set before a build (the
// compiler or the first draw may take the process down), kept while the new
// program is on probation, cleared once it has drawn a few frames.
class ShaderRecovery : public QObject
{
    Q_OBJECT

public:
    enum class Answer {
        Restore,
        Discard,
        Ask
    };

    // What the offer at start did.
    struct Outcome {
        bool restored = false;
        // The dead session was trying a new program when it died: the
        // restored text must not be compiled until the user asks.
        bool suspect = false;
        QString note;    // for the status line
        QString shading; // the shading method the restored buffers came from
    };

    explicit ShaderRecovery(ShaderDock *dock, QObject *parent = nullptr);
    ~ShaderRecovery() override;

    // Offers the newest orphaned journal (if any) and restores it into the
    // dock when the answer is yes. Ask shows a modal question on `parent`.
    Outcome offer(Answer answer, QWidget *parent);

    void setShading(const QString &shading) { m_shading = shading; }
    // Writes the journal now (before a compile). A failure is logged: the
    // journal is a safety net, editing goes on.
    void writeNow();
    // The buffers changed: journal them within the timer's period.
    void noteEdited();
    // Files were saved or replaced: forget the journal if nothing is unsaved.
    void noteFilesChanged();
    // Clean exit: the journal and the sentinel go.
    void clear();
    // Before a clean exit: unsaved buffers are offered for saving (a clean
    // exit forgets the journal). False when the user cancels.
    bool confirmUnsaved(QWidget *parent);

    // The sentinel's life: buildStarted() before the text reaches the driver,
    // then buildFailed() or programShown(); frameRendered() for each frame.
    void buildStarted(const QByteArray &hash);
    void buildFailed();
    void programShown(const QByteArray &hash);
    void frameRendered();

    RecoveryJournal &journal() { return m_journal; }
    static constexpr int kJournalPeriodMs = 2000;
    // A new program is trusted after this many frames, or one frame and this
    // long: a crash after that is not blamed on it.
    static constexpr int kProvenFrames = 3;
    static constexpr int kProvenAfterMs = 1000;

private:
    void markRunning(const QByteArray &hash);
    void clearRunning();
    void checkProbation();
    void restore(const OrphanedSession &session);
    bool ask(const OrphanedSession &session, QWidget *parent) const;
    void writeIfStale();

    ShaderDock *m_dock = nullptr;
    RecoveryJournal m_journal;
    QTimer *m_timer = nullptr;
    QString m_shading;
    bool m_stale = false;    // edited since the journal was last written
    bool m_running = false;  // a sentinel is on disk
    bool m_building = false; // the sentinel names a build not finished yet
    QByteArray m_probation;  // shown, not yet proven
    int m_probationFrames = 0;
    QElapsedTimer m_probationClock;
    QTimer *m_probationTimer = nullptr;
};

} // namespace phonglab
