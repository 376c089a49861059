#include "NearestSpelling.h"

#include <QCoreApplication>

#include <algorithm>
#include <utility>
#include <vector>

namespace phonglab {

namespace {

struct SpellingWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::NearestSpelling)
};

} // namespace

qsizetype editDistance(const QString &a, const QString &b)
{
    // Three rows of the table: a transposition looks two rows back.
    const auto width = std::size_t(b.size()) + 1;
    std::vector<qsizetype> before(width), above(width), row(width);
    for (std::size_t j = 0; j < width; ++j)
        row[j] = qsizetype(j);
    for (qsizetype i = 1; i <= a.size(); ++i) {
        std::swap(before, above);
        std::swap(above, row);
        row[0] = i;
        for (qsizetype j = 1; j <= b.size(); ++j) {
            const auto J = std::size_t(j);
            const qsizetype cost = a[i - 1] == b[j - 1] ? 0 : 1;
            row[J] = std::min({above[J] + 1, row[J - 1] + 1, above[J - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                row[J] = std::min(row[J], before[J - 2] + 1);
        }
    }
    return row.back();
}

QString nearestSpelling(const QString &given, const QStringList &candidates)
{
    // Words longer than this are not slips of the keyboard; and the table
    // above grows with the square of the length.
    constexpr qsizetype kLongestWord = 64;
    if (given.isEmpty() || given.size() > kLongestWord)
        return {};
    const QString lower = given.toLower();
    QString best;
    qsizetype bestDistance = 0;
    for (const QString &candidate : candidates) {
        if (candidate.size() > kLongestWord)
            continue;
        const qsizetype distance = editDistance(lower, candidate.toLower());
        // "-o" for "-h" is no slip worth naming: words this short get none.
        const qsizetype longer = std::max(given.size(), candidate.size());
        const qsizetype allowed = longer < 4 ? 0 : std::max<qsizetype>(1, longer / 3);
        if (distance <= allowed && (best.isEmpty() || distance < bestDistance)) {
            best = candidate;
            bestDistance = distance;
        }
    }
    return best;
}

QString didYouMean(const QString &given, const QStringList &known)
{
    const QString nearest = nearestSpelling(given, known);
    return nearest.isEmpty() ? QString() : SpellingWords::tr(" (did you mean '%1'?)").arg(nearest);
}

QString unknownOptionMessage(const QString &given, const QStringList &known)
{
    return SpellingWords::tr("unknown option '%1'").arg(given) + didYouMean(given, known);
}

QString unknownCommandMessage(const QString &given, const QStringList &known)
{
    return SpellingWords::tr("unknown command '%1'").arg(given) + didYouMean(given, known);
}

} // namespace phonglab
