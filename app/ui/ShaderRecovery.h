#pragma once
#include "core/RecoveryJournal.h"

#include <QObject>

class QTimer;
class QWidget;

namespace phonglab {

class ShaderDock;

// Keeps the Shaders dock's buffers in a RecoveryJournal so that no edit is
// lost to a crash or a kill: written before every compile and every 2 s while
// edits are unjournaled; cleared when everything is saved or the app exits
// cleanly. At start it offers what a dead session left behind.
class ShaderRecovery : public QObject
{
    Q_OBJECT

public:
    enum class Answer { Restore, Discard, Ask };

    // What the offer at start did.
    struct Outcome {
        bool restored = false;
        // The dead session was trying a new program when it died: the
        // restored text must not be compiled until the user asks.
        bool suspect = false;
        QString note;    // for the status line
        QString shading; // the preset the restored buffers came from
    };

    explicit ShaderRecovery(ShaderDock *dock, QObject *parent = nullptr);
    ~ShaderRecovery() override;

    // $PHONGLAB_RECOVERY_ANSWER (restore|discard) answers without a dialog.
    static Answer answerFromEnvironment();
    // Offers the newest orphaned journal (if any) and restores it into the
    // dock when the answer is yes. Ask shows a modal question on `parent`.
    Outcome offer(Answer answer, QWidget *parent);

    void setShading(const QString &shading) { m_shading = shading; }
    // Writes the journal now (before a compile). False with a reason.
    bool writeNow(QString *error = nullptr);
    // The buffers changed: journal them within the timer's period.
    void noteEdited();
    // Files were saved or replaced: forget the journal if nothing is unsaved.
    void noteFilesChanged();
    // Clean exit: the journal and the sentinel go.
    void clear();

    // The "new program running" sentinel, see RecoveryJournal.
    void markRunning(const QByteArray &hash);
    void clearRunning();

    RecoveryJournal &journal() { return m_journal; }
    static constexpr int kJournalPeriodMs = 2000;

private:
    void restore(const OrphanedSession &session);
    bool ask(const OrphanedSession &session, QWidget *parent) const;
    void writeIfStale();

    ShaderDock *m_dock = nullptr;
    RecoveryJournal m_journal;
    QTimer *m_timer = nullptr;
    QString m_shading;
    bool m_stale = false;   // edited since the journal was last written
    bool m_running = false; // a sentinel is on disk
};

} // namespace phonglab
