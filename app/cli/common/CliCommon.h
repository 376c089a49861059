#pragma once
#include <QCommandLineOption>
#include <QList>
#include <QSize>
#include <QString>
#include <QStringList>
#include <optional>

class QCommandLineParser;

namespace phonglab::cli {

// Exit codes shared by every subcommand (scripts rely on them).
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1; // bad input, render or compile failure
inline constexpr int kExitUsage = 2;   // wrong arguments

// "phonglab: error: MESSAGE" on stderr.
void printError(const QString &message);
void printLine(const QString &text);    // stdout
void printErrLine(const QString &text); // stderr, verbatim

QStringList argumentsFrom(int argc, char **argv);

// A usage error: "phonglab: error: MESSAGE" and the synopsis on stderr;
// returns kExitUsage.
int usageError(const QString &message, const QString &synopsis);
// What every subcommand does with its arguments first: adds `help` and
// `options` to `parser` and parses. A parse error is a usage error (an
// unknown option named as typed, with the nearest known one suggested), and
// so is an option with a value given twice unless `repeatable` names it
// (`--bind`): the second would otherwise win silently. --help prints
// `helpText` and exits 0. nullopt: go on.
struct CommandOptions {
    QCommandLineOption help;
    QList<QCommandLineOption> options; // all but help
    QStringList repeatable;            // names that may come more than once
};
std::optional<int> parseOrExit(QCommandLineParser &parser, const QStringList &arguments,
                               const CommandOptions &options, const QString &synopsis,
                               const QString &helpText);

// An option's line in a command's --help: "  --size WxH", then from the
// 23rd column its description, each further line of it indented as far.
QString helpLine(const QCommandLineOption &option);
// Several, one line (or more) each.
QString helpLines(const QList<QCommandLineOption> &options);

// "WxH" with each side in [minSide, maxSide] pixels; nullopt otherwise.
std::optional<QSize> parseSizeArgument(const QString &text, int minSide, int maxSide);

} // namespace phonglab::cli
