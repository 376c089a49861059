// Speed-against-accuracy charts: a 2-scene × 3-light-setup grid written as
// PNG and SVG without showing a window, the SVG naming every method and the
// Pareto front, and unwritable paths refused with a reason.

#include "ResultChecks.h"
#include "charts/SpeedAccuracyChart.h"
#include "core/support/Language.h"

#include <QApplication>
#include <QFile>
#include <QGraphicsScene>
#include <QImage>
#include <QTemporaryDir>
#include <QXmlStreamReader>
#include <QtCharts/QChart>
#include <QtCharts/QLegendMarker>
#include <QtCharts/QLogValueAxis>
#include <QtCharts/QValueAxis>
#include <QtCharts/QXYSeries>
#include <QtTest>

using namespace phonglab;

namespace {

const QStringList kMethods = {"flat", "gouraud", "blinn-phong", "phong"};
const std::vector<double> kDetails = {1.0, 0.5, 0.25, 0.1};

// Frame time grows with triangles, lights and method cost; error falls with
// detail and is zero for full-detail Phong.
std::vector<BenchRow> syntheticRows()
{
    std::vector<BenchRow> rows;
    const QStringList scenes = {"default", "teapot, glossy"};
    const std::vector<std::pair<int, bool>> setups = {{1, false}, {2, true}, {8, false}};
    for (int s = 0; s < scenes.size(); ++s) {
        for (const auto &[lights, own] : setups) {
            for (int m = 0; m < kMethods.size(); ++m) {
                for (double detail : kDetails) {
                    BenchRow r;
                    r.scene = scenes[s];
                    r.method = kMethods[m];
                    r.detail = detail;
                    r.triangles = qint64(13650 * detail) * (s + 1);
                    r.lights = lights;
                    r.sceneLights = own;
                    r.frameMs = 0.4 + r.triangles * 1e-4 * (1 + 0.1 * lights) * (1 + 0.3 * m);
                    const double methodError = (3 - m) * 1.5 + (m == 2 ? 0.4 : 0.0);
                    r.rmse = methodError + (1 - detail) * 4;
                    r.maxError = int(r.rmse * 3);
                    r.psnr = r.rmse > 0 ? 20 * std::log10(255 / r.rmse)
                                        : std::numeric_limits<double>::infinity();
                    rows.push_back(r);
                }
            }
        }
    }
    return rows;
}

// Every piece of text in an SVG document (element text and attributes).
bool readSvg(const QString &path, QString *allText, QString *error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = file.errorString();
        return false;
    }
    QXmlStreamReader xml(&file);
    bool sawSvg = false;
    while (!xml.atEnd()) {
        xml.readNext();
        if (xml.isStartElement() && xml.name() == QLatin1String("svg"))
            sawSvg = true;
        if (xml.isCharacters())
            *allText += xml.text().toString() + '\n';
    }
    if (xml.hasError()) {
        *error = QStringLiteral("line %1: %2").arg(xml.lineNumber()).arg(xml.errorString());
        return false;
    }
    if (!sawSvg) {
        *error = QStringLiteral("no <svg> element");
        return false;
    }
    return true;
}

} // namespace

class TestBenchChart : public QObject
{
    Q_OBJECT

private slots:
    void writesPngAndSvgGrid()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString png = dir.filePath("charts.png");
        const QString svg = dir.filePath("charts.svg");
        QString error;
        QVERIFY_OK(writeSpeedAccuracyCharts(syntheticRows(), png, svg, QSize(600, 420)));

        QImage image(png);
        QVERIFY(!image.isNull());
        QCOMPARE(image.size(), QSize(3 * 600, 2 * 420)); // 3 light setups × 2 scenes
        // Something was drawn: not a blank page.
        QSet<QRgb> colors;
        for (int y = 0; y < image.height(); y += 7)
            for (int x = 0; x < image.width(); x += 7)
                colors.insert(image.pixel(x, y));
        QVERIFY2(colors.size() > 10, qPrintable(QString::number(colors.size())));

        QString text;
        QVERIFY2(readSvg(svg, &text, &error), qPrintable(error));
        for (const QString &method : kMethods)
            QVERIFY2(text.contains(method), qPrintable(method));
        QVERIFY(text.contains("Pareto front"));
        QVERIFY(text.contains("frame time (ms"));
        QVERIFY(text.contains("8-bit steps"));
        QVERIFY(text.contains("teapot, glossy"));
        QVERIFY(text.contains("25 %"));

        // A scene with fewer setups takes the leftmost columns of its row:
        // the grid is as wide as the scene with the most.
        std::vector<BenchRow> uneven;
        for (const BenchRow &r : syntheticRows())
            if (r.scene == QLatin1String("default") ? r.lights != 2 : r.lights == 2)
                uneven.push_back(r);
        const QString unevenPng = dir.filePath("uneven.png");
        QVERIFY_OK(writeSpeedAccuracyCharts(uneven, unevenPng, QString(), QSize(600, 420)));
        QCOMPARE(QImage(unevenPng).size(), QSize(2 * 600, 2 * 420));
        QFile::remove(unevenPng);

