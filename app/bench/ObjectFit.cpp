#include "ObjectFit.h"
#include "core/support/Language.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>
#include <limits>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct ObjectFitWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::ObjectFit)
};

CombinedError combineObjectErrors(const std::vector<BenchRow> &rows, const std::vector<int> &chosen)
{
    CombinedError out;
    double squared = 0.0;
    qint64 pixels = 0;
    for (int i : chosen) {
        const BenchRow &row = rows[std::size_t(i)];
        out.maxError = std::max(out.maxError, row.maxError);
        squared += row.rmse * row.rmse * double(row.pixelsCompared);
        pixels += row.pixelsCompared;
    }
    if (pixels == 0)
        return out;
    const double rmse = std::sqrt(squared / double(pixels));
    out.psnr =
        rmse > 0.0 ? 20.0 * std::log10(255.0 / rmse) : std::numeric_limits<double>::infinity();
    return out;
}

namespace {

// Cheaper first: time, then fewer triangles, then lower error.
bool cheaper(const BenchRow &a, const BenchRow &b)
{
    if (a.frameMs != b.frameMs)
        return a.frameMs < b.frameMs;
    if (a.triangles != b.triangles)
        return a.triangles < b.triangles;
    return a.rmse < b.rmse;
}

// Past this many combinations the PSNR fit goes greedy.
constexpr double kExhaustiveLimit = 200000;

// Under a PSNR budget the objects share one error: the cheapest combination
// whose combined PSNR is within it, over every combination when there are
// few, else greedily from the most accurate rows towards cheaper ones.
std::vector<int> fitShared(const std::vector<BenchRow> &rows,
                           const std::vector<std::vector<int>> &candidates,
                           const ErrorBudget &budget)
{
    double combinations = 1.0;
    for (const auto &c : candidates)
        combinations *= double(c.size());
    const auto within = [&](const std::vector<int> &pick) {
        const CombinedError e = combineObjectErrors(rows, pick);
        return budget.accepts(e.maxError, e.psnr);
    };
    const auto time = [&](const std::vector<int> &pick) {
        double ms = 0.0;
        for (int i : pick)
            ms += rows[std::size_t(i)].frameMs;
        return ms;
    };
    std::vector<int> best;
    if (combinations <= kExhaustiveLimit) {
        std::vector<std::size_t> at(candidates.size(), 0);
        std::vector<int> pick(candidates.size());
        for (;;) {
            for (std::size_t o = 0; o < candidates.size(); ++o)
                pick[o] = candidates[o][at[o]];
            if (within(pick) && (best.empty() || time(pick) < time(best)))
                best = pick;
            std::size_t o = 0;
            while (o < at.size() && ++at[o] == candidates[o].size())
                at[o++] = 0;
            if (o == at.size())
                return best;
        }
    }
    std::vector<int> pick;
    for (const auto &c : candidates)
        pick.push_back(*std::min_element(c.begin(), c.end(), [&](int a, int b) {
            return rows[std::size_t(a)].rmse < rows[std::size_t(b)].rmse;
        }));
    if (!within(pick))
        return {};
    for (bool improved = true; improved;) {
        improved = false;
        std::vector<int> step;
        for (std::size_t o = 0; o < candidates.size(); ++o)
            for (int i : candidates[o]) {
                std::vector<int> next = pick;
                next[o] = i;
                if (time(next) < time(step.empty() ? pick : step) && within(next))
                    step = next;
            }
        if (!step.empty()) {
            pick = step;
            improved = true;
        }
    }
    return pick;
}

QString choiceText(const BenchRow &row)
{
    return QStringLiteral("%1 %2 at %3 (%4 ms, max %5/255)")
        .arg(row.object, row.method, detailPercent(row.detail))
        .arg(sentenceNumber(row.frameMs, 'f', 2))
        .arg(row.maxError);
}

// The single-object rows of each object in fit.choices, by the same index.
struct ObjectRows {
    std::vector<std::vector<int>> all;      // every row with a finite time
    std::vector<std::vector<int>> accepted; // those the budget accepts
};

// Fills fit.choices (in order of first appearance) and fit.baselineMs.
ObjectRows collectObjectRows(const std::vector<BenchRow> &rows, const ErrorBudget &budget,
                             ObjectFit &fit)
{
    ObjectRows grouped;
    for (int i = 0; i < int(rows.size()); ++i) {
        const BenchRow &row = rows[std::size_t(i)];
        if (row.isWholeScene() || !std::isfinite(row.frameMs))
            continue;
        auto it = std::find_if(fit.choices.begin(), fit.choices.end(),
                               [&](const ObjectChoice &c) { return c.object == row.object; });
        if (it == fit.choices.end()) {
            fit.choices.push_back({row.object, -1, -1});
            grouped.all.emplace_back();
            grouped.accepted.emplace_back();
            it = std::prev(fit.choices.end());
        }
        const std::size_t o = std::size_t(it - fit.choices.begin());
        grouped.all[o].push_back(i);
        if (budget.accepts(row))
            grouped.accepted[o].push_back(i);
        if (row.method == QLatin1String("phong") && row.detail >= 1.0)
            fit.baselineMs += row.frameMs;
    }
    return grouped;
}

int cheapestRow(const std::vector<BenchRow> &rows, const std::vector<int> &indices)
{
    return *std::min_element(indices.begin(), indices.end(), [&](int a, int b) {
        return cheaper(rows[std::size_t(a)], rows[std::size_t(b)]);
    });
}

// The image's max error is the largest object's: each object alone. Empty
// when some object has no accepted row.
std::vector<int> fitEachAlone(const std::vector<BenchRow> &rows,
                              const std::vector<std::vector<int>> &accepted)
{
    std::vector<int> pick;
    for (const std::vector<int> &objectRows : accepted) {
        if (objectRows.empty())
            return {};
        pick.push_back(cheapestRow(rows, objectRows));
    }
    return pick;
}

QString nothingFitsSummary(const ObjectFit &fit, const ObjectRows &grouped,
                           const ErrorBudget &budget)
{
    QStringList none;
    for (std::size_t o = 0; o < fit.choices.size(); ++o)
        if (grouped.accepted[o].empty())
            none << fit.choices[o].object;
    return none.isEmpty()
        ? ObjectFitWords::tr("no combination of the objects' rows meets %1").arg(budget.describe())
        : ObjectFitWords::tr("nothing meets %1 for %2")
              .arg(budget.describe(), none.join(QStringLiteral(", ")));
}

// Sets each choice's row, the summed time and the limiting object; returns
// the choices as text, in order.
QStringList applyPick(const std::vector<BenchRow> &rows, const std::vector<int> &pick,
                      ObjectFit &fit)
{
    double worstCost = 0.0;
    QStringList parts;
    for (std::size_t o = 0; o < fit.choices.size(); ++o) {
        ObjectChoice &choice = fit.choices[o];
        choice.row = pick[o];
        const BenchRow &row = rows[std::size_t(choice.row)];
        fit.frameMs += row.frameMs;
        parts << choiceText(row);
        const double cost = row.frameMs - rows[std::size_t(choice.fastest)].frameMs;
        if (cost > worstCost) {
            worstCost = cost;
            fit.limiting = choice.object;
        }
    }
    return parts;
}

QString limitingText(const std::vector<BenchRow> &rows, const ObjectFit &fit)
{
    if (fit.limiting.isEmpty())
        return ObjectFitWords::tr("; every object at its fastest");
    const auto it = std::find_if(fit.choices.begin(), fit.choices.end(),
                                 [&](const ObjectChoice &c) { return c.object == fit.limiting; });
    const BenchRow &fastest = rows[std::size_t(it->fastest)];
    return ObjectFitWords::tr("; %1 limits the saving (its fastest, %2 at %3, errs %4/255)")
        .arg(fit.limiting, fastest.method, detailPercent(fastest.detail))
        .arg(fastest.maxError);
}

} // namespace

