#include "RecoveryJournal.h"

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLockFile>
#include <QSaveFile>
#include <QStandardPaths>
#include <QStringDecoder>
#include <algorithm>
#include <atomic>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct RecoveryJournalWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::RecoveryJournal)
};

namespace {

constexpr auto kFormat = "phonglab-recovery";
constexpr int kVersion = 1;

bool isUtf8(const QByteArray &text)
{
    QStringDecoder decoder(QStringDecoder::Utf8, QStringDecoder::Flag::Stateless);
    const QString decoded = decoder(text);
    return !decoder.hasError();
}

// Shader text is UTF-8 in practice and then stays readable in the journal;
// anything else goes in base64 so that the journal gives back exact bytes.
QJsonObject bufferToJson(const RecoveryBuffer &buffer)
{
    QJsonObject json{{"file", buffer.filePath}, {"dirty", buffer.dirty}};
    if (isUtf8(buffer.text))
        json.insert("text", QString::fromUtf8(buffer.text));
    else
        json.insert("base64", QString::fromLatin1(buffer.text.toBase64()));
    return json;
}

std::optional<RecoveryBuffer> bufferFromJson(const QJsonValue &value)
{
    const QJsonObject json = value.toObject();
    if (!json.value("text").isString() && !json.value("base64").isString())
        return std::nullopt;
    RecoveryBuffer buffer;
    buffer.filePath = json.value("file").toString();
    buffer.dirty = json.value("dirty").toBool();
    buffer.text = json.contains("text")
        ? json.value("text").toString().toUtf8()
        : QByteArray::fromBase64(json.value("base64").toString().toLatin1());
    return buffer;
}

// Unique among sessions sharing a folder, even across a PID being reused
// and for several journals in one process (tests).
QString newSessionId()
{
    static std::atomic<int> instances{0};
    return QStringLiteral("%1-%2-%3")
        .arg(QCoreApplication::applicationPid())
        .arg(QDateTime::currentMSecsSinceEpoch())
        .arg(instances++);
}

} // namespace

bool OrphanedSession::isSuspect() const
{
    return runningHash && *runningHash == programTextHash(record.vertex.text, record.fragment.text);
}

RecoveryJournal::RecoveryJournal(const QString &directory)
    : m_directory(directory)
    , m_sessionId(newSessionId())
{
}

RecoveryJournal::~RecoveryJournal() = default; // QLockFile's destructor unlocks

QString RecoveryJournal::defaultDirectory()
{
    const QString fromEnv = qEnvironmentVariable("PHONGLAB_RECOVERY_DIR");
    if (!fromEnv.isEmpty())
        return fromEnv;
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)
        + QStringLiteral("/recovery");
}

QString RecoveryJournal::filePath(const QString &id, const char *suffix) const
{
    return QDir(m_directory).filePath(id + QLatin1String(suffix));
}

// The lock is what tells a running session from a dead one, so it is taken
// before the first journal exists.
Result<> RecoveryJournal::ensureSession()
{
    if (m_lock)
        return {};
    if (!QDir().mkpath(m_directory))
        return fail(
            RecoveryJournalWords::tr("%1: cannot create the recovery folder").arg(m_directory));
    auto lock = std::make_unique<QLockFile>(filePath(m_sessionId, kLockSuffix));
    lock->setStaleLockTime(0); // only a dead process makes it stale, never age
    if (!lock->tryLock(0))
        return fail(
            RecoveryJournalWords::tr("%1: cannot lock the recovery journal").arg(lock->fileName()));
    m_lock = std::move(lock);
    return {};
}

Result<> RecoveryJournal::write(const RecoveryRecord &record)
{
    if (Result<> session = ensureSession(); !session)
        return session;
    const QJsonObject json{
        {"format", kFormat},
        {"version", kVersion},
        {"savedAt", QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs)},
        {"shading", record.shading},
        {"vertex", bufferToJson(record.vertex)},
        {"fragment", bufferToJson(record.fragment)},
    };
    QSaveFile file(journalPath());
    if (!file.open(QIODevice::WriteOnly))
        return fail(QStringLiteral("%1: %2").arg(file.fileName(), file.errorString()));
    file.write(QJsonDocument(json).toJson(QJsonDocument::Indented));
    if (!file.commit()) // renames over the old journal only once all is on disk
        return fail(QStringLiteral("%1: %2").arg(file.fileName(), file.errorString()));
    return {};
}

