// `phonglab bench` as a script sees it: --quick writes a well-formed
// results.csv, fit.csv and chart (PNG + SVG), prints the table and the fit,
// and finishes in time; bad arguments are usage errors (exit 2), a bad scene
// a failure (exit 1) with nothing half-written.
#include "PhonglabProcess.h"
#include "TestPaths.h"
#include "bench/BenchResult.h"
#include "bench/ErrorBudget.h"

#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>
#include <QXmlStreamReader>

#include <cmath>

using namespace phonglab;
using namespace phonglab::test;

namespace {

QString readText(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly | QIODevice::Text) ? QString::fromUtf8(file.readAll())
                                                            : QString();
}

} // namespace

class TestCliBench : public QObject
{
    Q_OBJECT

private slots:
    void quickRunWritesCsvAndChart();
    void usageErrors_data();
    void usageErrors();
    void badSceneFails();
    void pathRunReportsFramesOverBudget();
    void badPathFails();

private:
    QTemporaryDir m_dir;
};

void TestCliBench::quickRunWritesCsvAndChart()
{
    const QString out = m_dir.filePath(QStringLiteral("quick"));
    QElapsedTimer clock;
    clock.start();
    const ProcessRun r = runPhonglab(
        {QStringLiteral("bench"), QStringLiteral("--quick"), QStringLiteral("--out"), out}, 240000);
    const double seconds = clock.elapsed() / 1000.0;
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    qInfo("phonglab bench --quick took %.1f s here (about 20 s on two idle cores, as documented)",
          seconds);
    const QString stdoutText = QString::fromUtf8(r.out);
    QVERIFY2(stdoutText.contains(QStringLiteral("frame ms")), qPrintable(stdoutText.left(400)));
    QVERIFY2(stdoutText.contains(QStringLiteral("fit to budget")),
             qPrintable(stdoutText.right(800)));

    // results.csv: the documented header, one well-formed row per configuration.
    const QString csv = readText(out + QStringLiteral("/results.csv"));
    QVERIFY(!csv.isEmpty());
    QCOMPARE(csv.section(QLatin1Char('\n'), 0, 0).split(QLatin1Char(',')), benchCsvColumns());
    const Result<std::vector<BenchRow>> read = benchRowsFromCsv(csv);
    QVERIFY2(read, qPrintable(read.error()));
    const std::vector<BenchRow> &rows = *read;
    // Two scenes (default: tree and cloud with 2 lights; sphere: 1 light),
    // 3 details, 5 methods; light setups 1, 4, 8 (+ the default's own 2);
    // and at the default's own lights one row per object (tree, cloud).
    QCOMPARE(rows.size(), std::size_t((4 + 3) * 3 * 5 + 2 * 3 * 5));
    const auto objectRows = std::count_if(rows.begin(), rows.end(),
                                          [](const BenchRow &r) { return !r.isWholeScene(); });
    QCOMPARE(objectRows, 2 * 3 * 5);
    // The table prints every row, the object it measured named: the whole
    // scene at its own lights too, not only the objects drawn alone.
    const auto tableLines = [](const QString &text) {
        static const QRegularExpression row(QStringLiteral("^(default|sphere) +"));
        QStringList lines;
        for (const QString &line : text.split(QLatin1Char('\n')))
            if (row.match(line).hasMatch())
                lines << line;
        return lines;
    };
    const QStringList table = tableLines(stdoutText);
    QCOMPARE(table.size(), qsizetype(rows.size()));
    QCOMPARE(table.filter(QStringLiteral(" whole scene ")).size(),
             qsizetype(rows.size()) - objectRows);
    QCOMPARE(
        table.filter(QRegularExpression(QStringLiteral("^default +whole scene .* 2\\* "))).size(),
        qsizetype(3 * 5));
    QVERIFY2(!table.filter(QStringLiteral(" tree.obj ")).isEmpty(), qPrintable(table.join('\n')));
    QVERIFY2(stdoutText.contains(QStringLiteral("per-object fit")),
             qPrintable(stdoutText.right(800)));
    QVERIFY2(stdoutText.contains(QStringLiteral("limits the saving"))
                 || stdoutText.contains(QStringLiteral("every object at its fastest")),
             qPrintable(stdoutText.right(800)));
    QVERIFY2(stdoutText.contains(QStringLiteral("drawn whole:"))
                 && stdoutText.contains(QStringLiteral("(within budget)")),
             qPrintable(stdoutText.right(800)));
    QSet<QString> methods, scenes;
    for (const BenchRow &row : rows) {
        methods.insert(row.method);
        scenes.insert(row.scene);
        QVERIFY(row.frames >= 20);
        QVERIFY(row.frameMs > 0 && std::isfinite(row.frameMs));
        QVERIFY(row.cpuSubmitMs >= 0 && row.cpuSubmitMs <= row.frameMs * 1.5 + 1.0);
        QVERIFY(row.triangles > 0);
        QVERIFY(row.pixelsCompared > 1000);
        QVERIFY(row.maxError >= 0 && row.maxError <= 255);
        QVERIFY(row.rmse >= 0);
    }
    QCOMPARE(methods, (QSet<QString>{"flat", "gouraud", "faceted", "blinn-phong", "phong"}));
    QCOMPARE(scenes, (QSet<QString>{"default", "sphere"}));

    // The fit: one line per scene; its choice meets the default budget.
    const QString fit = readText(out + QStringLiteral("/fit.csv"));
    const QStringList fitLines = fit.trimmed().split(QLatin1Char('\n'));
    QCOMPARE(fitLines.size(), 3);
    for (const BenchRow &row : rows) {
        if (!row.sceneLights)
            continue;
        const QString line = fitLines[row.scene == QLatin1String("default") ? 1 : 2];
        const QStringList f = line.split(QLatin1Char(','));
        if (f.value(2) == row.method && f.value(3).toDouble() == row.detail)
            QVERIFY2(row.maxError <= 2, qPrintable(line));
    }

    // The chart: a PNG of the grid and an SVG naming every method and the front.
    QImage png(out + QStringLiteral("/chart.png"));
    QVERIFY(!png.isNull());
    QVERIFY(png.width() >= 640 * 3 && png.height() >= 440 * 2);
    const QString svg = readText(out + QStringLiteral("/chart.svg"));
    QXmlStreamReader xml(svg);
    while (!xml.atEnd())
        xml.readNext();
    QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
    for (const QString &name : {QStringLiteral("gouraud"), QStringLiteral("Pareto front")})
        QVERIFY2(svg.contains(name), qPrintable(name));

    // --from fits the same rows again against another budget without
    // measuring: an impossible PSNR leaves nothing chosen, and says so.
    const QString refit = m_dir.filePath(QStringLiteral("refit"));
    const ProcessRun again = runPhonglab(
        {QStringLiteral("bench"), QStringLiteral("--from"), out + QStringLiteral("/results.csv"),
         QStringLiteral("--budget"), QStringLiteral("psnr:99"), QStringLiteral("--out"), refit});
    QVERIFY2(again.exitCode == 0, qPrintable(again.err));
    QVERIFY(!QFile::exists(refit + QStringLiteral("/results.csv")));
    QVERIFY(QFile::exists(refit + QStringLiteral("/chart.png")));
    QVERIFY2(QString::fromUtf8(again.out).contains(QStringLiteral("nothing meets PSNR")),
             again.out.constData());
    QCOMPARE(tableLines(QString::fromUtf8(again.out)), table); // --from: the same table
    QVERIFY2(QString::fromUtf8(again.out).contains(QStringLiteral("per-object fit (PSNR")),
             again.out.constData()); // and the per-object fit from the rows
    const QStringList refitLines =
        readText(refit + QStringLiteral("/fit.csv")).trimmed().split(QLatin1Char('\n'));
    QCOMPARE(refitLines.size(), 3);
    QCOMPARE(refitLines[1].split(QLatin1Char(',')).value(2), QString()); // no method chosen
}

