// The Pareto front of frame time against RMSE: known sets, ties on either
// axis, exact duplicates (which must not knock each other out), unmeasured
// rows, and a brute-force check over random sets.

#include "bench/ParetoFront.h"

#include <QtTest>
#include <cmath>
#include <limits>

using namespace phonglab;

namespace {

BenchRow point(double ms, double rmse)
{
    BenchRow r;
    r.method = QStringLiteral("phong");
    r.frameMs = ms;
    r.rmse = rmse;
    return r;
}

std::vector<BenchRow> points(std::initializer_list<std::pair<double, double>> list)
{
    std::vector<BenchRow> rows;
    for (const auto &[ms, rmse] : list)
        rows.push_back(point(ms, rmse));
    return rows;
}

// The definition, checked pair by pair.
std::vector<int> bruteForce(const std::vector<BenchRow> &rows)
{
    std::vector<int> front;
    for (int i = 0; i < int(rows.size()); ++i) {
        const BenchRow &a = rows[i];
        if (std::isnan(a.frameMs) || std::isnan(a.rmse))
            continue;
        bool dominated = false;
        for (int j = 0; j < int(rows.size()) && !dominated; ++j) {
            const BenchRow &b = rows[j];
            if (j == i || std::isnan(b.frameMs) || std::isnan(b.rmse))
                continue;
            dominated = b.frameMs <= a.frameMs && b.rmse <= a.rmse
                && (b.frameMs < a.frameMs || b.rmse < a.rmse);
        }
        if (!dominated)
            front.push_back(i);
    }
    std::sort(front.begin(), front.end(), [&](int a, int b) {
        if (rows[a].frameMs != rows[b].frameMs)
            return rows[a].frameMs < rows[b].frameMs;
        if (rows[a].rmse != rows[b].rmse)
            return rows[a].rmse < rows[b].rmse;
        return a < b;
    });
    return front;
}

using Indices = std::vector<int>;

} // namespace

class TestParetoFront : public QObject
{
    Q_OBJECT

private slots:
    void empty() { QVERIFY(paretoFront({}).empty()); }

    void single() { QCOMPARE(paretoFront(points({{2, 1}})), Indices{0}); }

    void knownSet()
    {
        // 0: slow and exact, 1: dominated by 2, 2: middle, 3: fast and rough,
        // 4: dominated by 3 (slower, rougher).
        const auto rows = points({{5.0, 0.0}, {3.5, 2.0}, {3.0, 1.0}, {1.0, 4.0}, {1.5, 6.0}});
        QCOMPARE(paretoFront(rows), (Indices{3, 2, 0}));
    }

    void sortedByTime()
    {
        const auto rows = points({{9, 0}, {1, 9}, {5, 3}, {3, 5}, {7, 1}});
        QCOMPARE(paretoFront(rows), (Indices{1, 3, 2, 4, 0}));
    }

    void equalTimeKeepsOnlyTheMoreAccurate()
    {
        const auto rows = points({{2, 3}, {2, 1}, {4, 0}});
        QCOMPARE(paretoFront(rows), (Indices{1, 2}));
    }

    void equalErrorKeepsOnlyTheFaster()
    {
        const auto rows = points({{3, 1}, {2, 1}, {1, 5}});
        QCOMPARE(paretoFront(rows), (Indices{2, 1}));
    }

    void duplicatesStayTogether()
    {
        // Two identical measurements on the front both stay; identical
        // dominated ones both go.
        const auto rows = points({{2, 1}, {1, 4}, {2, 1}, {3, 3}, {3, 3}, {1, 4}});
        QCOMPARE(paretoFront(rows), (Indices{1, 5, 0, 2}));
    }

    void allIdentical()
    {
        const auto rows = points({{2, 2}, {2, 2}, {2, 2}});
        QCOMPARE(paretoFront(rows), (Indices{0, 1, 2}));
    }

    void unmeasuredRowsAreLeftOut()
    {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const auto rows = points({{nan, 0}, {2, nan}, {3, 1}, {1, 2}});
        QCOMPARE(paretoFront(rows), (Indices{3, 2}));
    }

    void zeroErrorAndInfinity()
    {
        const double inf = std::numeric_limits<double>::infinity();
        const auto rows = points({{4, 0}, {4, 0}, {1, inf}, {2, inf}});
        QCOMPARE(paretoFront(rows), (Indices{2, 0, 1}));
    }

    void matchesTheDefinitionOnRandomSets()
    {
        QRandomGenerator random(7);
        for (int trial = 0; trial < 2000; ++trial) {
            std::vector<BenchRow> rows;
            const int n = random.bounded(0, 25);
            for (int i = 0; i < n; ++i)
                // Small integer grids make ties and duplicates common.
                rows.push_back(point(random.bounded(1, 8) * 0.5, random.bounded(0, 6) * 0.25));
            QCOMPARE(paretoFront(rows), bruteForce(rows));
        }
    }
};

QTEST_GUILESS_MAIN(TestParetoFront)
#include "tst_paretofront.moc"
