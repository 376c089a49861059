#include "ErrorBudget.h"

#include "core/support/Language.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <cmath>
#include <iterator>
#include <limits>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct ErrorBudgetWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::ErrorBudget)
};

namespace {

// "13 650": digits grouped by threes with a space, whatever the locale.
QString groupedNumber(qint64 value)
{
    const bool negative = value < 0;
    QString digits = QString::number(negative ? -value : value);
    for (qsizetype i = digits.size() - 3; i > 0; i -= 3)
        digits.insert(i, QLatin1Char(' '));
    return negative ? QLatin1Char('-') + digits : digits;
}

QString formatMs(double ms)
{
    const double a = std::abs(ms);
    if (a >= 100)
        return sentenceLocale().toString(ms, 'f', 0);
    if (a >= 1)
        return sentenceLocale().toString(ms, 'f', 1);
    return sentenceLocale().toString(ms, 'f', 2);
}

QString formatDb(double db)
{
    if (std::isinf(db))
        return db > 0 ? QStringLiteral("∞") : QStringLiteral("-∞");
    return sentenceLocale().toString(db, 'f', 1);
}

// flat < gouraud < faceted < blinn-phong < phong < anything else: per face,
// per vertex, then per fragment.
int methodCost(const QString &method)
{
    static const char *const order[] = {"flat", "gouraud", "faceted", "blinn-phong", "phong"};
    const int known = int(std::size(order));
    for (int i = 0; i < known; ++i)
        if (method == QLatin1String(order[i]))
            return i;
    return known;
}

QString methodTitle(const QString &method)
{
    if (method == QLatin1String("phong"))
        return QStringLiteral("Phong");
    if (method == QLatin1String("blinn-phong"))
        return QStringLiteral("Blinn-Phong");
    return method;
}

// "gouraud at detail 25 %" / "gouraud at full detail"
QString rowLabel(const BenchRow &row)
{
    if (row.detail >= 1.0)
        return ErrorBudgetWords::tr("%1 at full detail").arg(row.method);
    return ErrorBudgetWords::tr("%1 at detail %2").arg(row.method, detailPercent(row.detail));
}

// "3 412 triangles, 1.9 ms"
QString rowCost(const BenchRow &row)
{
    return ErrorBudgetWords::tr("%1 triangles, %2 ms")
        .arg(groupedNumber(row.triangles), formatMs(row.frameMs));
}

// The row's error in the budget's own terms: "max error 2/255" / "PSNR 41.3 dB".
QString rowError(const BenchRow &row, ErrorBudget::Kind kind)
{
    if (kind == ErrorBudget::Kind::MaxError)
        return ErrorBudgetWords::tr("max error %1/255").arg(row.maxError);
    return QStringLiteral("PSNR %1 dB").arg(formatDb(row.psnr));
}

} // namespace

double ErrorBudget::reductionAllowance() const
{
    if (kind == Kind::MaxError)
        return 0.25 * maxError / 255.0;
    // PSNR ≥ P dB allows an RMSE of 255·10^(-P/20) steps; a change below a
    // quarter of it at every pixel keeps the rest for the method.
    return 0.25 * std::pow(10.0, -minPsnr / 20.0);
}

bool ErrorBudget::accepts(const BenchRow &row) const
{
    return accepts(row.maxError, row.psnr);
}

bool ErrorBudget::accepts(int measuredMax, double psnr) const
{
    switch (kind) {
    case Kind::MaxError: return measuredMax >= 0 && measuredMax <= maxError;
    case Kind::Psnr: return !std::isnan(psnr) && psnr >= minPsnr; // NaN: not measured, refused
    }
    return false;
}

QString ErrorBudget::describe() const
{
    if (kind == Kind::MaxError)
        return ErrorBudgetWords::tr("max error ≤ %1/255").arg(maxError);
    return QStringLiteral("PSNR ≥ %1 dB").arg(sentenceLocale().toString(minPsnr, 'g', 6));
}

