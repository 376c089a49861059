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

} // namespace

ObjectFit fitObjects(const std::vector<BenchRow> &rows, const ErrorBudget &budget)
{
    ObjectFit fit;
    std::vector<std::vector<int>> all, accepted;
    for (int i = 0; i < int(rows.size()); ++i) {
        const BenchRow &row = rows[std::size_t(i)];
        if (row.isWholeScene() || !std::isfinite(row.frameMs))
            continue;
        auto it = std::find_if(fit.choices.begin(), fit.choices.end(),
                               [&](const ObjectChoice &c) { return c.object == row.object; });
        if (it == fit.choices.end()) {
            fit.choices.push_back({row.object, -1, -1});
            all.emplace_back();
            accepted.emplace_back();
            it = std::prev(fit.choices.end());
        }
        const std::size_t o = std::size_t(it - fit.choices.begin());
        all[o].push_back(i);
        if (budget.accepts(row))
            accepted[o].push_back(i);
        if (row.method == QLatin1String("phong") && row.detail >= 1.0)
            fit.baselineMs += row.frameMs;
    }
    if (fit.choices.empty()) {
        fit.summary = ObjectFitWords::tr("no per-object rows: nothing to fit object by object");
        return fit;
    }
    for (std::size_t o = 0; o < fit.choices.size(); ++o)
        fit.choices[o].fastest = *std::min_element(all[o].begin(), all[o].end(), [&](int a, int b) {
            return cheaper(rows[std::size_t(a)], rows[std::size_t(b)]);
        });

    std::vector<int> pick;
    if (budget.kind == ErrorBudget::Kind::MaxError) {
        // The image's max error is the largest object's: each object alone.
        for (std::size_t o = 0; o < fit.choices.size(); ++o) {
            if (accepted[o].empty()) {
                pick.clear();
                break;
            }
            pick.push_back(
                *std::min_element(accepted[o].begin(), accepted[o].end(), [&](int a, int b) {
                    return cheaper(rows[std::size_t(a)], rows[std::size_t(b)]);
                }));
        }
    } else {
        pick = fitShared(rows, all, budget);
    }
    if (pick.empty()) {
        QStringList none;
        for (std::size_t o = 0; o < fit.choices.size(); ++o)
            if (accepted[o].empty())
                none << fit.choices[o].object;
        fit.summary = none.isEmpty()
            ? ObjectFitWords::tr("no combination of the objects' rows meets %1")
                  .arg(budget.describe())
            : ObjectFitWords::tr("nothing meets %1 for %2")
                  .arg(budget.describe(), none.join(QStringLiteral(", ")));
        return fit;
    }
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
    const CombinedError combined = combineObjectErrors(rows, pick);
    fit.maxError = combined.maxError;
    fit.psnr = combined.psnr;
    fit.fits = budget.accepts(combined.maxError, combined.psnr);
    fit.summary = parts.join(QStringLiteral("; "))
        + QStringLiteral(": %1 ms").arg(sentenceNumber(fit.frameMs, 'f', 2))
        + (fit.baselineMs > 0 ? ObjectFitWords::tr(" against %1 ms at full-detail Phong")
                                    .arg(sentenceNumber(fit.baselineMs, 'f', 2))
                              : QString());
    if (!fit.limiting.isEmpty()) {
        const auto it =
            std::find_if(fit.choices.begin(), fit.choices.end(),
                         [&](const ObjectChoice &c) { return c.object == fit.limiting; });
        const BenchRow &fastest = rows[std::size_t(it->fastest)];
        fit.summary +=
            ObjectFitWords::tr("; %1 limits the saving (its fastest, %2 at %3, errs %4/255)")
                .arg(fit.limiting, fastest.method, detailPercent(fastest.detail))
                .arg(fastest.maxError);
    } else {
        fit.summary += ObjectFitWords::tr("; every object at its fastest");
    }
    return fit;
}

} // namespace phonglab
