// WebGL projects as students hand them in: `check
// --project` and `grade` find the shaders in pages, inline scripts, script
// files and files of their own, check each program that lights on its own
// (the `program` column), leave out an unlit one with a note, and report
// every error at the line of the file handed in.
#include "PhonglabProcess.h"
#include "TestFiles.h"
#include "TestPaths.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using namespace phonglab::test;

namespace {

QByteArray course(const char *path)
{
    return readTestFile(sourcePath(QStringLiteral("tests/data/course/") + QLatin1String(path)));
}

QByteArray script(const char *id, const char *type, const QByteArray &code)
{
    return "<script id=\"" + QByteArray(id) + "\" type=\"" + type + "\">\n" + code + "</script>\n";
}

// ada: Angel & Shreiner's page, two programs that light and a grid that does not.
QByteArray angelPage()
{
    const QByteArray v = course("mediump/phong.vert"), f = course("mediump/phong.frag");
    return "<!DOCTYPE html>\n<html><head><title>Lab 3</title>\n"
        + script("vertex-shader", "x-shader/x-vertex", v)
        + script("fragment-shader", "x-shader/x-fragment", f)
        + script("gouraud-vertex-shader", "x-shader/x-vertex", v)
        + script("gouraud-fragment-shader", "x-shader/x-fragment", f)
        + "<script id=\"grid-vs\" type=\"notjs\">attribute vec4 p; void main() { gl_Position = p; }"
          "</script>\n<script id=\"grid-fs\" type=\"notjs\">precision mediump float;\n"
          "void main() { gl_FragColor = vec4(0.5); }</script>\n"
          "<script>\nprogram = initShaders(gl, \"vertex-shader\", \"fragment-shader\");\n"
          "gouraud = initShaders(gl, \"gouraud-vertex-shader\", \"gouraud-fragment-shader\");\n"
          "grid = initShaders(gl, \"grid-vs\", "
          "\"grid-fs\");\n</script>\n</head><body></body></html>\n";
}

// ben: MDN's way, template literals in an inline script.
QByteArray inlineScriptPage(const QByteArray &vertex, const QByteArray &fragment)
{
    return "<!DOCTYPE html>\n<html>\n<body>\n<canvas id=\"glcanvas\"></canvas>\n<script>\n"
           "// the shaders, as the tutorial writes them\n"
           "const vsSource = `"
        + vertex + "`;\n\nconst fsSource = `" + fragment
        + "`;\nconst shaderProgram = initShaderProgram(gl, vsSource, fsSource);\n"
          "</script>\n</body>\n</html>\n";
}

// cleo: a three.js ShaderMaterial, its stages in script elements.
QByteArray threePage()
{
    return "<html><body>\n"
        + script("vertexShader", "x-shader/x-vertex", course("threejs/phong.vert"))
        + script("fragmentShader", "x-shader/x-fragment", course("threejs/phong.frag"))
        + "<script type=\"module\">\nconst material = new THREE.ShaderMaterial({\n"
          "  vertexShader: document.getElementById('vertexShader').textContent,\n"
          "  fragmentShader: document.getElementById('fragmentShader').textContent,\n"
          "});\n</script></body></html>\n";
}

QMap<QString, QStringList> rowsByStudentAndProgram(const QByteArray &csv)
{
    QMap<QString, QStringList> rows;
    const QList<QByteArray> lines = csv.split('\n');
    const qsizetype program =
        QString::fromUtf8(lines.first()).split(QLatin1Char(',')).indexOf(QStringLiteral("program"));
    for (const QByteArray &line : lines.mid(1)) {
        if (line.isEmpty())
            continue;
        const QStringList cells = QString::fromUtf8(line).split(QLatin1Char(','));
        rows[cells.first() + QLatin1Char('/') + cells.value(program)] = cells;
    }
    return rows;
}

} // namespace

class TestCliProject : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    QByteArray m_broken;