void TestCliBench::usageErrors_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::newRow("frames below 20")
        << QStringList{QStringLiteral("--frames"), QStringLiteral("5")};
    QTest::newRow("unknown method")
        << QStringList{QStringLiteral("--methods"), QStringLiteral("phong,toon")};
    QTest::newRow("detail above 1")
        << QStringList{QStringLiteral("--details"), QStringLiteral("1,2")};
    QTest::newRow("detail zero") << QStringList{QStringLiteral("--details"), QStringLiteral("0")};
    QTest::newRow("lights 9") << QStringList{QStringLiteral("--lights"), QStringLiteral("9")};
    QTest::newRow("bad budget") << QStringList{QStringLiteral("--budget"), QStringLiteral("lots")};
    QTest::newRow("bad size") << QStringList{QStringLiteral("--size"), QStringLiteral("4x4")};
    QTest::newRow("stray argument") << QStringList{QStringLiteral("scene.json")};
    QTest::newRow("unknown option") << QStringList{QStringLiteral("--fast")};
    QTest::newRow("from with scene")
        << QStringList{QStringLiteral("--from"), QStringLiteral("r.csv"), QStringLiteral("--scene"),
                       QStringLiteral("s.json")};
    QTest::newRow("path with methods")
        << QStringList{QStringLiteral("--path"), QStringLiteral("orbit"),
                       QStringLiteral("--methods"), QStringLiteral("phong")};
    QTest::newRow("path frames without path")
        << QStringList{QStringLiteral("--path-frames"), QStringLiteral("4")};
    QTest::newRow("path frames 1")
        << QStringList{QStringLiteral("--path"), QStringLiteral("dolly"),
                       QStringLiteral("--path-frames"), QStringLiteral("1")};
}

