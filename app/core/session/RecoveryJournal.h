#pragma once
#include "core/program/ProgramTextHash.h"
#include "core/support/Result.h"
#include <QByteArray>
#include <QDateTime>
#include <QList>
#include <QString>
#include <memory>
#include <optional>

class QLockFile;

namespace phonglab {

// One editor buffer as it was when the journal was written.
struct RecoveryBuffer {
    QString filePath; // the file the buffer was opened from ("" = none)
    QByteArray text;
    bool dirty = false; // differs from filePath's contents

    bool operator==(const RecoveryBuffer &) const = default;
};

// Everything needed to put the shader editors back as they were.
struct RecoveryRecord {
    RecoveryBuffer vertex;
    RecoveryBuffer fragment;
    QString shading;   // shadingName() of the preset the buffers came from
    QDateTime savedAt; // set by write()

    bool operator==(const RecoveryRecord &) const = default;
};

// A journal left behind by a session that did not end cleanly (crash, kill).
struct OrphanedSession {
    QString id;
    RecoveryRecord record;
    // Set when the session died while a new program was running: the hash
    // (programTextHash) of the text that program was built from.
    std::optional<QByteArray> runningHash;

    // The recovered text is the text that was running when the session died.
    bool isSuspect() const;
};

// Crash-safe journal of the shader editors, one per running session, in
// recovery/ under the app's data folder ($PHONGLAB_RECOVERY_DIR overrides it).
// Files per session <id>: <id>.journal (JSON, written atomically with
// QSaveFile, so a reader sees the old or the new version, never a torn one),
// <id>.running (the "a new program is running" sentinel) and <id>.lock, held
// while the session lives: a journal whose lock is not held (its process is
// gone) is an orphan that the next start offers to restore. No GL, no widgets.
class RecoveryJournal
{
public:
    explicit RecoveryJournal(const QString &directory = defaultDirectory());
    ~RecoveryJournal(); // releases the lock; the journal stays unless clear()ed
    RecoveryJournal(const RecoveryJournal &) = delete;
    RecoveryJournal &operator=(const RecoveryJournal &) = delete;

    static QString defaultDirectory();
    QString directory() const { return m_directory; }
    QString sessionId() const { return m_sessionId; }
    QString journalPath() const { return filePath(m_sessionId, kJournalSuffix); }
    QString sentinelPath() const { return filePath(m_sessionId, kSentinelSuffix); }

    // This session's journal. Creates the folder and takes the session lock
    // on first use. A failure with the reason when it cannot be written.
    Result<> write(const RecoveryRecord &record);
    Result<RecoveryRecord> read() const;
    bool hasJournal() const;
    // Removes this session's journal and sentinel (clean exit, all saved).
    void clear();

    // The sentinel: written before a new program first runs, cleared once it
    // has drawn frames without taking the process down.
    Result<> markRunning(const QByteArray &textHash);
    void clearRunning();
    std::optional<QByteArray> runningHash() const;

    // Sessions that ended without clearing their journal, newest first.
    // Sessions still running (lock held) are not listed.
    QList<OrphanedSession> orphans() const;
    // Deletes an orphan's files (after restoring or discarding it).
    void discard(const QString &sessionId);

    // Reads any session's journal file; a failure when it is missing,
    // unreadable, or not a complete PhongLab journal.
    static Result<RecoveryRecord> readFile(const QString &path);

    static constexpr const char *kJournalSuffix = ".journal";
    static constexpr const char *kSentinelSuffix = ".running";
    static constexpr const char *kLockSuffix = ".lock";

private:
    Result<> ensureSession();
    bool isSessionAlive(const QString &id) const;
    QString filePath(const QString &id, const char *suffix) const;

    QString m_directory;
    QString m_sessionId;
    std::unique_ptr<QLockFile> m_lock;
};

} // namespace phonglab
