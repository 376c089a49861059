// The crash journal of the shader editors: what is written is read back
// exactly, a write cut short never replaces a good journal, clearing forgets
// it, and a session that died is told apart from one that still runs.

#include "core/session/RecoveryJournal.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QLockFile>
#include <QSysInfo>
#include <QTemporaryDir>
#include <QTest>

using namespace phonglab;

namespace {

RecoveryRecord sampleRecord()
{
    RecoveryRecord record;
    record.vertex = {QStringLiteral("/shaders/phong.vert"),
                     QByteArray("#version 330 core\nvoid main() {}\n"), false};
    record.fragment = {
        QStringLiteral("/shaders/phong.frag"),
        QByteArray("#version 330 core\n// édité: ü\nout vec4 c;\nvoid main() { c = vec4(0.5); }\n"),
        true};
    record.shading = QStringLiteral("phong");
    return record;
}

void writeFile(const QString &path, const QByteArray &contents)
{
    QFile file(path);
    QVERIFY2(file.open(QIODevice::WriteOnly), qPrintable(file.errorString()));
    file.write(contents);
}

// A journal left by a session whose process is gone: its lock names a PID
// that does not run (the lock file is what a killed process leaves behind).
void leaveOrphan(const QString &dir, const QString &id, const RecoveryRecord &record)
{
    {
        RecoveryJournal other(dir);
        const Result<> written = other.write(record);
        QVERIFY2(written, qPrintable(written.error()));
        QVERIFY(QFile::rename(other.journalPath(), QDir(dir).filePath(id + ".journal")));
    }
    writeFile(QDir(dir).filePath(id + ".lock"),
              "999999999\nphonglab\n" + QSysInfo::machineHostName().toUtf8() + '\n');
}

} // namespace

class TestRecoveryJournal : public QObject
{
    Q_OBJECT

private slots:
    void init();
    void roundTrip();
    void nonUtf8TextRoundTrips();
    void rewriteReplacesWholeJournal();
    void halfWrittenTempFileIsIgnored();
    void truncatedJournalIsRefused();
    void clearRemovesJournalAndSentinel();
    void sentinelRoundTrip();
    void runningSessionIsNotAnOrphan();
    void deadSessionIsAnOrphanWithItsSentinel();
    void orphansNewestFirstAndDiscard();
    void hashSeparatesStages();
    void directoryFromEnvironment();

private:
    std::unique_ptr<QTemporaryDir> m_dir;
};

void TestRecoveryJournal::init()
{
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
}

void TestRecoveryJournal::roundTrip()
{
    RecoveryJournal journal(m_dir->path());
    QVERIFY(!journal.hasJournal());
    const Result<> written = journal.write(sampleRecord());
    QVERIFY2(written, qPrintable(written.error()));
    QVERIFY(journal.hasJournal());
    const auto read = journal.read();
    QVERIFY2(read, qPrintable(read.error()));
    QCOMPARE(read->vertex, sampleRecord().vertex);
    QCOMPARE(read->fragment, sampleRecord().fragment);
    QCOMPARE(read->shading, QStringLiteral("phong"));
    QVERIFY(read->savedAt.isValid());
    QVERIFY(qAbs(read->savedAt.secsTo(QDateTime::currentDateTimeUtc())) < 60);
}

void TestRecoveryJournal::nonUtf8TextRoundTrips()
{
    RecoveryJournal journal(m_dir->path());
    RecoveryRecord record = sampleRecord();
    static constexpr char kText[] = "bad \xff\xfe bytes\0 and a nul";
    record.fragment.text = QByteArray(kText, sizeof kText - 1); // the nul inside included
    QVERIFY(journal.write(record));
    const auto read = journal.read();
    QVERIFY(read);
    QCOMPARE(read->fragment.text, record.fragment.text);
}

void TestRecoveryJournal::rewriteReplacesWholeJournal()
{
    RecoveryJournal journal(m_dir->path());
    QVERIFY(journal.write(sampleRecord()));
    RecoveryRecord shorter = sampleRecord();
    shorter.fragment.text = "x";
    QVERIFY(journal.write(shorter));
    QCOMPARE(journal.read()->fragment.text, QByteArray("x"));
}

// QSaveFile writes <journal>.XXXXXX and renames it over the journal on
// commit; a process killed before the rename leaves that temp file, which
// must neither replace nor hide the last complete journal.
void TestRecoveryJournal::halfWrittenTempFileIsIgnored()
{
    RecoveryJournal journal(m_dir->path());
    QVERIFY(journal.write(sampleRecord()));
    const QByteArray complete = sampleRecord().fragment.text;
    writeFile(journal.journalPath() + QStringLiteral(".Xa12bC"),
              "{\"format\": \"phonglab-recovery\", \"vers");
    const auto read = journal.read();
    QVERIFY(read);
    QCOMPARE(read->fragment.text, complete);

    // A dead session's leftovers: only its complete journal counts.
    leaveOrphan(m_dir->path(), QStringLiteral("42-1"), sampleRecord());
    writeFile(QDir(m_dir->path()).filePath(QStringLiteral("42-1.journal.Zz9xYw")), "{\"format\"");
    const QList<OrphanedSession> orphans = journal.orphans();
    QCOMPARE(orphans.size(), 1);
    QCOMPARE(orphans.front().record.fragment, sampleRecord().fragment);
}