void TestCliBench::usageErrors()
{
    QFETCH(QStringList, args);
    const ProcessRun r = runPhonglab(QStringList{QStringLiteral("bench")} + args);
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains(QStringLiteral("phonglab: error: ")), qPrintable(r.err));
    QVERIFY2(r.err.contains(QStringLiteral("usage: phonglab bench")), qPrintable(r.err));
}

void TestCliBench::badSceneFails()
{
    const QString out = m_dir.filePath(QStringLiteral("bad"));
    const QString scene = m_dir.filePath(QStringLiteral("broken.json"));
    QFile file(scene);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("{\"objects\": [ {\"mesh\": 3} ]}");
    file.close();
    const ProcessRun r = runPhonglab(
        {QStringLiteral("bench"), QStringLiteral("--scene"), scene, QStringLiteral("--out"), out});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains(QStringLiteral("broken.json")), qPrintable(r.err));
    QVERIFY(!QFile::exists(out + QStringLiteral("/results.csv")));

    // A results file that is not one: exit 1 naming it.
    const ProcessRun bad = runPhonglab(
        {QStringLiteral("bench"), QStringLiteral("--from"), scene, QStringLiteral("--out"), out});
    QCOMPARE(bad.exitCode, 1);
    QVERIFY2(bad.err.contains(QStringLiteral("broken.json")), qPrintable(bad.err));
}

// --path: the line scripts read, path.csv with a row per frame, the chart.
void TestCliBench::pathRunReportsFramesOverBudget()
{
    const QString out = m_dir.filePath(QStringLiteral("path"));
    const ProcessRun r = runPhonglab(
        {QStringLiteral("bench"), QStringLiteral("--path"), QStringLiteral("dolly"),
         QStringLiteral("--path-frames"), QStringLiteral("4"), QStringLiteral("--scene"),
         sourcePath(QStringLiteral("assets/scenes/sphere.json")), QStringLiteral("--size"),
         QStringLiteral("160x120"), QStringLiteral("--frames"), QStringLiteral("3"),
         QStringLiteral("--out"), out});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const QString text = QString::fromUtf8(r.out);
    QVERIFY2(text.contains(QStringLiteral("\nframes over budget: 0 of 4\n")), qPrintable(text));
    const QStringList csv = readText(out + QStringLiteral("/path.csv")).trimmed().split(u'\n');
    QCOMPARE(csv.size(), 5);
    QVERIFY(csv.front().startsWith(QStringLiteral("scene,path,frame,eye_x")));
    QVERIFY(csv.at(1).startsWith(QStringLiteral("sphere,dolly,0,")));
    QVERIFY(QFileInfo(out + QStringLiteral("/path.png")).size() > 1000);
    QVERIFY(QFileInfo(out + QStringLiteral("/path.svg")).size() > 1000);
}

void TestCliBench::badPathFails()
{
    const QString keys = m_dir.filePath(QStringLiteral("keys.json"));
    QFile file(keys);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"keyframes": [{"eye": [0, 0, 4]}, {"eye": "far"}]})");
    file.close();
    const ProcessRun r = runPhonglab(
        {QStringLiteral("bench"), QStringLiteral("--path"), keys, QStringLiteral("--scene"),
         sourcePath(QStringLiteral("assets/scenes/sphere.json")), QStringLiteral("--out"),
         m_dir.filePath(QStringLiteral("bad-path"))});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains(QStringLiteral("keys.json: keyframes[1].eye: expected 3 numbers")),
             qPrintable(r.err));
}

QTEST_GUILESS_MAIN(TestCliBench)
#include "tst_clibench.moc"