        // Written atomically: no temporary files left beside them.
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files).size(), 2);

        // PHONGLAB_KEEP_CHARTS=<folder>: keep a copy to look at.
        const QString keep = qEnvironmentVariable("PHONGLAB_KEEP_CHARTS");
        if (!keep.isEmpty()) {
            QDir().mkpath(keep);
            QFile::remove(keep + "/speed-accuracy.png");
            QFile::remove(keep + "/speed-accuracy.svg");
            QFile::copy(png, keep + "/speed-accuracy.png");
            QFile::copy(svg, keep + "/speed-accuracy.svg");
        }
    }

    void chartHasSeriesPerMethodAndFront()
    {
        std::vector<BenchRow> rows;
        for (const BenchRow &r : syntheticRows())
            if (r.scene == "default" && r.lights == 2)
                rows.push_back(r);
        QGraphicsScene scene;
        QChart *chart = createSpeedAccuracyChart(rows, "default");
        scene.addItem(chart); // the scene owns it
        chart->setGeometry(0, 0, 640, 440);
        QCoreApplication::sendPostedEvents();
        QCOMPARE(chart->title(), QStringLiteral("default"));
        QStringList legend;
        for (QLegendMarker *marker : chart->legend()->markers())
            if (marker->isVisible())
                legend << marker->label();
        QCOMPARE(legend, (QStringList{"flat", "gouraud", "blinn-phong", "phong", "Pareto front"}));

        // Points along each method's line run in order of detail.
        for (QAbstractSeries *series : chart->series()) {
            auto *xy = qobject_cast<QXYSeries *>(series);
            QVERIFY(xy);
            if (series->name() == "phong" && xy->count() == int(kDetails.size())) {
                // Frame time rises with detail in the synthetic data.
                for (int i = 1; i < xy->count(); ++i)
                    QVERIFY(xy->at(i).x() > xy->at(i - 1).x());
            }
        }
        // Full-detail Phong has zero error and the rest span < 2 decades... or
        // not: either way the y axis can show it.
        QCOMPARE(chart->axes(Qt::Vertical).size(), 1);
    }

    void logAxisWhenErrorsSpanDecades()
    {
        std::vector<BenchRow> rows;
        const double errors[] = {0.0, 0.01, 0.3, 5.0, 40.0};
        for (int i = 0; i < 5; ++i) {
            BenchRow r;
            r.scene = "s";
            r.method = "phong";
            r.detail = 1.0 - i * 0.2;
            r.frameMs = 5.0 - i;
            r.rmse = errors[i];
            rows.push_back(r);
        }
        std::unique_ptr<QChart> chart(createSpeedAccuracyChart(rows, "log"));
        auto *log = qobject_cast<QLogValueAxis *>(chart->axes(Qt::Vertical).value(0));
        QVERIFY(log);
        QVERIFY(log->min() > 0);
        QVERIFY(log->min() < 0.01); // zero drawn below the smallest error
        QVERIFY2(log->titleText().contains("0 drawn at"), qPrintable(log->titleText()));
        const QString keep = qEnvironmentVariable("PHONGLAB_KEEP_CHARTS");
        if (!keep.isEmpty()) {
            QVERIFY_OK(writeChartImages(chart.get(), keep + "/log-axis.png", QString()));
        }

        // A narrow span stays linear and starts at zero.
        for (BenchRow &r : rows)
            r.rmse = 1 + r.rmse / 100;
        chart.reset(createSpeedAccuracyChart(rows, "linear"));
        auto *linear = qobject_cast<QValueAxis *>(chart->axes(Qt::Vertical).value(0));
        QVERIFY(linear);
        QCOMPARE(linear->min(), 0.0);
    }

    // The axes carry their numbers (a localized axis draws none without a
    // precision in its format), written as the run's sentences write them.
    void axesAreLabelledInTheSentencesNumbers()
    {
        std::vector<BenchRow> rows;
        const double errors[] = {0.05, 0.3, 5.0, 40.0};
        for (int i = 0; i < 4; ++i) {
            BenchRow r;
            r.scene = "s";
            r.method = "phong";
            r.detail = 1.0 - i * 0.2;
            r.frameMs = 2.5 * (i + 1);
            r.rmse = errors[i];
            rows.push_back(r);
        }
        const auto labels = [&](const QString &language) {
            useLanguage(language);
            std::unique_ptr<QChart> chart(createSpeedAccuracyChart(rows, "axes"));
            QTemporaryDir dir;
            const QString svg = dir.filePath("axes.svg");
            QString text, error;
            if (!writeChartImages(chart.get(), dir.filePath("axes.png"), svg)
                || !readSvg(svg, &text, &error))
                return QStringList{error};
            return text.split('\n');
        };
        const QStringList english = labels("en");
        const QStringList german = labels("de");
        useLanguage("en");
        for (const char *tick : {"0.1", "1", "10", "100"}) // the log axis' decades
            QVERIFY2(english.contains(tick), qPrintable(english.join(" | ")));
        QVERIFY2(german.contains("0,1") && german.contains("10"), qPrintable(german.join(" | ")));
        QVERIFY(!german.contains("0.1"));
    }

    void methodColoursAreFixed()
    {
        QCOMPARE(methodColor("phong"), methodColor("phong"));
        QVERIFY(methodColor("phong") != methodColor("gouraud"));
        QVERIFY(methodColor("flat") != methodColor("blinn-phong"));
        QCOMPARE(methodColor("toon"), methodColor("toon"));
    }

    void unwritablePathFailsWithReason()
    {
        QTemporaryDir dir;
        const QString missing = dir.filePath("no/such/folder/charts.png");
        const Result<> noPngFolder =
            writeSpeedAccuracyCharts(syntheticRows(), missing, dir.filePath("ok.svg"));
        QVERIFY(!noPngFolder);
        QVERIFY2(noPngFolder.error().contains(missing), qPrintable(noPngFolder.error()));
        // Nothing half-written beside it.
        QVERIFY(!QFile::exists(dir.filePath("ok.svg")));

        const Result<> noSvgFolder = writeSpeedAccuracyCharts(
            syntheticRows(), dir.filePath("ok.png"), dir.filePath("missing/charts.svg"));
        QVERIFY(!noSvgFolder);
        QVERIFY2(noSvgFolder.error().contains("charts.svg"), qPrintable(noSvgFolder.error()));
        QVERIFY(!QFile::exists(dir.filePath("ok.png")));
    }

    void nothingToDrawIsAnError()
    {
        QTemporaryDir dir;
        const Result<> refusal =
            writeSpeedAccuracyCharts({}, dir.filePath("a.png"), dir.filePath("a.svg"));
        QVERIFY(!refusal);
        QVERIFY(!refusal.error().isEmpty());
    }

    void singleChartImage()
    {
        QTemporaryDir dir;
        std::vector<LabelledSeries> series(2);
        series[0].name = "subdivided";
        series[0].color = Qt::darkCyan;
        series[0].points = {{1.0, 2.0, "area"}, {1.5, 1.0, "angle"}};
        series[1].name = "original";
        series[1].color = Qt::darkRed;
        series[1].points = {{0.5, 4.0, "area"}, {0.8, 3.0, "angle"}};
        std::unique_ptr<QChart> chart(
            createLabelledChart(series, "normals", "time (ms)", "mean error (°)"));
        QVERIFY_OK(
            writeChartImages(chart.get(), dir.filePath("n.png"), QString(), QSize(500, 350)));
        QCOMPARE(QImage(dir.filePath("n.png")).size(), QSize(500, 350));
        QVERIFY(!chart->scene()); // handed back, still ours
    }

    void normalStudyChart()
    {
        // The fields of NormalStudyRow (app/mesh/normals/NormalMethodStudy.h).
        struct Row {
            QString tessellation;
            QString method;
            qint64 triangles;
            double ms;
            double maxAngleDeg;
            double meanAngleDeg;
        };
        const std::vector<Row> rows = {
            {"uv sphere", "area", 960, 0.12, 9.5, 2.1},
            {"uv sphere", "angle", 960, 0.15, 6.0, 1.2},
            {"uv sphere", "unweighted", 960, 0.10, 14.0, 3.4},
            {"icosphere", "area", 1280, 0.14, 4.0, 0.9},
            {"icosphere", "angle", 1280, 0.18, 3.1, 0.8},
            {"icosphere", "unweighted", 1280, 0.11, 4.2, 0.95},
        };
        QTemporaryDir dir;
        const QString png = dir.filePath("normals.png");
        const QString svg = dir.filePath("normals.svg");
        QString error;
        QVERIFY_OK(writeNormalStudyChart(rows, png, svg, QSize(560, 400)));
        QCOMPARE(QImage(png).size(), QSize(560, 400));
        QString text;
        QVERIFY2(readSvg(svg, &text, &error), qPrintable(error));
        for (const char *name : {"uv sphere", "icosphere", "unweighted", "mean angular error"})
            QVERIFY2(text.contains(name), qPrintable(name));
        const Result<> refusal = writeNormalStudyChart(std::vector<Row>{}, png, svg);
        QVERIFY(!refusal);
        const QString keep = qEnvironmentVariable("PHONGLAB_KEEP_CHARTS");
        if (!keep.isEmpty()) {
            QFile::remove(keep + "/normal-study.png");
            QFile::copy(png, keep + "/normal-study.png");
        }
    }
};

int main(int argc, char **argv)
{
    // Charts are widgets; they need a QApplication but never a window.
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    TestBenchChart test;
    return QTest::qExec(&test, argc, argv);
}

#include "tst_benchchart.moc"