void TestRecoveryJournal::truncatedJournalIsRefused()
{
    const QString path = QDir(m_dir->path()).filePath(QStringLiteral("7-7.journal"));
    writeFile(path,
              "{\"format\": \"phonglab-recovery\", \"version\": 1, \"vertex\": {\"text\": \"ab");
    const auto truncated = RecoveryJournal::readFile(path);
    QVERIFY(!truncated);
    QVERIFY2(truncated.error().contains(QStringLiteral("not a complete")),
             qPrintable(truncated.error()));
    writeFile(
        path,
        "{\"format\": \"phonglab-recovery\", \"version\": 1, \"vertex\": {\"text\": \"ab\"}}");
    const auto partial = RecoveryJournal::readFile(path);
    QVERIFY(!partial);
    QVERIFY2(partial.error().contains(QStringLiteral("missing")), qPrintable(partial.error()));
    RecoveryJournal journal(m_dir->path());
    QVERIFY(journal.orphans().isEmpty());
}

void TestRecoveryJournal::clearRemovesJournalAndSentinel()
{
    RecoveryJournal journal(m_dir->path());
    QVERIFY(journal.write(sampleRecord()));
    QVERIFY(journal.markRunning("abc"));
    journal.clear();
    QVERIFY(!journal.hasJournal());
    QVERIFY(!journal.runningHash());
    QVERIFY(!QFile::exists(journal.journalPath()));
    QVERIFY(!QFile::exists(journal.sentinelPath()));
}

void TestRecoveryJournal::sentinelRoundTrip()
{
    RecoveryJournal journal(m_dir->path());
    QVERIFY(!journal.runningHash());
    const QByteArray hash = programTextHash("v", "f");
    QVERIFY(journal.markRunning(hash));
    QCOMPARE(journal.runningHash().value_or(QByteArray()), hash);
    journal.clearRunning();
    QVERIFY(!journal.runningHash());
    QVERIFY(!QFile::exists(journal.sentinelPath()));
}

void TestRecoveryJournal::runningSessionIsNotAnOrphan()
{
    RecoveryJournal running(m_dir->path());
    QVERIFY(running.write(sampleRecord()));
    RecoveryJournal next(m_dir->path());
    QVERIFY(next.orphans().isEmpty());
    QVERIFY(running.orphans().isEmpty()); // nor is one's own session
}

void TestRecoveryJournal::deadSessionIsAnOrphanWithItsSentinel()
{
    RecoveryRecord record = sampleRecord();
    leaveOrphan(m_dir->path(), QStringLiteral("100-5"), record);
    const QByteArray hash = programTextHash(record.vertex.text, record.fragment.text);
    writeFile(QDir(m_dir->path()).filePath(QStringLiteral("100-5.running")), hash + '\n');

    RecoveryJournal journal(m_dir->path());
    const QList<OrphanedSession> orphans = journal.orphans();
    QCOMPARE(orphans.size(), 1);
    QCOMPARE(orphans.front().id, QStringLiteral("100-5"));
    QCOMPARE(orphans.front().record.fragment, record.fragment);
    QCOMPARE(orphans.front().runningHash.value_or(QByteArray()), hash);
    QVERIFY(orphans.front().isSuspect());

    // A sentinel for other text (the user typed on after it) is no reason to
    // distrust what the journal holds.
    writeFile(QDir(m_dir->path()).filePath(QStringLiteral("100-5.running")), "0123\n");
    QVERIFY(!journal.orphans().front().isSuspect());
}

void TestRecoveryJournal::orphansNewestFirstAndDiscard()
{
    RecoveryRecord older = sampleRecord();
    older.fragment.text = "older";
    leaveOrphan(m_dir->path(), QStringLiteral("1-1"), older);
    // savedAt has millisecond resolution: the next record is saved a
    // millisecond later at least.
    const qint64 olderSaved = QDateTime::currentMSecsSinceEpoch();
    QTRY_VERIFY(QDateTime::currentMSecsSinceEpoch() > olderSaved);
    RecoveryRecord newer = sampleRecord();
    newer.fragment.text = "newer";
    leaveOrphan(m_dir->path(), QStringLiteral("2-2"), newer);

    RecoveryJournal journal(m_dir->path());
    QList<OrphanedSession> orphans = journal.orphans();
    QCOMPARE(orphans.size(), 2);
    QCOMPARE(orphans[0].record.fragment.text, QByteArray("newer"));
    QCOMPARE(orphans[1].record.fragment.text, QByteArray("older"));

    journal.discard(QStringLiteral("2-2"));
    orphans = journal.orphans();
    QCOMPARE(orphans.size(), 1);
    QCOMPARE(orphans[0].id, QStringLiteral("1-1"));
    QVERIFY(!QFile::exists(QDir(m_dir->path()).filePath(QStringLiteral("2-2.journal"))));
    QVERIFY(!QFile::exists(QDir(m_dir->path()).filePath(QStringLiteral("2-2.lock"))));
}

void TestRecoveryJournal::hashSeparatesStages()
{
    QCOMPARE(programTextHash("ab", "c"), programTextHash("ab", "c"));
    QVERIFY(programTextHash("ab", "c") != programTextHash("a", "bc"));
    QVERIFY(programTextHash("ab", "c") != programTextHash("ab", "d"));
}

void TestRecoveryJournal::directoryFromEnvironment()
{
    qputenv("PHONGLAB_RECOVERY_DIR", m_dir->path().toUtf8());
    QCOMPARE(RecoveryJournal::defaultDirectory(), m_dir->path());
    qunsetenv("PHONGLAB_RECOVERY_DIR");
    QVERIFY(RecoveryJournal::defaultDirectory().endsWith(QStringLiteral("/recovery")));
}

QTEST_GUILESS_MAIN(TestRecoveryJournal)
#include "tst_recoveryjournal.moc"
