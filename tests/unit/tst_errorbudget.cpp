// Error budgets: the accepted spellings, what a budget accepts, and
// fitToBudget() — never a row over budget (checked over many random row
// sets), ties broken towards fewer triangles, lower error and cheaper methods, savings
// against the full-detail Phong row, and a clear "nothing fits".

#include "bench/ErrorBudget.h"

#include <QtTest>
#include <cmath>
#include <limits>

using namespace phonglab;

namespace {

BenchRow row(const QString &method, double detail, qint64 triangles, double ms, int maxError,
             double psnr = 40)
{
    BenchRow r;
    r.scene = QStringLiteral("default");
    r.method = method;
    r.detail = detail;
    r.triangles = triangles;
    r.lights = 2;
    r.sceneLights = true;
    r.frameMs = ms;
    r.maxError = maxError;
    r.psnr = psnr;
    r.rmse = maxError / 3.0;
    return r;
}

ErrorBudget maxBudget(int maxError)
{
    ErrorBudget b;
    b.kind = ErrorBudget::Kind::MaxError;
    b.maxError = maxError;
    return b;
}

ErrorBudget psnrBudget(double minPsnr)
{
    ErrorBudget b;
    b.kind = ErrorBudget::Kind::Psnr;
    b.minPsnr = minPsnr;
    return b;
}

const QStringList kMethods = {"flat", "gouraud", "blinn-phong", "phong"};

} // namespace

