// results.csv: the column interface, exact round trips (NaN, inf, names with
// commas and quotes), columns found by name, and errors that name the line.

#include "bench/BenchResult.h"

#include <QtTest>
#include <cmath>
#include <limits>

using namespace phonglab;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

BenchRow sampleRow()
{
    BenchRow row;
    row.scene = QStringLiteral("default");
    row.method = QStringLiteral("gouraud");
    row.detail = 0.25;
    row.triangles = 3412;
    row.lights = 2;
    row.sceneLights = true;
    row.frameMs = 1.9;
    row.frameMsP90 = 2.0500000000000003;
    row.cpuSubmitMs = 0.1 + 0.2; // 0.30000000000000004
    row.gpuMs = kNaN;
    row.frames = 120;
    row.psnr = 41.23456789012345;
    row.rmse = 1.0 / 3.0;
    row.maxError = 2;
    row.specularPsnr = kInf;
    row.specularRmse = 0;
    row.specularMaxError = 0;
    row.specularPixels = 0;
    row.pixelsCompared = 1234567;
    row.coverageErrors = 3;
    return row;
}

// Same bits, where NaN equals NaN.
bool sameDouble(double a, double b)
{
    if (std::isnan(a) || std::isnan(b))
        return std::isnan(a) && std::isnan(b);
    return a == b && std::signbit(a) == std::signbit(b);
}

void compareRows(const BenchRow &a, const BenchRow &b)
{
    QCOMPARE(a.scene, b.scene);
    QCOMPARE(a.method, b.method);
    QVERIFY(sameDouble(a.detail, b.detail));
    QCOMPARE(a.triangles, b.triangles);
    QCOMPARE(a.lights, b.lights);
    QCOMPARE(a.sceneLights, b.sceneLights);
    QVERIFY2(sameDouble(a.frameMs, b.frameMs), qPrintable(QString::number(b.frameMs, 'g', 17)));
    QVERIFY(sameDouble(a.frameMsP90, b.frameMsP90));
    QVERIFY(sameDouble(a.cpuSubmitMs, b.cpuSubmitMs));
    QVERIFY(sameDouble(a.gpuMs, b.gpuMs));
    QCOMPARE(a.frames, b.frames);
    QVERIFY(sameDouble(a.psnr, b.psnr));
    QVERIFY(sameDouble(a.rmse, b.rmse));
    QCOMPARE(a.maxError, b.maxError);
    QVERIFY(sameDouble(a.specularPsnr, b.specularPsnr));
    QVERIFY(sameDouble(a.specularRmse, b.specularRmse));
    QCOMPARE(a.specularMaxError, b.specularMaxError);
    QCOMPARE(a.specularPixels, b.specularPixels);
    QCOMPARE(a.pixelsCompared, b.pixelsCompared);
    QCOMPARE(a.coverageErrors, b.coverageErrors);
}

QString validCsv(int rows)
{
    std::vector<BenchRow> list(rows, sampleRow());
    return benchRowsToCsv(list);
}

} // namespace

class TestBenchCsv : public QObject
{
    Q_OBJECT

private slots:
    void fileWithoutObjectColumnStillReads()
    {
        // A results.csv from before the per-object rows: no "object" column.
        QStringList header = benchCsvColumns();
        header.removeLast();
        BenchRow row;
        row.scene = QStringLiteral("default");
        row.method = QStringLiteral("phong");
        QString line = benchRowsToCsv({row}).section(QLatin1Char('\n'), 1, 1);
        line.chop(1); // the empty object field and its comma
        const auto read = benchRowsFromCsv(header.join(',') + '\n' + line + '\n');
        QVERIFY2(read, qPrintable(read.error()));
        QCOMPARE(read->size(), std::size_t(1));
        QVERIFY(read->front().isWholeScene());

        BenchRow one = row;
        one.object = QStringLiteral("0: tree, big.obj");
        const auto back = benchRowsFromCsv(benchRowsToCsv({one}));
        QVERIFY2(back, qPrintable(back.error()));
        QCOMPARE(back->front().object, one.object);
    }

    void columnsAreTheInterface()
    {
        const QStringList expected = {
            "scene",        "method",         "detail",       "triangles",       "lights",
            "scene_lights", "frame_ms",       "frame_ms_p90", "cpu_submit_ms",   "gpu_ms",
            "frames",       "psnr_db",        "rmse",         "max_error",       "spec_psnr_db",
            "spec_rmse",    "spec_max_error", "spec_pixels",  "pixels_compared", "coverage_errors",
            "object"}; // added at the end: older files without it still read
        QCOMPARE(benchCsvColumns(), expected);
        const QString csv = benchRowsToCsv({});
        QCOMPARE(csv, expected.join(',') + '\n');
    }

