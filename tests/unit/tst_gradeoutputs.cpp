// What `phonglab grade` writes, made from rows without any GL: the CSV's
// exact bytes (columns, number formats, quoting, formulas defused), the
// class folder as read (stages by suffix and content, two files for a stage,
// order), shell quoting and HTML escaping of what students named.
#include "cli/grade/ClassFolder.h"
#include "cli/grade/GradeReport.h"
#include "cli/grade/GradeTables.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace phonglab;
using namespace phonglab::cli;

namespace {

GradeResults twoRows()
{
    GradeResults r;
    r.settings.classFolder = QStringLiteral("class");
    Submission alice;
    alice.name = QStringLiteral("alice");
    Submission hostile;
    hostile.name = QStringLiteral("=SUM(A1),\"x\" %1");
    r.submissions = {alice, hostile};
    GradeScene scene;
    scene.label = QStringLiteral("check.json");
    r.scenes = {scene};

    GradeRow pass;
    pass.submission = 0;
    pass.verdict = Verdict::Pass;
    pass.findings.report.comparison.psnr = std::numeric_limits<double>::infinity();
    pass.findings.report.comparison.pixelsCompared = 100;
    pass.seconds = 0.5;

    GradeRow fail;
    fail.submission = 1;
    fail.verdict = Verdict::Fail;
    fail.findings.report.comparison.psnr = 23.456;
    fail.findings.report.comparison.maxError = 145;
    fail.findings.report.comparison.pixelsCompared = 1000;
    fail.findings.report.badPixels = 250;
    MistakeFinding finding;
    finding.key = ShaderMistake::ReflectIncident;
    finding.also = {ShaderMistake::ViewVector};
    finding.confidence = 1.0;
    fail.findings.report.diagnosis.findings = {finding};
    fail.findings.stages = {{QStringLiteral("x/a.frag"),
                             QStringLiteral("void main()\n{\n    vec3 R = reflect(L, N);\n}\n"),
                             false}};
    fail.seconds = 1.25;
    r.rows = {pass, fail};
    return r;
}

void write(const QString &path, const QByteArray &text)
{
    QDir().mkpath(QFileInfo(path).path());
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(text);
}

} // namespace

class TestGradeOutputs : public QObject
{
    Q_OBJECT

private slots:
    void csvBytes()
    {
        const QByteArray csv = gradesCsv(twoRows());
        const QList<QByteArray> lines = csv.split('\n');
        QCOMPARE(lines.value(0),
                 QByteArray("submission,scene,verdict,psnr_db,max_error,"
                            "bad_fraction,key,also,file,line,equation,bindings,"
                            "seconds,mistakes,program,student,participant,page_fidelity,"
                            "page_own_scene,page_javascript,page_error"));
        QCOMPARE(lines.value(1),
                 QByteArray("alice,check.json,pass,inf,0,0.000000,,,,,guarded,,0.50,,,,,,,,"));
        // The formula gets a ', the quote is doubled, "%1" stays as written.
        QCOMPARE(lines.value(2),
                 QByteArray("\"'=SUM(A1),\"\"x\"\" %1\",check.json,fail,23.46,145,0.250000,"
                            "reflect-incident,view-vector,x/a.frag,3,guarded,,1.25,"
                            "reflect-incident,,,,,,,"));
        QCOMPARE(csv, gradesCsv(twoRows())); // the same rows, the same bytes
        // grade --pages: the fidelity, the JavaScript half's mistakes, why a
        // page was not run; what a page said is data, never a formula.
        GradeResults withPages = twoRows();
        SubmissionPage checked;
        checked.largestDifference = 1;
        checked.mistakes = {QStringLiteral("normals-face cloud.obj")};
        SubmissionPage failed;
        failed.error = QStringLiteral("=HYPERLINK(\"x\")");
        withPages.pages = {checked, failed};
        const QList<QByteArray> paged = gradesCsv(withPages).split('\n');
        QVERIFY(paged.value(1).endsWith(",1,,normals-face cloud.obj,"));
        QVERIFY2(paged.value(2).endsWith(",,,,\"'=HYPERLINK(\"\"x\"\")\""),
                 paged.value(2).constData());
    }

