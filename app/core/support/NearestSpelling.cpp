#include "NearestSpelling.h"

#include <QCoreApplication>

#include <algorithm>
#include <vector>

namespace phonglab {

namespace {

struct SpellingWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::NearestSpelling)
};

// Optimal string alignment distance: insertions, deletions, substitutions
// and transpositions of neighbours each cost one.
qsizetype editDistance(const QString &a, const QString &b)
{
    const qsizetype n = a.size(), m = b.size();
    std::vector<std::vector<qsizetype>> d(std::size_t(n + 1),
                                          std::vector<qsizetype>(std::size_t(m + 1)));
    for (qsizetype i = 0; i <= n; ++i)
        d[std::size_t(i)][0] = i;
    for (qsizetype j = 0; j <= m; ++j)
        d[0][std::size_t(j)] = j;
    for (qsizetype i = 1; i <= n; ++i) {
        for (qsizetype j = 1; j <= m; ++j) {
            const auto I = std::size_t(i), J = std::size_t(j);
            const qsizetype cost = a[i - 1] == b[j - 1] ? 0 : 1;
            d[I][J] = std::min({d[I - 1][J] + 1, d[I][J - 1] + 1, d[I - 1][J - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[I][J] = std::min(d[I][J], d[I - 2][J - 2] + 1);
        }
    }
    return d[std::size_t(n)][std::size_t(m)];
}

} // namespace

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