std::optional<ErrorBudget> ErrorBudget::parse(const QString &text)
{
    const QString t = text.trimmed().toLower();

    // "2", "max:2", "max: 2", "2/255", "max:2/255"
    static const QRegularExpression maxForm(
        QStringLiteral("^(?:max\\s*:\\s*)?(\\d{1,3})(?:\\s*/\\s*255)?$"));
    QRegularExpressionMatch m = maxForm.match(t);
    if (m.hasMatch()) {
        const int value = m.captured(1).toInt();
        if (value > 255)
            return std::nullopt;
        ErrorBudget budget;
        budget.kind = Kind::MaxError;
        budget.maxError = value;
        return budget;
    }

    // "psnr:40", "psnr: 38.5", "40dB", "40 dB", "psnr:40dB"
    static const QRegularExpression psnrForm(
        QStringLiteral("^(?:psnr\\s*:\\s*(\\d+(?:\\.\\d*)?|\\.\\d+)(?:\\s*db)?"
                       "|(\\d+(?:\\.\\d*)?|\\.\\d+)\\s*db)$"));
    m = psnrForm.match(t);
    if (m.hasMatch()) {
        const QString number = m.captured(1).isEmpty() ? m.captured(2) : m.captured(1);
        bool ok = false;
        const double value = number.toDouble(&ok);
        if (!ok || !std::isfinite(value) || value <= 0)
            return std::nullopt;
        ErrorBudget budget;
        budget.kind = Kind::Psnr;
        budget.minPsnr = value;
        return budget;
    }
    return std::nullopt;
}

namespace {

int baselineIndex(const std::vector<BenchRow> &rows)
{
    const int n = int(rows.size());
    for (int i = 0; i < n; ++i)
        if (rows[i].isBaseline())
            return i;
    return -1;
}

// One object's rows (the per-object fit's) are no choice for the scene.
bool isCandidate(const BenchRow &row, const ErrorBudget &budget)
{
    return row.isWholeScene() && budget.accepts(row) && std::isfinite(row.frameMs);
}

// Between two rows equally fast: the fewer triangles, then the lower error,
// then the cheaper method.
bool isBetterChoice(const BenchRow &row, const BenchRow &best)
{
    if (row.triangles != best.triangles)
        return row.triangles < best.triangles;
    if (row.rmse != best.rmse && !std::isnan(row.rmse) && !std::isnan(best.rmse))
        return row.rmse < best.rmse; // as cheap either way: the accuracy is free
    if (methodCost(row.method) != methodCost(best.method))
        return methodCost(row.method) < methodCost(best.method);
    if (row.method != best.method)
        return row.method < best.method;
    return row.frameMs < best.frameMs;
}

// The index of the chosen row, -1 when no row meets the budget.
int chooseCheapest(const std::vector<BenchRow> &rows, const ErrorBudget &budget)
{
    const int n = int(rows.size());
    // The fastest accepted time; every accepted row within kTimeTieFraction
    // of it counts as equally fast.
    double fastest = std::numeric_limits<double>::infinity();
    for (int i = 0; i < n; ++i)
        if (isCandidate(rows[i], budget))
            fastest = std::min(fastest, rows[i].frameMs);
    if (!std::isfinite(fastest))
        return -1;

    int chosen = -1;
    const double tieLimit = fastest + std::abs(fastest) * kTimeTieFraction;
    for (int i = 0; i < n; ++i) {
        const BenchRow &row = rows[i];
        if (!isCandidate(row, budget) || row.frameMs > tieLimit)
            continue;
        if (chosen < 0 || isBetterChoice(row, rows[chosen]))
            chosen = i;
    }
    return chosen;
}

// The row that came closest to the budget, -1 when no row was measured.
int closestToBudget(const std::vector<BenchRow> &rows, ErrorBudget::Kind kind)
{
    int bestIndex = -1;
    const int n = int(rows.size());
    for (int i = 0; i < n; ++i) {
        const BenchRow &row = rows[i];
        if (kind == ErrorBudget::Kind::MaxError) {
            if (row.maxError < 0)
                continue;
            if (bestIndex < 0 || row.maxError < rows[bestIndex].maxError)
                bestIndex = i;
        } else {
            if (std::isnan(row.psnr))
                continue;
            if (bestIndex < 0 || row.psnr > rows[bestIndex].psnr)
                bestIndex = i;
        }
    }
    return bestIndex;
}

// Nothing fits: say so, and how close the best measurement came.
QString nothingFitsSummary(const std::vector<BenchRow> &rows, const ErrorBudget &budget)
{
    const int bestIndex = closestToBudget(rows, budget.kind);
    if (bestIndex < 0)
        return ErrorBudgetWords::tr("nothing meets %1: no measured rows").arg(budget.describe());
    return ErrorBudgetWords::tr("nothing meets %1: the best measured was %2 (%3)")
        .arg(budget.describe(), rowError(rows[bestIndex], budget.kind), rowLabel(rows[bestIndex]));
}

// "saves 3 412 triangles and 1.9 ms (40 %)", "costs 0.2 ms more", "saves nothing"
QString savingsText(const BudgetFit &fit, const BenchRow &base)
{
    QStringList parts;
    if (fit.trianglesSaved > 0)
        parts << ErrorBudgetWords::tr("%1 triangles").arg(groupedNumber(fit.trianglesSaved));
    QString timePart;
    if (std::isfinite(fit.msSaved) && fit.msSaved > 0) {
        timePart = QStringLiteral("%1 ms").arg(formatMs(fit.msSaved));
        if (base.frameMs > 0)
            timePart += QStringLiteral(" (%1 %)").arg(
                sentenceLocale().toString(fit.msSaved / base.frameMs * 100.0, 'f', 0));
        parts << timePart;
    }
    QString effect;
    if (!parts.isEmpty())
        effect = ErrorBudgetWords::tr("saves %1").arg(parts.join(ErrorBudgetWords::tr(" and ")));
    QStringList costs;
    if (fit.trianglesSaved < 0)
        costs << ErrorBudgetWords::tr("%1 more triangles").arg(groupedNumber(-fit.trianglesSaved));
    if (std::isfinite(fit.msSaved) && fit.msSaved < 0)
        costs << ErrorBudgetWords::tr("%1 ms more").arg(formatMs(-fit.msSaved));
    if (!costs.isEmpty())
        effect += (effect.isEmpty() ? ErrorBudgetWords::tr("costs ")
                                    : ErrorBudgetWords::tr(" but costs "))
            + costs.join(ErrorBudgetWords::tr(" and "));
    if (effect.isEmpty())
        effect = ErrorBudgetWords::tr("saves nothing");
    return effect;
}

} // namespace