    void reportEscapesAndQuotes()
    {
        const QString html = gradeReportHtml(twoRows());
        QVERIFY(html.contains(QStringLiteral("=SUM(A1),&quot;x&quot; %1")));
        QVERIFY(!html.contains(QStringLiteral("\"x\"")));
        QVERIFY(html.contains(QStringLiteral("reflect(L, N);")));
        QCOMPARE(shellQuoted(QStringLiteral("/a/b-c.frag")), QStringLiteral("/a/b-c.frag"));
        QCOMPARE(shellQuoted(QStringLiteral("my shader.frag")), QStringLiteral("'my shader.frag'"));
        QCOMPARE(shellQuoted(QStringLiteral("o'neil $(id)")), QStringLiteral("'o'\\''neil $(id)'"));
    }

    void tableKeepsColumns()
    {
        const QStringList lines = gradesTable(twoRows()).split(QLatin1Char('\n'));
        QCOMPARE(lines.size(), 3);
        QVERIFY(lines[2].contains(QStringLiteral("reflect-incident  x/a.frag:3")));
        QCOMPARE(lines[1].indexOf(QStringLiteral("check.json")),
                 lines[2].indexOf(QStringLiteral("check.json")));
    }

    void classFolderStages()
    {
        QTemporaryDir dir;
        const QString root = dir.path();
        write(root + QStringLiteral("/zoe/shader.VERT"), "void main() { gl_Position = vec4(0); }");
        write(root + QStringLiteral("/amy/deep/er/v.glsl"),
              "void main() { gl_Position = vec4(0); }");
        write(root + QStringLiteral("/amy/f.glsl"), "void main() {}");
        write(root + QStringLiteral("/bo/a.frag"), "");
        write(root + QStringLiteral("/bo/b.fs"), "");
        write(root + QStringLiteral("/cy/readme.md"), "");
        write(root + QStringLiteral("/.git/x.frag"), "");
        write(root + QStringLiteral("/loose.frag"), "");
        const ClassFolder c = readClassFolder(root);
        QVERIFY(c.error.isEmpty());
        QCOMPARE(c.submissions.size(), std::size_t(4));
        QCOMPARE(c.submissions[0].name, QStringLiteral("amy"));
        QVERIFY(c.submissions[0].vertex.endsWith(QStringLiteral("deep/er/v.glsl")));
        QVERIFY(c.submissions[0].fragment.endsWith(QStringLiteral("amy/f.glsl")));
        QCOMPARE(c.submissions[1].name, QStringLiteral("bo"));
        QVERIFY(c.submissions[1].error.contains(QStringLiteral("a.frag, b.fs")));
        QVERIFY(c.submissions[1].fragment.isEmpty());
        QVERIFY(c.submissions[2].error.contains(QStringLiteral("no shader file")));
        QCOMPARE(c.submissions[3].name, QStringLiteral("zoe"));
        QVERIFY(c.submissions[3].vertex.endsWith(QStringLiteral("shader.VERT")));
        QVERIFY(c.submissions[3].fragment.isEmpty()); // the shipped one, later
        QVERIFY(c.submissions[3].error.isEmpty());
    }

    void classFolderErrors()
    {
        QTemporaryDir dir;
        QVERIFY(readClassFolder(dir.filePath(QStringLiteral("nosuch")))
                    .error.contains(QStringLiteral("no such folder")));
        QVERIFY(readClassFolder(dir.path()).error.contains(QStringLiteral("no submission")));
        write(dir.filePath(QStringLiteral("file")), "");
        QVERIFY(readClassFolder(dir.filePath(QStringLiteral("file")))
                    .error.contains(QStringLiteral("not a folder")));
    }
};

QTEST_GUILESS_MAIN(TestGradeOutputs)
#include "tst_gradeoutputs.moc"
