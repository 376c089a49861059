// The per-object fit (ObjectFit.h): each object its own method and detail,
// never a combination over budget (checked against every combination on
// many random row sets, under both kinds of budget), the cheapest such
// combination, and the object that limits the saving named.

#include "bench/ObjectFit.h"

#include <QRandomGenerator>
#include <QtTest>
#include <cmath>
#include <limits>

using namespace phonglab;

namespace {

const QStringList kMethods = {"flat", "gouraud", "faceted", "blinn-phong", "phong"};

BenchRow objectRow(const QString &object, const QString &method, double detail, double ms,
                   int maxError, double rmse, qint64 pixels = 1000)
{
    BenchRow r;
    r.scene = QStringLiteral("default");
    r.object = object;
    r.method = method;
    r.detail = detail;
    r.triangles = qint64(detail * 1000);
    r.lights = 2;
    r.sceneLights = true;
    r.frameMs = ms;
    r.maxError = maxError;
    r.rmse = rmse;
    r.pixelsCompared = pixels;
    r.psnr = rmse > 0 ? 20 * std::log10(255 / rmse) : std::numeric_limits<double>::infinity();
    return r;
}

ErrorBudget maxBudget(int steps)
{
    ErrorBudget b;
    b.kind = ErrorBudget::Kind::MaxError;
    b.maxError = steps;
    return b;
}

ErrorBudget psnrBudget(double db)
{
    ErrorBudget b;
    b.kind = ErrorBudget::Kind::Psnr;
    b.minPsnr = db;
    return b;
}

// The cheapest accepted combination by trying every one: -1 ms when none.
double bruteForceMs(const std::vector<BenchRow> &rows, const QStringList &objects,
                    const ErrorBudget &budget)
{
    std::vector<std::vector<int>> per(std::size_t(objects.size()));
    for (int i = 0; i < int(rows.size()); ++i)
        per[std::size_t(objects.indexOf(rows[std::size_t(i)].object))].push_back(i);
    double best = -1.0;
    std::vector<std::size_t> at(per.size(), 0);
    for (;;) {
        std::vector<int> pick;
        double ms = 0;
        for (std::size_t o = 0; o < per.size(); ++o) {
            pick.push_back(per[o][at[o]]);
            ms += rows[std::size_t(pick.back())].frameMs;
        }
        const CombinedError e = combineObjectErrors(rows, pick);
        if (budget.accepts(e.maxError, e.psnr) && (best < 0 || ms < best))
            best = ms;
        std::size_t o = 0;
        while (o < at.size() && ++at[o] == per[o].size())
            at[o++] = 0;
        if (o == at.size())
            return best;
    }
}

} // namespace

class TestObjectFit : public QObject
{
    Q_OBJECT

private slots:
    void eachObjectItsOwnChoice()
    {
        const std::vector<BenchRow> rows = {
            objectRow("tree", "phong", 1.0, 2.0, 1, 0.3),
            objectRow("tree", "gouraud", 1.0, 1.0, 9, 2.0), // over budget
            objectRow("cloud", "phong", 1.0, 1.5, 1, 0.3),
            objectRow("cloud", "gouraud", 0.25, 0.4, 2, 0.6), // within: the cloud's choice
        };
        const ObjectFit fit = fitObjects(rows, maxBudget(2));
        QVERIFY(fit.fits);
        QCOMPARE(fit.choices.size(), std::size_t(2));
        QCOMPARE(fit.choices[0].row, 0);
        QCOMPARE(fit.choices[1].row, 3);
        QCOMPARE(fit.frameMs, 2.4);
        QCOMPARE(fit.baselineMs, 3.5);
        QCOMPARE(fit.maxError, 2);
        QCOMPARE(fit.limiting, QStringLiteral("tree"));
        QVERIFY2(fit.summary.contains(QStringLiteral("tree limits the saving")),
                 qPrintable(fit.summary));
    }

    void wholeSceneRowsAreIgnoredAndNothingFitsIsSaid()
    {
        BenchRow whole = objectRow("", "flat", 1.0, 0.1, 0, 0.0);
        const std::vector<BenchRow> rows = {whole, objectRow("tree", "phong", 1.0, 2.0, 5, 1.0)};
        const ObjectFit fit = fitObjects(rows, maxBudget(2));
        QVERIFY(!fit.fits);
        QCOMPARE(fit.choices.size(), std::size_t(1));
        QCOMPARE(fit.choices[0].row, -1);
        QVERIFY2(fit.summary.contains(QStringLiteral("nothing meets")), qPrintable(fit.summary));
        QVERIFY(!fitObjects({whole}, maxBudget(2)).fits);
    }

    void psnrIsSharedOverThePixels()
    {
        // Each alone meets 40 dB only at phong; together a cheap tree on few
        // pixels and an exact cloud on many still meet it.
        const std::vector<BenchRow> rows = {
            objectRow("tree", "phong", 1.0, 2.0, 1, 0.2, 100),
            objectRow("tree", "gouraud", 1.0, 0.5, 12, 3.0, 100), // 38.6 dB alone
            objectRow("cloud", "phong", 1.0, 1.0, 1, 0.0, 10000),
        };
        const ObjectFit fit = fitObjects(rows, psnrBudget(40.0));
        QVERIFY(fit.fits);
        QCOMPARE(fit.choices[0].row, 1);
        QVERIFY(fit.psnr >= 40.0);
    }

    void neverOverBudgetAndCheapestOnRandomRowSets()
    {
        QRandomGenerator random(20261125);
        int fitted = 0, unfitted = 0;
        for (int trial = 0; trial < 3000; ++trial) {
            QStringList objects;
            for (int o = 0, n = random.bounded(1, 4); o < n; ++o)
                objects << QStringLiteral("object %1").arg(o);
            std::vector<BenchRow> rows;
            for (const QString &object : objects)
                for (int r = 0, n = random.bounded(1, 7); r < n; ++r) {
                    const int maxError = random.bounded(0, 12);
                    const double rmse = maxError == 0 ? 0.0 : random.generateDouble() * maxError;
                    rows.push_back(objectRow(object, kMethods[random.bounded(kMethods.size())],
                                             random.bounded(2) ? 1.0 : 0.25,
                                             0.2 + random.generateDouble() * 4, maxError, rmse,
                                             random.bounded(1, 5000)));
                }
            const ErrorBudget budget = random.bounded(2)
                ? maxBudget(random.bounded(0, 8))
                : psnrBudget(30 + random.generateDouble() * 25);
            const ObjectFit fit = fitObjects(rows, budget);
            const double best = bruteForceMs(rows, objects, budget);
            if (!fit.fits) {
                QCOMPARE(best, -1.0);
                ++unfitted;
                continue;
            }
            ++fitted;
            std::vector<int> pick;
            for (const ObjectChoice &c : fit.choices)
                pick.push_back(c.row);
            const CombinedError e = combineObjectErrors(rows, pick);
            QVERIFY2(budget.accepts(e.maxError, e.psnr),
                     qPrintable(
                         QStringLiteral("trial %1: over budget: %2").arg(trial).arg(fit.summary)));
            QCOMPARE(e.maxError, fit.maxError);
            QVERIFY2(std::abs(fit.frameMs - best) < 1e-9,
                     qPrintable(QStringLiteral("trial %1: %2 ms, the cheapest is %3 ms")
                                    .arg(trial)
                                    .arg(fit.frameMs)
                                    .arg(best)));
        }
        QVERIFY(fitted > 500 && unfitted > 100);
    }
};

QTEST_APPLESS_MAIN(TestObjectFit)
#include "tst_objectfit.moc"
