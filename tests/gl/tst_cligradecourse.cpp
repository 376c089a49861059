// A course platform's download in, grades and feedback back out: Moodle's "download all submissions" zip in both layouts, with
// WebGL projects, a student's own zip and a hostile one; the `student` and
// `participant` columns; moodle-grades.csv byte for byte with --points;
// feedback.zip with each participant's folder named as in the download and
// a feedback.html that holds that student alone (opened in Chromium); and a
// run stopped half way that --resume finishes with the same grades.csv.
#include "PhonglabProcess.h"
#include "ShaderMutations.h"
#include "TestFiles.h"
#include "TestPaths.h"
#include "cli/grade/SubmissionArchive.h"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QUrl>

#include <archive.h>
#include <archive_entry.h>
#include <csignal>

using namespace phonglab;
using namespace phonglab::test;

namespace {

// A zip through libarchive, names in UTF-8.
void writeZip(const QString &path, const std::vector<std::pair<QByteArray, QByteArray>> &files)
{
    archive *a = archive_write_new();
    archive_write_set_format_zip(a);
    archive_write_set_options(a, "zip:hdrcharset=UTF-8");
    QVERIFY(archive_write_open_filename(a, QFile::encodeName(path).constData()) == ARCHIVE_OK);
    for (const auto &[name, data] : files) {
        archive_entry *e = archive_entry_new();
        archive_entry_set_pathname_utf8(e, name.constData());
        archive_entry_set_filetype(e, AE_IFREG);
        archive_entry_set_perm(e, 0644);
        archive_entry_set_size(e, data.size());
        archive_write_header(a, e);
        archive_write_data(a, data.constData(), std::size_t(data.size()));
        archive_entry_free(e);
    }
    archive_write_close(a);
    archive_write_free(a);
}

QByteArray zipBytes(const std::vector<std::pair<QByteArray, QByteArray>> &files)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("z.zip"));
    writeZip(path, files);
    return readTestFile(path);
}

QByteArray inlinePage(const QByteArray &vertex, const QByteArray &fragment)
{
    return "<!DOCTYPE html>\n<html><body><canvas></canvas>\n<script>\nconst vsSource = `" + vertex
        + "`;\nconst fsSource = `" + fragment
        + "`;\nconst program = initShaderProgram(gl, vsSource, "
          "fsSource);\n</script></body></html>\n";
}

QString withoutColumn(const QByteArray &csv, const QString &column)
{
    QStringList out;
    const QList<QByteArray> lines = csv.split('\n');
    const qsizetype at = QString::fromUtf8(lines.first()).split(QLatin1Char(',')).indexOf(column);
    for (const QByteArray &line : lines) {
        QStringList cells = QString::fromUtf8(line).split(QLatin1Char(','));
        if (at >= 0 && at < cells.size())
            cells.removeAt(at);
        out << cells.join(QLatin1Char(','));
    }
    return out.join(QLatin1Char('\n'));
}

const char *kStudents[] = {"Anna Beck", "Ben Cho", "Cem Demir", "Dora Eng"};

} // namespace

class TestCliGradeCourse : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    QString m_download;
    QString m_out;
    ProcessRun m_run;

    QStringList gradeArgs(const QString &out, int jobs = 2) const
    {
        return {QStringLiteral("grade"),    m_download,
                QStringLiteral("--scene"),  checkScene(),
                QStringLiteral("--size"),   QStringLiteral("96x72"),
                QStringLiteral("--points"), QStringLiteral("pass=2,fail=0.5"),
                QStringLiteral("--jobs"),   QString::number(jobs),
                QStringLiteral("--out"),    out};
    }

    static QString checkScene() { return sourcePath(QStringLiteral("assets/scenes/check.json")); }