    void writesNaNEmptyAndInfAsInf()
    {
        const QString csv = benchRowsToCsv({sampleRow()});
        const QStringList lines = csv.split('\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 2);
        const QStringList fields = lines[1].split(',');
        const QStringList header = benchCsvColumns();
        QCOMPARE(fields.size(), header.size());
        QCOMPARE(fields[header.indexOf("gpu_ms")], QString());
        QCOMPARE(fields[header.indexOf("spec_psnr_db")], QStringLiteral("inf"));
        QCOMPARE(fields[header.indexOf("scene_lights")], QStringLiteral("1"));
        QCOMPARE(fields[header.indexOf("detail")], QStringLiteral("0.25"));
        QCOMPARE(fields[header.indexOf("frame_ms")], QStringLiteral("1.9")); // shortest exact form
    }

    void roundTripIsExact()
    {
        std::vector<BenchRow> rows;
        rows.push_back(sampleRow());

        BenchRow awkward = sampleRow();
        awkward.scene = QStringLiteral("teapot, \"glossy\" (v2)");
        awkward.method = QStringLiteral("blinn-phong");
        awkward.detail = 1.0;
        awkward.sceneLights = false;
        awkward.psnr = kInf;
        awkward.gpuMs = 0.123456789012345678;
        awkward.frameMs = 5e-324; // the smallest denormal
        awkward.frameMsP90 = 1.7976931348623157e308;
        awkward.rmse = kNaN;
        awkward.triangles = Q_INT64_C(9007199254740993);
        awkward.coverageErrors = -1;
        rows.push_back(awkward);

        BenchRow spaced = sampleRow();
        spaced.scene = QStringLiteral(" leading and trailing ");
        rows.push_back(spaced);

        // Random doubles: every one must come back bit for bit.
        QRandomGenerator random(12345);
        for (int i = 0; i < 200; ++i) {
            BenchRow row = sampleRow();
            row.frameMs = random.generateDouble() * std::pow(10.0, random.bounded(-6, 6));
            row.rmse = random.generateDouble() * 50;
            row.psnr = 20 + random.generateDouble() * 40;
            row.detail = random.generateDouble();
            rows.push_back(row);
        }

        const QString csv = benchRowsToCsv(rows);
        const Result<std::vector<BenchRow>> read = benchRowsFromCsv(csv);
        QVERIFY2(read, qPrintable(read.error()));
        const std::vector<BenchRow> &back = *read;
        QCOMPARE(back.size(), rows.size());
        for (size_t i = 0; i < rows.size(); ++i)
            compareRows(rows[i], back[i]);
        // And writing again gives the same text.
        QCOMPARE(benchRowsToCsv(back), csv);
    }

    void readsCrlfAndBom()
    {
        QString csv = validCsv(2);
        csv.replace("\n", "\r\n");
        csv.prepend(QChar(0xFEFF));
        const Result<std::vector<BenchRow>> read = benchRowsFromCsv(csv);
        QVERIFY2(read, qPrintable(read.error()));
        const std::vector<BenchRow> &rows = *read;
        QCOMPARE(rows.size(), size_t(2));
        compareRows(sampleRow(), rows[1]);
    }

    void columnsAreFoundByNameAndExtrasIgnored()
    {
        // Reverse the column order and add unknown columns at both ends.
        const QString csv = validCsv(1);
        const QStringList lines = csv.split('\n', Qt::SkipEmptyParts);
        QStringList header = lines[0].split(',');
        QStringList fields = lines[1].split(',');
        std::reverse(header.begin(), header.end());
        std::reverse(fields.begin(), fields.end());
        header.prepend("gpu_name");
        fields.prepend("\"llvmpipe, LLVM 15\"");
        header.append("notes");
        fields.append("anything");
        const QString shuffled = header.join(',') + '\n' + fields.join(',') + '\n';

        const Result<std::vector<BenchRow>> read = benchRowsFromCsv(shuffled);
        QVERIFY2(read, qPrintable(read.error()));
        const std::vector<BenchRow> &rows = *read;
        QCOMPARE(rows.size(), size_t(1));
        compareRows(sampleRow(), rows[0]);
    }

    void headerOnlyIsNoRows()
    {
        const Result<std::vector<BenchRow>> read = benchRowsFromCsv(benchRowsToCsv({}));
        QVERIFY2(read, qPrintable(read.error()));
        const std::vector<BenchRow> &rows = *read;
        QVERIFY(rows.empty());
    }

    void emptyFileIsAnError()
    {
        for (const QString &text : {QString(), QStringLiteral("\n\n"), QStringLiteral("  \r\n")}) {
            const Result<std::vector<BenchRow>> refusal = benchRowsFromCsv(text);
            QVERIFY(!refusal);
            QVERIFY2(refusal.error().startsWith("results.csv"), qPrintable(refusal.error()));
            QVERIFY2(refusal.error().contains("empty"), qPrintable(refusal.error()));
        }
    }

    void missingColumnNamesTheColumn()
    {
        QString csv = validCsv(1);
        csv.replace("frame_ms_p90", "frame_ms_p99");
        const Result<std::vector<BenchRow>> refusal = benchRowsFromCsv(csv);
        QVERIFY(!refusal);
        QCOMPARE(refusal.error(),
                 QStringLiteral("results.csv line 1: missing column frame_ms_p90"));
    }

    void badNumberNamesLineAndColumn()
    {
        // Six good rows, then the seventh line has frame_ms = abc.
        QString csv = validCsv(6);
        const int frameMs = benchCsvColumns().indexOf("frame_ms");
        QStringList fields = csv.split('\n', Qt::SkipEmptyParts).at(1).split(',');
        fields[frameMs] = "abc";
        csv += fields.join(',') + '\n';

        const Result<std::vector<BenchRow>> refusal = benchRowsFromCsv(csv);
        QVERIFY(!refusal);
        QCOMPARE(refusal.error(),
                 QStringLiteral("results.csv line 8: frame_ms is not a number: 'abc'"));

        // The overload names the file it was given.
        const Result<std::vector<BenchRow>> refusal2 =
            benchRowsFromCsv(csv, QStringLiteral("/tmp/out/results.csv"));
        QVERIFY(!refusal2);
        QVERIFY2(refusal2.error().startsWith("/tmp/out/results.csv line 8: frame_ms"),
                 qPrintable(refusal2.error()));
    }

    void otherBadFieldsAreErrors_data()
    {
        QTest::addColumn<QString>("column");
        QTest::addColumn<QString>("value");
        QTest::addColumn<QString>("expected");
        QTest::newRow("triangles not whole") << "triangles"
                                             << "12.5"
                                             << "triangles is not a whole number: '12.5'";
        QTest::newRow("scene_lights") << "scene_lights"
                                      << "yes"
                                      << "scene_lights is not 0 or 1: 'yes'";
        QTest::newRow("max_error empty") << "max_error"
                                         << ""
                                         << "max_error is not a whole number: ''";
        QTest::newRow("rmse trailing junk") << "rmse"
                                            << "1.5x"
                                            << "rmse is not a number: '1.5x'";
        QTest::newRow("psnr infinity spelled wrong") << "psnr_db"
                                                     << "infx"
                                                     << "psnr_db is not a number: 'infx'";
    }

    void otherBadFieldsAreErrors()
    {
        QFETCH(QString, column);
        QFETCH(QString, value);
        QFETCH(QString, expected);
        QString csv = validCsv(1);
        QStringList fields = csv.split('\n', Qt::SkipEmptyParts).at(1).split(',');
        fields[benchCsvColumns().indexOf(column)] = value;
        csv += fields.join(',') + '\n';
        const Result<std::vector<BenchRow>> refusal = benchRowsFromCsv(csv);
        QVERIFY(!refusal);
        QCOMPARE(refusal.error(), QStringLiteral("results.csv line 3: ") + expected);
    }

    void wrongFieldCountNamesTheLine()
    {
        QString csv = validCsv(2);
        csv += "default,phong,1\n";
        const Result<std::vector<BenchRow>> refusal = benchRowsFromCsv(csv);
        QVERIFY(!refusal);
        QVERIFY2(refusal.error().startsWith("results.csv line 4: expected 21 fields"),
                 qPrintable(refusal.error()));
    }

    void unbalancedQuoteIsAnError()
    {
        QString csv = validCsv(1);
        csv += "\"unterminated,phong\n";
        const Result<std::vector<BenchRow>> refusal = benchRowsFromCsv(csv);
        QVERIFY(!refusal);
        QVERIFY2(refusal.error().startsWith("results.csv line 3:"), qPrintable(refusal.error()));
    }

    void blankLinesAreSkippedAndLinesStillCount()
    {
        QString csv = validCsv(1);
        csv += "\n\n";
        QStringList fields = validCsv(1).split('\n', Qt::SkipEmptyParts).at(1).split(',');
        fields[benchCsvColumns().indexOf("lights")] = "two";
        csv += fields.join(',') + '\n';
        const Result<std::vector<BenchRow>> refusal = benchRowsFromCsv(csv);
        QVERIFY(!refusal);
        QCOMPARE(refusal.error(),
                 QStringLiteral("results.csv line 5: lights is not a whole number: 'two'"));
    }
};

QTEST_GUILESS_MAIN(TestBenchCsv)
#include "tst_benchcsv.moc"