BudgetFit fitToBudget(const std::vector<BenchRow> &rows, const ErrorBudget &budget)
{
    BudgetFit fit;
    fit.baseline = baselineIndex(rows);
    fit.chosen = chooseCheapest(rows, budget);
    if (fit.chosen < 0) {
        fit.summary = nothingFitsSummary(rows, budget);
        return fit;
    }

    const BenchRow &chosen = rows[fit.chosen];
    const QString error = rowError(chosen, budget.kind);

    if (fit.baseline < 0) {
        fit.summary = ErrorBudgetWords::tr(
                          "%1 (%2) meets %3; %4; no full-detail Phong row to compare against")
                          .arg(rowLabel(chosen), rowCost(chosen), budget.describe(), error);
        return fit;
    }

    const BenchRow &base = rows[fit.baseline];
    fit.trianglesSaved = base.triangles - chosen.triangles;
    fit.msSaved = base.frameMs - chosen.frameMs;
    const QString baseText =
        ErrorBudgetWords::tr("full-detail %1 (%2)").arg(methodTitle(base.method), rowCost(base));

    if (fit.chosen == fit.baseline) {
        fit.summary = ErrorBudgetWords::tr("%1 is the cheapest that meets %2; %3")
                          .arg(baseText, budget.describe(), error);
        return fit;
    }

    fit.summary =
        QStringLiteral("%1 (%2): %3 against %4; %5")
            .arg(rowLabel(chosen), rowCost(chosen), savingsText(fit, base), baseText, error);
    return fit;
}

} // namespace phonglab