ObjectFit fitObjects(const std::vector<BenchRow> &rows, const ErrorBudget &budget)
{
    ObjectFit fit;
    const ObjectRows grouped = collectObjectRows(rows, budget, fit);
    if (fit.choices.empty()) {
        fit.summary = ObjectFitWords::tr("no per-object rows: nothing to fit object by object");
        return fit;
    }
    for (std::size_t o = 0; o < fit.choices.size(); ++o)
        fit.choices[o].fastest = cheapestRow(rows, grouped.all[o]);

    const std::vector<int> pick = budget.kind == ErrorBudget::Kind::MaxError
        ? fitEachAlone(rows, grouped.accepted)
        : fitShared(rows, grouped.all, budget);
    if (pick.empty()) {
        fit.summary = nothingFitsSummary(fit, grouped, budget);
        return fit;
    }
    const QStringList parts = applyPick(rows, pick, fit);
    const CombinedError combined = combineObjectErrors(rows, pick);
    fit.maxError = combined.maxError;
    fit.psnr = combined.psnr;
    fit.fits = budget.accepts(combined.maxError, combined.psnr);
    fit.summary = parts.join(QStringLiteral("; "))
        + QStringLiteral(": %1 ms").arg(sentenceNumber(fit.frameMs, 'f', 2))
        + (fit.baselineMs > 0 ? ObjectFitWords::tr(" against %1 ms at full-detail Phong")
                                    .arg(sentenceNumber(fit.baselineMs, 'f', 2))
                              : QString());
    fit.summary += limitingText(rows, fit);
    return fit;
}

} // namespace phonglab