private slots:
    void initTestCase()
    {
        const QByteArray v =
            readTestFile(sourcePath(QStringLiteral("assets/shaders/webgl2/phong.vert")));
        const QByteArray f =
            readTestFile(sourcePath(QStringLiteral("assets/shaders/webgl2/phong.frag")));
        const QString root = m_dir.filePath(QStringLiteral("class"));
        QVERIFY(writeTestFile(root + QStringLiteral("/ada/index.html"), angelPage()));
        QVERIFY(writeTestFile(root + QStringLiteral("/ben/index.html"), inlineScriptPage(v, f)));
        QVERIFY(writeTestFile(root + QStringLiteral("/cleo/index.html"), threePage()));
        QByteArray broken = f;
        broken.replace("normalize(", "normalise(");
        m_broken = inlineScriptPage(v, broken);
        QVERIFY(writeTestFile(root + QStringLiteral("/dan/index.html"), m_broken));
        // eve: a script file that fetches files of their own.
        QVERIFY(writeTestFile(root + QStringLiteral("/eve/index.html"),
                              "<html><body><script src=\"main.js\"></script></body></html>\n"));
        QVERIFY(writeTestFile(root + QStringLiteral("/eve/main.js"),
                              "const vs = await (await fetch('shaders/phong.vert')).text();\n"
                              "const fs = await (await fetch('shaders/phong.frag')).text();\n"));
        QVERIFY(writeTestFile(root + QStringLiteral("/eve/shaders/phong.vert"), v));
        QVERIFY(writeTestFile(root + QStringLiteral("/eve/shaders/phong.frag"), f));
    }

    void checkFindsTheProgramAndItsLines()
    {
        const QString scene = sourcePath(QStringLiteral("tests/data/course/scene.json"));
        const QString ben = m_dir.filePath(QStringLiteral("class/ben/index.html"));
        const ProcessRun pass =
            runPhonglab({QStringLiteral("check"), scene, QStringLiteral("--project"), ben,
                         QStringLiteral("--size"), QStringLiteral("160x120")});
        QVERIFY2(pass.exitCode == 0, qPrintable(pass.err + pass.out));
        const QString dan = m_dir.filePath(QStringLiteral("class/dan"));
        const ProcessRun broken = runPhonglab(
            {QStringLiteral("check"), scene, QStringLiteral("--project"), dan,
             QStringLiteral("--size"), QStringLiteral("160x120"), QStringLiteral("--json")});
        QCOMPARE(broken.exitCode, 1);
        const QJsonObject error = QJsonDocument::fromJson(broken.out)
                                      .object()
                                      .value(QStringLiteral("errors"))
                                      .toArray()
                                      .first()
                                      .toObject();
        QVERIFY2(error.value(QStringLiteral("file"))
                     .toString()
                     .endsWith(QStringLiteral("dan/index.html")),
                 qPrintable(broken.out));
        QCOMPARE(error.value(QStringLiteral("line")).toInt(), lineOf(m_broken, "normalise("));
        // Two programs light in ada's page: one must be named.
        const QString ada = m_dir.filePath(QStringLiteral("class/ada"));
        const ProcessRun two =
            runPhonglab({QStringLiteral("check"), scene, QStringLiteral("--project"), ada,
                         QStringLiteral("--size"), QStringLiteral("160x120")});
        QCOMPARE(two.exitCode, 1);
        QVERIFY2(two.err.contains("--program"), qPrintable(two.err));
        const ProcessRun named =
            runPhonglab({QStringLiteral("check"), scene, QStringLiteral("--project"), ada,
                         QStringLiteral("--program"), QStringLiteral("gouraud"),
                         QStringLiteral("--size"), QStringLiteral("160x120")});
        QVERIFY2(named.exitCode == 0 && named.out.contains("grid: not checked"),
                 qPrintable(named.err + named.out));
    }

    void gradeChecksEveryProgramThatLights()
    {
        const QString out = m_dir.filePath(QStringLiteral("out"));
        const ProcessRun run = runPhonglab(
            {QStringLiteral("grade"), m_dir.filePath(QStringLiteral("class")),
             QStringLiteral("--scene"), sourcePath(QStringLiteral("tests/data/course/scene.json")),
             QStringLiteral("--size"), QStringLiteral("160x120"), QStringLiteral("--define"),
             QStringLiteral("NUM_LIGHTS=2"), QStringLiteral("--out"), out, QStringLiteral("--jobs"),
             QStringLiteral("2")});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        const QByteArray csv = readTestFile(out + QStringLiteral("/grades.csv"));
        QVERIFY(csv.startsWith("submission,scene,verdict,"));
        QVERIFY(csv.left(csv.indexOf('\n'))
                    .endsWith(",mistakes,program,student,participant,page_fidelity,page_own_scene,"
                              "page_javascript,"
                              "page_error"));
        const QMap<QString, QStringList> rows = rowsByStudentAndProgram(csv);
        QCOMPARE(rows.keys(),
                 (QStringList{QStringLiteral("ada/gouraud"), QStringLiteral("ada/index"),
                              QStringLiteral("ben/index"), QStringLiteral("cleo/index"),
                              QStringLiteral("dan/index"), QStringLiteral("eve/phong")}));
        for (const char *pass :
             {"ada/gouraud", "ada/index", "ben/index", "cleo/index", "eve/phong"})
            QVERIFY2(rows.value(QLatin1String(pass)).value(2) == QLatin1String("pass"),
                     qPrintable(QLatin1String(pass) + QLatin1Char(' ')
                                + rows.value(QLatin1String(pass)).join(QLatin1Char(','))));
        const QStringList dan = rows.value(QStringLiteral("dan/index"));
        QCOMPARE(dan.value(2), QStringLiteral("error"));
        QCOMPARE(dan.value(8), QStringLiteral("dan/index.html"));
        QCOMPARE(dan.value(9).toInt(), lineOf(m_broken, "normalise("));
        // The unlit grid: said beside ada's rows, never checked.
        const QJsonArray json =
            QJsonDocument::fromJson(readTestFile(out + QStringLiteral("/grades.json")))
                .object()
                .value(QStringLiteral("rows"))
                .toArray();
        bool gridNoted = false;
        for (const QJsonValue &r : json)
            if (r.toObject().value(QStringLiteral("submission")).toString() == QLatin1String("ada"))
                for (const QJsonValue &n : r.toObject().value(QStringLiteral("notes")).toArray())
                    gridNoted =
                        gridNoted || n.toString().contains(QStringLiteral("grid: not checked"));
        QVERIFY(gridNoted);
        // The report quotes dan's line from the page, and names ada's programs.
        const QByteArray report = readTestFile(out + QStringLiteral("/report.html"));
        QVERIFY(report.contains("normalise("));
        QVERIFY(report.contains("ada · gouraud") && report.contains("ada · index"));
    }

    void gradeTakesOneProgramWhereAsked()
    {
        const QString out = m_dir.filePath(QStringLiteral("out-gouraud"));
        const ProcessRun run = runPhonglab(
            {QStringLiteral("grade"), m_dir.filePath(QStringLiteral("class")),
             QStringLiteral("--scene"), sourcePath(QStringLiteral("tests/data/course/scene.json")),
             QStringLiteral("--size"), QStringLiteral("96x72"), QStringLiteral("--define"),
             QStringLiteral("NUM_LIGHTS=2"), QStringLiteral("--program"), QStringLiteral("gouraud"),
             QStringLiteral("--out"), out});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        const QMap<QString, QStringList> rows =
            rowsByStudentAndProgram(readTestFile(out + QStringLiteral("/grades.csv")));
        // ada's gouraud alone; the others say they have no such program.
        QCOMPARE(rows.value(QStringLiteral("ada/gouraud")).value(2), QStringLiteral("pass"));
        QVERIFY(!rows.contains(QStringLiteral("ada/index")));
        QCOMPARE(rows.value(QStringLiteral("ben/index")).value(2), QStringLiteral("error"));
        QCOMPARE(rows.size(), 5);
    }
};

QTEST_GUILESS_MAIN(TestCliProject)
#include "tst_cliproject.moc"
