// `phonglab grade` as a teacher's script sees it: one class folder with a
// pass, a fail, each way a check can end without a verdict of its own
// (compile error, two files for one stage, no shader, a shader past
// --timeout, a crash, memory exhausted), a missing stage and a WebGL 2
// student with their own names, all in one run; the CSV row of each, the
// JSON beside it, the report page (opened in headless Chromium where it is
// installed), the exit codes and the same bytes from the same input.
#include "PhonglabProcess.h"
#include "ShaderMutations.h"
#include "TestFiles.h"
#include "TestPaths.h"

#include <QDir>
#include <QDirIterator>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace phonglab;
using namespace phonglab::test;

namespace {

constexpr int kTimeoutS = 3;
// A folder name as hostile as a file system allows: CSV, HTML, shell and
// arg() placeholders at once.
const QString kHostileName = QStringLiteral("=cmd|' -C calc'!A0,<b>o\"neil<i> %2 $(id)");

QString checkScene()
{
    return sourcePath(QStringLiteral("assets/scenes/check.json"));
}

void writeFile(const QString &path, const QByteArray &text)
{
    QDir().mkpath(QFileInfo(path).path());
    QFile f(path);
    QVERIFY2(f.open(QIODevice::WriteOnly), qPrintable(path));
    f.write(text);
}

QByteArray readFile(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

QByteArray shipped(const QString &name)
{
    return readFile(sourcePath(QStringLiteral("shaders/") + name));
}

// The shipped fragment shader with `text` after its first line of main().
QByteArray fragmentWith(const QByteArray &text)
{
    QByteArray frag = shipped(QStringLiteral("phong.frag"));
    const int at = frag.indexOf("vec3 I = Ia * ka;");
    Q_ASSERT(at > 0);
    return frag.insert(at + 17, " " + text);
}

// RFC 4180 records: quoted fields may hold commas, quotes and newlines.
QList<QStringList> parseCsv(const QString &text)
{
    QList<QStringList> records;
    QStringList fields;
    QString field;
    bool quoted = false;
    for (int i = 0; i < text.size(); ++i) {
        const QChar c = text[i];
        if (quoted) {
            if (c == QLatin1Char('"') && i + 1 < text.size() && text[i + 1] == QLatin1Char('"'))
                field += c, ++i;
            else if (c == QLatin1Char('"'))
                quoted = false;
            else
                field += c;
        } else if (c == QLatin1Char('"')) {
            quoted = true;
        } else if (c == QLatin1Char(',')) {
            fields << field;
            field.clear();
        } else if (c == QLatin1Char('\n')) {
            fields << field;
            records << fields;
            fields.clear();
            field.clear();
        } else {
            field += c;
        }
    }
    return records;
}

// The CSV without its last column (seconds, the only one that may differ).
QString withoutSeconds(const QByteArray &csv)
{
    QStringList out;
    const QList<QStringList> rows = parseCsv(QString::fromUtf8(csv));
    const qsizetype seconds = rows.isEmpty() ? -1 : rows.first().indexOf(QStringLiteral("seconds"));
    for (QStringList r : rows) {
        if (seconds >= 0 && seconds < r.size())
            r.removeAt(seconds);
        out << r.join(QLatin1Char('|'));
    }
    return out.join(QLatin1Char('\n'));
}

// What a file outside the class holds: it must show in no output.
constexpr char kSecret[] = "precision highp float; // TEACHER-ONLY 7f3a9c\n"
                           "void main() { gl_FragColor = vec4(1.0); }\n";

// The class: each student a way a submission can be.
void writeClass(const QString &root, bool everyFailure)
{
    const ShaderPair mistaken = withMistake(ShaderMistake::ReflectIncident);
    writeFile(root + QStringLiteral("/alice/my shader.vert"),
              shipped(QStringLiteral("phong.vert")));
    writeFile(root + QStringLiteral("/alice/my shader.frag"),
              shipped(QStringLiteral("phong.frag")));
    // bob: the fragment stage alone (the vertex stage is the shipped one), one mistake
    writeFile(root + QStringLiteral("/bob/src/phong.fs"), mistaken.fragment.code);
    // heidi: WebGL 2 names, one folder down, .glsl: passes with no --bind
    writeFile(root + QStringLiteral("/heidi/a.glsl"),
              readFile(sourcePath(QStringLiteral("assets/shaders/webgl2/phong.vert"))));
    writeFile(root + QStringLiteral("/heidi/b.glsl"),
              readFile(sourcePath(QStringLiteral("assets/shaders/webgl2/phong.frag"))));
    writeFile(root + QLatin1Char('/') + kHostileName + QStringLiteral("/x.frag"),
              mistaken.fragment.code);
    if (!everyFailure)
        return;
    writeFile(root + QStringLiteral("/carol/broken.frag"), fragmentWith("this is not GLSL;"));
    writeFile(root + QStringLiteral("/dave/one.frag"), shipped(QStringLiteral("phong.frag")));
    writeFile(root + QStringLiteral("/dave/two.frag"), shipped(QStringLiteral("phong.frag")));
    writeFile(root + QStringLiteral("/erin/notes.txt"), "no shader here");
    // A child that never answers. A heavy loop alone is not enough: on this
    // 2-core machine llvmpipe drew a million iterations of sin() per pixel
    // at 160x120 in under the 3 s limit, so the verdict came down to the
    // machine's load. The child's own hang (PHONGLAB_GRADE_FAULTS) is what
    // --timeout must end, every time.
    writeFile(root + QStringLiteral("/frank/slow.frag"),
              fragmentWith("for (int k = 0; k < 1000000; ++k) I += 1e-9 * sin(I * float(k));\n"
                           "// PHONGLAB_FAULT: hang"));
    writeFile(root + QStringLiteral("/grace/crash.frag"), fragmentWith("// PHONGLAB_FAULT: crash"));
    writeFile(root + QStringLiteral("/ivan/hungry.frag"), fragmentWith("// PHONGLAB_FAULT: oom"));
    // mallory: links to a file of the teacher's (outside the class) and a
    // folder that is itself a link; neither may be read.
    const QString secret = root + QStringLiteral("/../teacher-secret.frag");
    writeFile(secret, kSecret);
    QDir().mkpath(root + QStringLiteral("/mallory"));
    QFile::link(secret, root + QStringLiteral("/mallory/phong.frag"));
    QDir().mkpath(root + QStringLiteral("/../outside"));
    writeFile(root + QStringLiteral("/../outside/phong.frag"), kSecret);
    QFile::link(root + QStringLiteral("/../outside"), root + QStringLiteral("/trudy"));
}

ProcessRun grade(const QString &classRoot, const QString &out, const QStringList &more = {})
{
    qputenv("PHONGLAB_GRADE_FAULTS", "1"); // the children inherit it
    return runPhonglab(QStringList{QStringLiteral("grade"), classRoot, QStringLiteral("--scene"),
                                   checkScene(), QStringLiteral("--size"),
                                   QStringLiteral("160x120"), QStringLiteral("--timeout"),
                                   QString::number(kTimeoutS), QStringLiteral("--memory"),
                                   QStringLiteral("400"), QStringLiteral("--out"), out}
                       + more);
}

QMap<QString, QStringList> rowsBySubmission(const QByteArray &csv)
{
    QMap<QString, QStringList> rows;
    const QList<QStringList> records = parseCsv(QString::fromUtf8(csv));
    for (const QStringList &r : records.mid(1))
        rows[r.value(0)] = r;
    return rows;
}

} // namespace

class TestCliGrade : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    QString m_out;
    ProcessRun m_run;
    qint64 m_runMs = 0;

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        writeClass(m_dir.filePath(QStringLiteral("class")), true);
        m_out = m_dir.filePath(QStringLiteral("out"));
        QElapsedTimer clock;
        clock.start();
        // "class/" as a shell completes it: the paths in the tables are
        // relative to it all the same ("bob/src/phong.fs").
        m_run = grade(m_dir.filePath(QStringLiteral("class/")), m_out,
                      {QStringLiteral("--jobs"), QStringLiteral("2")});
        m_runMs = clock.elapsed();
    }

    void everySubmissionGetsItsVerdict()
    {
        QVERIFY2(m_run.exitCode == 0, qPrintable(m_run.err));
        const QByteArray csv = readFile(m_out + QStringLiteral("/grades.csv"));
        QVERIFY(csv.startsWith(
            "submission,scene,verdict,psnr_db,max_error,bad_fraction,key,also,"
            "file,line,equation,bindings,seconds,mistakes,program,student,participant,"
            "page_fidelity,page_own_scene,page_javascript,page_error\n"));
        const QMap<QString, QStringList> rows = rowsBySubmission(csv);
        QCOMPARE(rows.size(), 12);
        const auto verdict = [&](const QString &who) { return rows.value(who).value(2); };
        const auto column = [&](const QString &who, int c) { return rows.value(who).value(c); };
        QCOMPARE(verdict(QStringLiteral("alice")), QStringLiteral("pass"));
        QCOMPARE(column(QStringLiteral("alice"), 6), QString()); // no key
        QCOMPARE(column(QStringLiteral("alice"), 10), QStringLiteral("guarded"));

        QCOMPARE(verdict(QStringLiteral("bob")), QStringLiteral("fail"));
        QCOMPARE(column(QStringLiteral("bob"), 6), QStringLiteral("reflect-incident"));
        QCOMPARE(column(QStringLiteral("bob"), 8), QStringLiteral("bob/src/phong.fs"));
        QVERIFY(column(QStringLiteral("bob"), 9).toInt() > 0);
        QVERIFY(column(QStringLiteral("bob"), 3).toDouble() < 40.0);

        QCOMPARE(verdict(QStringLiteral("heidi")), QStringLiteral("pass"));
        QVERIFY2(column(QStringLiteral("heidi"), 11).contains(QStringLiteral("uModelMatrix=model")),
                 qPrintable(column(QStringLiteral("heidi"), 11)));

        QCOMPARE(verdict(QStringLiteral("carol")), QStringLiteral("error"));
        QCOMPARE(column(QStringLiteral("carol"), 8), QStringLiteral("carol/broken.frag"));
        QVERIFY(column(QStringLiteral("carol"), 9).toInt() > 0); // the compiler's line

        QCOMPARE(verdict(QStringLiteral("dave")), QStringLiteral("error"));
        QCOMPARE(verdict(QStringLiteral("erin")), QStringLiteral("error"));
        QCOMPARE(verdict(QStringLiteral("frank")), QStringLiteral("timeout"));
        QVERIFY(column(QStringLiteral("frank"), 12).toDouble() >= kTimeoutS);
        QCOMPARE(verdict(QStringLiteral("grace")), QStringLiteral("crash"));
        QCOMPARE(verdict(QStringLiteral("ivan")), QStringLiteral("crash"));

        for (const char *who : {"mallory", "trudy"})
            QCOMPARE(verdict(QLatin1String(who)), QStringLiteral("error"));

        // The hostile name, read back whole: CSV quoting, and the formula defused.
        QCOMPARE(verdict(QLatin1Char('\'') + kHostileName), QStringLiteral("fail"));
    }

    // A link to a file of the teacher's, or a submission that
    // is a link, is never read: its text is in no table, page or log.
    void noFileOutsideTheClassIsRead()
    {
        QVERIFY(!m_run.out.contains("TEACHER-ONLY") && !m_run.err.contains("TEACHER-ONLY"));
        QDirIterator it(m_out, QDir::Files, QDirIterator::Subdirectories);
        int files = 0;
        while (it.hasNext()) {
            const QString path = it.next();
            ++files;
            QVERIFY2(!readFile(path).contains("TEACHER-ONLY"), qPrintable(path));
        }
        QVERIFY(files >= 3); // grades.csv, grades.json, report.html at least
    }

    void theRunEndsSoonAfterTheTimeout()
    {
        // One shader that never ends must not hold up the class: the run
        // ends within its timeout plus a margin (references, 12 children
        // on 2 jobs).
        QVERIFY2(m_runMs < (kTimeoutS + 45) * 1000, qPrintable(QString::number(m_runMs)));
    }

    void jsonHoldsTheChecksKeysPerRow()
    {
        const QJsonObject json =
            QJsonDocument::fromJson(readFile(m_out + QStringLiteral("/grades.json"))).object();
        const QJsonArray rows = json.value(QStringLiteral("rows")).toArray();
        QCOMPARE(rows.size(), 12);
        QMap<QString, QJsonObject> by;
        for (const QJsonValue &r : rows)
            by[r.toObject().value(QStringLiteral("submission")).toString()] = r.toObject();
        for (const char *key :
             {"verdict", "psnr_db", "max_error", "bad_fraction", "tolerance", "worst", "diagnosis",
              "undetectable", "errors", "bindings", "equation", "notes", "scene", "seconds"})
            QVERIFY2(by[QStringLiteral("bob")].contains(QLatin1String(key)), key);
        QCOMPARE(by[QStringLiteral("bob")]
                     .value(QStringLiteral("diagnosis"))
                     .toArray()
                     .first()
                     .toObject()
                     .value(QStringLiteral("key"))
                     .toString(),
                 QStringLiteral("reflect-incident"));
        const auto firstError = [&](const QString &who) {
            return by[who]
                .value(QStringLiteral("errors"))
                .toArray()
                .first()
                .toObject()
                .value(QStringLiteral("message"))
                .toString();
        };
        const QString daveError = firstError(QStringLiteral("dave"));
        QVERIFY2(daveError.contains(QStringLiteral("one.frag"))
                     && daveError.contains(QStringLiteral("two.frag")),
                 qPrintable(daveError));
        QCOMPARE(by[QStringLiteral("frank")].value(QStringLiteral("verdict")).toString(),
                 QStringLiteral("timeout"));
        for (const char *who : {"mallory", "trudy"}) {
            const QString error = firstError(QLatin1String(who));
            QVERIFY2(error.contains(QStringLiteral("symbolic link")), qPrintable(error));
        }
    }

    // A submission that drew nothing (dave's error, frank's timeout) leaves
    // no empty folder under images/, and one that drew keeps its images.
    void noImageFolderLeftEmpty()
    {
        const QDir images(m_out + QStringLiteral("/images"));
        int folders = 0;
        for (const QFileInfo &folder : images.entryInfoList(QDir::Dirs | QDir::NoDotAndDotDot)) {
            ++folders;
            QVERIFY2(!QDir(folder.filePath()).isEmpty(), qPrintable(folder.filePath()));
        }
        QVERIFY(folders > 0);
    }

    void stdoutTableNamesEveryStudent()
    {
        const QString table = QString::fromUtf8(m_run.out);
        for (const char *who : {"alice", "bob", "carol", "frank", "grace"})
            QVERIFY2(table.contains(QLatin1String(who)), who);
        QVERIFY(table.contains(QStringLiteral("reflect-incident  bob/src/phong.fs:")));
    }

    void reportEscapesWhatStudentsWrote()
    {
        const QString html = QString::fromUtf8(readFile(m_out + QStringLiteral("/report.html")));
        QVERIFY(!html.contains(QStringLiteral("<b>o")));
        QVERIFY(html.contains(QStringLiteral("&lt;b&gt;o&quot;neil&lt;i&gt; %2 $(id)")));
        // Every image the page shows is there.
        static const QRegularExpression src(QStringLiteral("src=\"([^\"]+)\""));
        int images = 0;
        for (auto it = src.globalMatch(html); it.hasNext(); ++images)
            QVERIFY(QFile::exists(m_out + QLatin1Char('/') + it.next().captured(1)));
        QCOMPARE(images, 3 * 4); // alice, bob, heidi and the hostile one: theirs, exact, heatmap
        // The command that opens a submission, quoted for a shell.
        QVERIFY(html.contains(QStringLiteral("--fragment '")));
        // bob wrote the fragment stage alone: the command names the shipped
        // vertex shader he was checked with, as the window would not by itself.
        QVERIFY(html.contains(QRegularExpression(QStringLiteral(
            R"(--vertex \S*shaders/phong\.vert --fragment \S*/bob/src/phong\.fs)"))));
        QVERIFY(html.contains(QStringLiteral("'\\''")));
    }

    void reportOpensInABrowser()
    {
        const QString browser = chromiumExecutable();
        if (browser.isEmpty())
            QSKIP("no chromium installed (scripts/setup.sh installs it)");
        QProcess p;
        p.start(browser,
                {QStringLiteral("--headless"), QStringLiteral("--no-sandbox"),
                 QStringLiteral("--disable-gpu"), QStringLiteral("--allow-file-access-from-files"),
                 QStringLiteral("--virtual-time-budget=5000"), QStringLiteral("--dump-dom"),
                 QUrl::fromLocalFile(m_out + QStringLiteral("/report.html")).toString()
                     + QStringLiteral("#sort=verdict")});
        QVERIFY(p.waitForFinished(120000));
        const QString dom = QString::fromUtf8(p.readAllStandardOutput());
        QVERIFY2(dom.contains(QStringLiteral("data-sorted-by=\"verdict\"")),
                 qPrintable(QString::fromUtf8(p.readAllStandardError()).left(2000)));
        QVERIFY(dom.contains(QStringLiteral("data-broken-images=\"0\"")));
        // Sorted worst first: the crashes before the passes.
        static const QRegularExpression rank(QStringLiteral("data-rank=\"(\\d)\""));
        QList<int> ranks;
        for (auto it = rank.globalMatch(dom); it.hasNext();)
            ranks << it.next().captured(1).toInt();
        QCOMPARE(ranks.size(), 12);
        QVERIFY(std::is_sorted(ranks.begin(), ranks.end()));
        QCOMPARE(ranks.front(), 0);
        QCOMPARE(ranks.back(), 4);
    }

    void sameInputSameCsv()
    {
        QTemporaryDir dir;
        const QString root = dir.filePath(QStringLiteral("class"));
        writeClass(root, false);
        const ProcessRun a = grade(root, dir.filePath(QStringLiteral("a")));
        const ProcessRun b = grade(root, dir.filePath(QStringLiteral("b")),
                                   {QStringLiteral("--jobs"), QStringLiteral("1")});
        QCOMPARE(a.exitCode, 0);
        QCOMPARE(b.exitCode, 0);
        const QByteArray csvA = readFile(dir.filePath(QStringLiteral("a/grades.csv")));
        QCOMPARE(withoutSeconds(csvA),
                 withoutSeconds(readFile(dir.filePath(QStringLiteral("b/grades.csv")))));
        QCOMPARE(parseCsv(QString::fromUtf8(csvA)).size(), 5);
    }

    // --lang de makes the report German; the CSV a script reads
    // (columns, keys, verdicts) is the same byte for byte.
    void germanReportSameCsv()
    {
        QTemporaryDir dir;
        const QString root = dir.filePath(QStringLiteral("class"));
        writeClass(root, false);
        const ProcessRun english = grade(root, dir.filePath(QStringLiteral("en")));
        const ProcessRun german = grade(root, dir.filePath(QStringLiteral("de")),
                                        {QStringLiteral("--lang"), QStringLiteral("de")});
        QCOMPARE(english.exitCode, 0);
        QCOMPARE(german.exitCode, 0);
        QCOMPARE(withoutSeconds(readFile(dir.filePath(QStringLiteral("de/grades.csv")))),
                 withoutSeconds(readFile(dir.filePath(QStringLiteral("en/grades.csv")))));
        const QString en =
            QString::fromUtf8(readFile(dir.filePath(QStringLiteral("en/report.html"))));
        const QString de =
            QString::fromUtf8(readFile(dir.filePath(QStringLiteral("de/report.html"))));
        QVERIFY(en.contains(QStringLiteral("<html lang=\"en\">")));
        QVERIFY(en.contains(QStringLiteral("Passes per scene")));
        QVERIFY(de.contains(QStringLiteral("<html lang=\"de\">")));
        QVERIFY2(de.contains(QStringLiteral("Bestanden je Szene"))
                     && !de.contains(QStringLiteral("Passes per scene")),
                 qPrintable(de.left(2000)));
    }

    void exitCodes()
    {
        QTemporaryDir dir;
        const QString root = dir.filePath(QStringLiteral("class"));
        writeFile(root + QStringLiteral("/alice/a.frag"), shipped(QStringLiteral("phong.frag")));
        const auto run = [&](const QStringList &args) {
            return runPhonglab(QStringList{QStringLiteral("grade")} + args);
        };
        const QString out = dir.filePath(QStringLiteral("out"));
        // Usage: 2
        QCOMPARE(run({root}).exitCode, 2); // no --scene
        QCOMPARE(run({root, QStringLiteral("--scene"), checkScene(), QStringLiteral("--timeout"),
                      QStringLiteral("0")})
                     .exitCode,
                 2);
        QCOMPARE(run({QStringLiteral("--scene"), checkScene()}).exitCode, 2);
        // The run cannot complete: 1
        const ProcessRun noScene =
            run({root, QStringLiteral("--scene"), dir.filePath(QStringLiteral("nosuch.json")),
                 QStringLiteral("--out"), out});
        QCOMPARE(noScene.exitCode, 1);
        QVERIFY2(noScene.err.contains(QStringLiteral("nosuch.json")), qPrintable(noScene.err));
        writeFile(dir.filePath(QStringLiteral("file")), "not a folder");
        QCOMPARE(run({root, QStringLiteral("--scene"), checkScene(), QStringLiteral("--out"),
                      dir.filePath(QStringLiteral("file/out"))})
                     .exitCode,
                 1);
        QCOMPARE(run({dir.filePath(QStringLiteral("file")), QStringLiteral("--scene"), checkScene(),
                      QStringLiteral("--out"), out})
                     .exitCode,
                 1);
    }
};

QTEST_GUILESS_MAIN(TestCliGrade)
#include "tst_cligrade.moc"
