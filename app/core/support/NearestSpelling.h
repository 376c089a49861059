#pragma once
#include <QString>
#include <QStringList>

// What a slip of the keyboard most likely meant: `--szie` → `--size`,
// `meshinfo` → `mesh-info`, `builtin:cub` → `builtin:cube`. One wording for
// every place that refuses a word it does not know, so that the command
// line, the window's arguments and the scene reader read alike.
namespace phonglab {

// Optimal string alignment distance: insertions, deletions, substitutions
// and swaps of two neighbouring letters each cost one. The one measure of
// "how far apart are two spellings" (option names, mesh names, uniform
// names against their usual aliases).
qsizetype editDistance(const QString &a, const QString &b);

// The candidate closest to `given` by edit distance (a swap of two
// neighbouring letters counts once), when it is close enough to be a slip:
// at most a third of the longer word's letters differ (at least one; none
// for words under four letters, where anything is one letter off). Empty
// when none is.
QString nearestSpelling(const QString &given, const QStringList &candidates);

// "unknown option '--szie' (did you mean '--size'?)" when one of `known`
// (spelled with their dashes) is near, else "unknown option '--szie'".
QString unknownOptionMessage(const QString &given, const QStringList &known);
// "unknown command 'meshinfo' (did you mean 'mesh-info'?)", likewise.
QString unknownCommandMessage(const QString &given, const QStringList &known);
// " (did you mean 'builtin:cube'?)" when one of `known` is near, else empty:
// for messages that name what they refuse in their own words.
QString didYouMean(const QString &given, const QStringList &known);

} // namespace phonglab