private slots:
    void initTestCase()
    {
        const QByteArray v =
            readTestFile(sourcePath(QStringLiteral("assets/shaders/webgl2/phong.vert")));
        const QByteArray f =
            readTestFile(sourcePath(QStringLiteral("assets/shaders/webgl2/phong.frag")));
        const ShaderPair mistaken = withMistake(ShaderMistake::ReflectIncident);
        m_download = m_dir.filePath(QStringLiteral("Lab 3-Phong-download.zip"));
        writeZip(m_download,
                 {// Anna: Moodle's folder layout, plain shader files, one mistake
                  {"Anna Beck_1001_assignsubmission_file_/phong.vert", mistaken.vertex.code},
                  {"Anna Beck_1001_assignsubmission_file_/phong.frag", mistaken.fragment.code},
                  {"Anna Beck_1001_assignsubmission_onlinetext_/onlinetext.html", "<p>done</p>"},
                  // Ben: the flat layout, a page with its shaders inline
                  {"Ben Cho_1002_assignsubmission_file_index.html", inlinePage(v, f)},
                  // Cem: his own zip of the project, inside his folder
                  {"Cem Demir_1003_assignsubmission_file_/lab3.zip",
                   zipBytes({{"lab3/index.html", inlinePage(v, f)}})},
                  // Dora: a zip whose name leaves the folder
                  {"Dora Eng_1004_assignsubmission_file_/evil.zip",
                   zipBytes({{"../../../../escape.frag", f}})}});
        m_out = m_dir.filePath(QStringLiteral("out"));
        m_run = runPhonglab(gradeArgs(m_out));
    }

    void rowsNameTheStudents()
    {
        QVERIFY2(m_run.exitCode == 0, qPrintable(m_run.err));
        const QByteArray csv = readTestFile(m_out + QStringLiteral("/grades.csv"));
        const QStringList lines =
            QString::fromUtf8(csv).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 5); // four students, no online text
        const auto row = [&](const char *student) {
            for (const QString &line : lines)
                if (line.contains(QLatin1String(student)))
                    return line.split(QLatin1Char(','));
            return QStringList();
        };
        QCOMPARE(row("Anna Beck").value(2), QStringLiteral("fail"));
        QVERIFY(row("Anna Beck")
                    .join(QLatin1Char(','))
                    .endsWith(QStringLiteral(",Anna Beck,1001,,,,")));
        QCOMPARE(row("Ben Cho").value(2), QStringLiteral("pass"));
        QCOMPARE(row("Cem Demir").value(2), QStringLiteral("pass"));
        QCOMPARE(row("Dora Eng").value(2), QStringLiteral("error"));
        QVERIFY(!QFileInfo::exists(m_dir.filePath(QStringLiteral("escape.frag"))));
        QDirIterator all(m_dir.path(), QDir::Files, QDirIterator::Subdirectories);
        while (all.hasNext()) {
            const QString path = QDir(m_dir.path()).relativeFilePath(all.next());
            QVERIFY2(!path.endsWith(QLatin1String("escape.frag")), qPrintable(path));
        }
    }

    void moodleGradesCsvBytes()
    {
        const QByteArray csv = readTestFile(m_out + QStringLiteral("/moodle-grades.csv"));
        const QList<QByteArray> lines = csv.split('\n');
        QCOMPARE(lines.value(0),
                 QByteArray("\"Identifier\",\"Full name\",\"Grade\",\"Feedback comments\""));
        QCOMPARE(
            lines.value(1),
            QByteArray("\"Participant 1001\",\"Anna Beck\",\"0.5\",\"check.json: differs from the "
                       "exact image, most likely reflect-incident.\""));
        QCOMPARE(lines.value(2),
                 QByteArray("\"Participant 1002\",\"Ben Cho\",\"2\",\"check.json: "
                            "matches the exact image.\""));
        QCOMPARE(lines.value(3),
                 QByteArray("\"Participant 1003\",\"Cem Demir\",\"2\",\"check.json: "
                            "matches the exact image.\""));
        QVERIFY(lines.value(4).startsWith(
            "\"Participant 1004\",\"Dora Eng\",\"0\",\"check.json: not checked"));
        QCOMPARE(lines.size(), 6); // and the last newline
    }

    void feedbackZipHoldsEachStudentAlone()
    {
        const QString into = m_dir.filePath(QStringLiteral("feedback"));
        const Result<cli::UnpackedArchive> done =
            cli::unpackArchive(m_out + QStringLiteral("/feedback.zip"), into);
        QVERIFY2(done, qPrintable(done.error()));
        QStringList folders = QDir(into).entryList(QDir::Dirs | QDir::NoDotAndDotDot);
        QCOMPARE(folders,
                 (QStringList{QStringLiteral("Anna Beck_1001_assignsubmission_file_"),
                              QStringLiteral("Ben Cho_1002_assignsubmission_file_"),
                              QStringLiteral("Cem Demir_1003_assignsubmission_file_"),
                              QStringLiteral("Dora Eng_1004_assignsubmission_file_")}));
        const QString browser = chromiumExecutable();
        for (int i = 0; i < 4; ++i) {
            const QString page =
                into + QLatin1Char('/') + folders[i] + QStringLiteral("/feedback.html");
            QByteArray html = readTestFile(page);
            QVERIFY2(!html.isEmpty(), qPrintable(page));
            if (!browser.isEmpty()) { // as the student's browser shows it
                QProcess p;
                p.start(browser,
                        {QStringLiteral("--headless"), QStringLiteral("--no-sandbox"),
                         QStringLiteral("--disable-gpu"),
                         QStringLiteral("--virtual-time-budget=5000"), QStringLiteral("--dump-dom"),
                         QUrl::fromLocalFile(page).toString()});
                QVERIFY(p.waitForFinished(120000));
                html = p.readAllStandardOutput();
                QVERIFY2(html.contains("data-broken-images=\"0\""), qPrintable(page));
            }
            for (int other = 0; other < 4; ++other)
                QCOMPARE(html.contains(kStudents[other]), other == i);
            QVERIFY(!html.contains(m_dir.path().toUtf8())); // no path of the teacher's
        }
        if (browser.isEmpty())
            QSKIP("chromium not installed: the pages were read as files only");
    }

    void aStoppedRunResumes()
    {
        // Stopped after its first rows (one job: one row at a time).
        const QString out = m_dir.filePath(QStringLiteral("stopped"));
        QProcess p;
        p.start(phonglabExecutable(), gradeArgs(out, 1));
        const QString journal = out + QStringLiteral("/grades.partial.jsonl");
        QTRY_VERIFY_WITH_TIMEOUT(readTestFile(journal).count('\n') >= 3,
                                 60000); // the fingerprint and two rows
        ::kill(pid_t(p.processId()), SIGINT);
        QVERIFY(p.waitForFinished(20000));
        QVERIFY(!QFile::exists(out + QStringLiteral("/grades.csv")));
        const ProcessRun resumed = runPhonglab(gradeArgs(out, 1) << QStringLiteral("--resume"));
        QVERIFY2(resumed.exitCode == 0, qPrintable(resumed.err));
        static const QRegularExpression kept(QStringLiteral("kept (\\d+) finished checks"));
        const QRegularExpressionMatch m = kept.match(resumed.err);
        QVERIFY2(m.hasMatch() && m.captured(1).toInt() >= 2, qPrintable(resumed.err));
        QCOMPARE(withoutColumn(readTestFile(out + QStringLiteral("/grades.csv")),
                               QStringLiteral("seconds")),
                 withoutColumn(readTestFile(m_out + QStringLiteral("/grades.csv")),
                               QStringLiteral("seconds")));
        QCOMPARE(readTestFile(out + QStringLiteral("/moodle-grades.csv")),
                 readTestFile(m_out + QStringLiteral("/moodle-grades.csv")));
        QVERIFY(!QFile::exists(journal)); // done: the journal went
    }
};

QTEST_GUILESS_MAIN(TestCliGradeCourse)
#include "tst_cligradecourse.moc"