class TestErrorBudget : public QObject
{
    Q_OBJECT

private slots:
    void parseForms_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<bool>("valid");
        QTest::addColumn<bool>("isPsnr");
        QTest::addColumn<double>("value");
        QTest::newRow("bare") << "2" << true << false << 2.0;
        QTest::newRow("zero") << "0" << true << false << 0.0;
        QTest::newRow("max:") << "max:2" << true << false << 2.0;
        QTest::newRow("MAX: spaced") << " MAX: 7 " << true << false << 7.0;
        QTest::newRow("of 255") << "3/255" << true << false << 3.0;
        QTest::newRow("255") << "255" << true << false << 255.0;
        QTest::newRow("psnr:") << "psnr:40" << true << true << 40.0;
        QTest::newRow("psnr: fraction") << "PSNR:38.5" << true << true << 38.5;
        QTest::newRow("dB") << "40dB" << true << true << 40.0;
        QTest::newRow("db spaced") << "42.5 db" << true << true << 42.5;
        QTest::newRow("256") << "256" << false << false << 0.0;
        QTest::newRow("negative") << "-1" << false << false << 0.0;
        QTest::newRow("fractional max") << "2.5" << false << false << 0.0;
        QTest::newRow("empty") << "" << false << false << 0.0;
        QTest::newRow("words") << "tight" << false << false << 0.0;
        QTest::newRow("psnr empty") << "psnr:" << false << false << 0.0;
        QTest::newRow("psnr zero") << "psnr:0" << false << false << 0.0;
        QTest::newRow("psnr negative") << "psnr:-3" << false << false << 0.0;
        QTest::newRow("max words") << "max:two" << false << false << 0.0;
        QTest::newRow("dB alone") << "dB" << false << false << 0.0;
    }

    void parseForms()
    {
        QFETCH(QString, text);
        QFETCH(bool, valid);
        QFETCH(bool, isPsnr);
        QFETCH(double, value);
        const std::optional<ErrorBudget> budget = ErrorBudget::parse(text);
        QCOMPARE(budget.has_value(), valid);
        if (!valid)
            return;
        QCOMPARE(budget->kind == ErrorBudget::Kind::Psnr, isPsnr);
        if (isPsnr)
            QCOMPARE(budget->minPsnr, value);
        else
            QCOMPARE(double(budget->maxError), value);
    }

    void describe()
    {
        QCOMPARE(maxBudget(2).describe(), QStringLiteral("max error ≤ 2/255"));
        QCOMPARE(psnrBudget(40).describe(), QStringLiteral("PSNR ≥ 40 dB"));
        QCOMPARE(psnrBudget(38.5).describe(), QStringLiteral("PSNR ≥ 38.5 dB"));
        // describe() and parse() agree.
        QCOMPARE(ErrorBudget::parse("max:5")->describe(), maxBudget(5).describe());
    }

    void accepts()
    {
        QVERIFY(maxBudget(2).accepts(row("phong", 1, 100, 1, 2)));
        QVERIFY(!maxBudget(2).accepts(row("phong", 1, 100, 1, 3)));
        QVERIFY(maxBudget(0).accepts(row("phong", 1, 100, 1, 0)));
        QVERIFY(psnrBudget(40).accepts(row("phong", 1, 100, 1, 9, 40.0)));
        QVERIFY(!psnrBudget(40).accepts(row("phong", 1, 100, 1, 0, 39.99)));
        QVERIFY(psnrBudget(40).accepts(
            row("phong", 1, 100, 1, 0, std::numeric_limits<double>::infinity())));
        QVERIFY(!psnrBudget(40).accepts(
            row("phong", 1, 100, 1, 0, std::numeric_limits<double>::quiet_NaN())));
    }

    void picksTheFastestAndReportsSavings()
    {
        const std::vector<BenchRow> rows = {
            row("phong", 1.0, 13650, 3.1, 0),   row("phong", 0.25, 3412, 2.2, 4),   // too coarse
            row("gouraud", 1.0, 13650, 2.6, 1), row("gouraud", 0.25, 3412, 1.9, 2), // the answer
            row("flat", 0.25, 3412, 1.5, 9), // fastest, over budget
        };
        const BudgetFit fit = fitToBudget(rows, maxBudget(2));
        QCOMPARE(fit.chosen, 3);
        QCOMPARE(fit.baseline, 0);
        QCOMPARE(fit.trianglesSaved, qint64(13650 - 3412));
        QVERIFY(std::abs(fit.msSaved - 1.2) < 1e-9);
        QCOMPARE(fit.summary,
                 QStringLiteral(
                     "gouraud at detail 25 % (3 412 triangles, 1.9 ms): saves 10 238 triangles "
                     "and 1.2 ms (39 %) against full-detail Phong (13 650 triangles, 3.1 ms); "
                     "max error 2/255"));
    }

    void prefersFewerTrianglesOnATimeTie()
    {
        // 2.00 and 2.05 ms are within 5 %: the coarser mesh wins although slower.
        const std::vector<BenchRow> rows = {
            row("phong", 1.0, 10000, 4.0, 0), row("phong", 0.5, 5000, 2.00, 1),
            row("phong", 0.25, 2500, 2.05, 2),
            row("phong", 0.1, 1000, 2.5, 2), // fewer still, but clearly slower
        };
        const BudgetFit fit = fitToBudget(rows, maxBudget(2));
        QCOMPARE(fit.chosen, 2);
    }

    void prefersLowerErrorThenCheaperMethodOnATie()
    {
        // Same time (within 5 %) and triangles: the more accurate wins, since
        // it costs nothing more; at equal error the cheaper method.
        std::vector<BenchRow> rows = {
            row("phong", 1.0, 10000, 3.0, 0),       row("phong", 0.5, 5000, 2.0, 0),
            row("blinn-phong", 0.5, 5000, 2.01, 0), row("gouraud", 0.5, 5000, 2.02, 1),
            row("toon", 0.5, 5000, 1.99, 0), // unknown methods come after phong
        };
        BudgetFit fit = fitToBudget(rows, maxBudget(2));
        QCOMPARE(rows[fit.chosen].method, QStringLiteral("blinn-phong"));
        rows[3].maxError = 0;
        rows[3].rmse = 0.0; // now as accurate as the others, and cheapest
        fit = fitToBudget(rows, maxBudget(2));
        QCOMPARE(rows[fit.chosen].method, QStringLiteral("gouraud"));
    }

    void baselineChosenSaysSo()
    {
        const std::vector<BenchRow> rows = {
            row("gouraud", 1.0, 10000, 2.0, 5),
            row("phong", 1.0, 10000, 3.0, 0),
        };
        const BudgetFit fit = fitToBudget(rows, maxBudget(1));
        QCOMPARE(fit.chosen, 1);
        QCOMPARE(fit.baseline, 1);
        QCOMPARE(fit.trianglesSaved, qint64(0));
        QCOMPARE(fit.msSaved, 0.0);
        QVERIFY2(fit.summary.contains("full-detail Phong"), qPrintable(fit.summary));
    }

    void withoutBaselineStillChooses()
    {
        const std::vector<BenchRow> rows = {
            row("gouraud", 1.0, 10000, 2.0, 1),
            row("phong", 0.5, 5000, 1.0, 1),
        };
        const BudgetFit fit = fitToBudget(rows, maxBudget(2));
        QCOMPARE(fit.chosen, 1);
        QCOMPARE(fit.baseline, -1);
        QCOMPARE(fit.trianglesSaved, qint64(0));
        QCOMPARE(fit.msSaved, 0.0);
        QVERIFY2(fit.summary.contains("no full-detail Phong"), qPrintable(fit.summary));
    }

    void nothingFitsSaysSoAndTheBest()
    {
        const std::vector<BenchRow> rows = {
            row("phong", 1.0, 10000, 3.0, 4, 35.5),
            row("gouraud", 0.5, 5000, 1.0, 9, 30.0),
        };
        BudgetFit fit = fitToBudget(rows, maxBudget(2));
        QCOMPARE(fit.chosen, -1);
        QCOMPARE(fit.baseline, 0);
        QCOMPARE(fit.trianglesSaved, qint64(0));
        QVERIFY2(fit.summary.startsWith("nothing meets max error ≤ 2/255"),
                 qPrintable(fit.summary));
        QVERIFY2(fit.summary.contains("max error 4/255"), qPrintable(fit.summary));

        fit = fitToBudget(rows, psnrBudget(40));
        QCOMPARE(fit.chosen, -1);
        QVERIFY2(fit.summary.contains("PSNR ≥ 40 dB"), qPrintable(fit.summary));
        QVERIFY2(fit.summary.contains("PSNR 35.5 dB"), qPrintable(fit.summary));

        fit = fitToBudget({}, maxBudget(2));
        QCOMPARE(fit.chosen, -1);
        QCOMPARE(fit.baseline, -1);
        QVERIFY(fit.summary.startsWith("nothing meets"));
    }

    void psnrKind()
    {
        const std::vector<BenchRow> rows = {
            row("phong", 1.0, 10000, 3.0, 0, std::numeric_limits<double>::infinity()),
            row("gouraud", 1.0, 10000, 2.0, 12, 38.0),
            row("phong", 0.5, 5000, 2.0, 6, 45.0),
            row("flat", 0.5, 5000, 1.0, 40, 25.0),
        };
        BudgetFit fit = fitToBudget(rows, ::psnrBudget(40));
        QCOMPARE(fit.chosen, 2);
        QCOMPARE(fit.trianglesSaved, qint64(5000));
        QVERIFY2(fit.summary.endsWith("PSNR 45.0 dB"), qPrintable(fit.summary));
        fit = fitToBudget(rows, ::psnrBudget(35));
        QCOMPARE(fit.chosen, 2); // ties with gouraud on time; fewer triangles
        fit = fitToBudget(rows, ::psnrBudget(50));
        QCOMPARE(fit.chosen, 0);
    }

    // Over many random row sets: the chosen row is accepted, no accepted row
    // is more than kTimeTieFraction faster, and the choice is -1 exactly
    // when nothing is accepted.
    void neverPicksARowOverBudget()
    {
        QRandomGenerator random(20240611);
        for (int trial = 0; trial < 3000; ++trial) {
            const int n = random.bounded(0, 14);
            std::vector<BenchRow> rows;
            for (int i = 0; i < n; ++i) {
                const double detail =
                    random.bounded(2) ? 1.0 : 0.05 + random.generateDouble() * 0.9;
                BenchRow r = row(kMethods[random.bounded(kMethods.size())], detail,
                                 qint64(detail * 10000), 0.5 + random.generateDouble() * 4,
                                 random.bounded(0, 12), 20 + random.generateDouble() * 40);
                if (random.bounded(20) == 0)
                    r.frameMs = rows.empty() ? r.frameMs : rows.back().frameMs; // exact time ties
                if (random.bounded(25) == 0)
                    r.psnr = std::numeric_limits<double>::quiet_NaN();
                rows.push_back(r);
            }
            const ErrorBudget budget = random.bounded(2) ? maxBudget(random.bounded(0, 10))
                                                         : ::psnrBudget(25 + random.bounded(30));
            const BudgetFit fit = fitToBudget(rows, budget);
            bool anyAccepted = false;
            double fastestAccepted = std::numeric_limits<double>::infinity();
            for (const BenchRow &r : rows)
                if (budget.accepts(r)) {
                    anyAccepted = true;
                    fastestAccepted = std::min(fastestAccepted, r.frameMs);
                }
            QCOMPARE(fit.chosen >= 0, anyAccepted);
            if (fit.chosen < 0) {
                QVERIFY(fit.summary.startsWith("nothing meets"));
                continue;
            }
            QVERIFY(fit.chosen < n);
            const BenchRow &chosen = rows[fit.chosen];
            QVERIFY2(budget.accepts(chosen), qPrintable(QString("trial %1").arg(trial)));
            QVERIFY(chosen.frameMs <= fastestAccepted * (1 + kTimeTieFraction) + 1e-12);
            // Nothing accepted in the tie band has fewer triangles.
            for (const BenchRow &r : rows)
                if (budget.accepts(r) && r.frameMs <= fastestAccepted * (1 + kTimeTieFraction))
                    QVERIFY(r.triangles >= chosen.triangles);
            if (fit.baseline >= 0) {
                QVERIFY(rows[fit.baseline].isBaseline());
                QCOMPARE(fit.trianglesSaved, rows[fit.baseline].triangles - chosen.triangles);
                QCOMPARE(fit.msSaved, rows[fit.baseline].frameMs - chosen.frameMs);
            }
        }
    }
};

QTEST_GUILESS_MAIN(TestErrorBudget)
#include "tst_errorbudget.moc"