Result<RecoveryRecord> RecoveryJournal::readFile(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return fail(QStringLiteral("%1: %2").arg(path, file.errorString()));
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(file.readAll(), &parseError);
    const QJsonObject json = document.object();
    if (parseError.error != QJsonParseError::NoError
        || json.value("format").toString() != QLatin1String(kFormat)
        || json.value("version").toInt() != kVersion)
        return fail(
            RecoveryJournalWords::tr("%1: not a complete PhongLab recovery journal").arg(path));
    const auto vertex = bufferFromJson(json.value("vertex"));
    const auto fragment = bufferFromJson(json.value("fragment"));
    if (!vertex || !fragment)
        return fail(
            RecoveryJournalWords::tr("%1: a shader buffer is missing from the journal").arg(path));
    RecoveryRecord record;
    record.vertex = *vertex;
    record.fragment = *fragment;
    record.shading = json.value("shading").toString();
    record.savedAt = QDateTime::fromString(json.value("savedAt").toString(), Qt::ISODateWithMs);
    return record;
}

Result<RecoveryRecord> RecoveryJournal::read() const
{
    return readFile(journalPath());
}

bool RecoveryJournal::hasJournal() const
{
    return QFileInfo::exists(journalPath());
}

void RecoveryJournal::clear()
{
    QFile::remove(journalPath());
    QFile::remove(sentinelPath());
}

Result<> RecoveryJournal::markRunning(const QByteArray &textHash)
{
    if (Result<> session = ensureSession(); !session)
        return session;
    QSaveFile file(sentinelPath());
    if (!file.open(QIODevice::WriteOnly))
        return fail(QStringLiteral("%1: %2").arg(file.fileName(), file.errorString()));
    file.write(textHash + '\n');
    if (!file.commit())
        return fail(QStringLiteral("%1: %2").arg(file.fileName(), file.errorString()));
    return {};
}

void RecoveryJournal::clearRunning()
{
    QFile::remove(sentinelPath());
}

std::optional<QByteArray> RecoveryJournal::runningHash() const
{
    QFile file(sentinelPath());
    if (!file.open(QIODevice::ReadOnly))
        return std::nullopt;
    return file.readAll().trimmed();
}

bool RecoveryJournal::isSessionAlive(const QString &id) const
{
    if (id == m_sessionId)
        return true;
    QLockFile lock(filePath(id, kLockSuffix));
    lock.setStaleLockTime(0);
    if (!lock.tryLock(0))
        return lock.error() == QLockFile::LockFailedError; // held by a live process
    lock.unlock(); // it was stale (or missing): the session is gone
    return false;
}

QList<OrphanedSession> RecoveryJournal::orphans() const
{
    // Only complete journals are listed: QSaveFile's temporary files (a
    // write cut short) have other names and are never read.
    const QStringList names =
        QDir(m_directory).entryList({QStringLiteral("*") + kJournalSuffix}, QDir::Files);
    QList<OrphanedSession> sessions;
    for (const QString &name : names) {
        const QString id = name.chopped(int(qstrlen(kJournalSuffix)));
        if (isSessionAlive(id))
            continue;
        const auto record = readFile(filePath(id, kJournalSuffix));
        if (!record)
            continue;
        OrphanedSession session{id, *record, std::nullopt};
        QFile sentinel(filePath(id, kSentinelSuffix));
        if (sentinel.open(QIODevice::ReadOnly))
            session.runningHash = sentinel.readAll().trimmed();
        sessions << session;
    }
    std::sort(sessions.begin(), sessions.end(),
              [](const OrphanedSession &a, const OrphanedSession &b) {
                  return a.record.savedAt > b.record.savedAt;
              });
    return sessions;
}

void RecoveryJournal::discard(const QString &sessionId)
{
    if (sessionId == m_sessionId)
        return clear();
    for (const char *suffix : {kJournalSuffix, kSentinelSuffix, kLockSuffix})
        QFile::remove(filePath(sessionId, suffix));
}

} // namespace phonglab
