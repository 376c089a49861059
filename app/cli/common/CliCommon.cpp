#include "CliCommon.h"

#include "core/support/NearestSpelling.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QRegularExpression>

#include <cstdio>

namespace phonglab::cli {

struct CliCommonWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::cli::CliCommon)
};

void printError(const QString &message)
{
    std::fprintf(stderr, "phonglab: error: %s\n", message.toLocal8Bit().constData());
    std::fflush(stderr);
}

void printLine(const QString &text)
{
    std::fprintf(stdout, "%s\n", text.toLocal8Bit().constData());
    std::fflush(stdout);
}

void printErrLine(const QString &text)
{
    std::fprintf(stderr, "%s\n", text.toLocal8Bit().constData());
    std::fflush(stderr);
}

int usageError(const QString &message, const QString &synopsis)
{
    printError(message);
    printErrLine(synopsis);
    return kExitUsage;
}

namespace {

// "-o" or "--size": an option's name as a user types it.
QString dashed(const QString &name)
{
    return (name.size() == 1 ? QStringLiteral("-") : QStringLiteral("--")) + name;
}

// The unknown option `name` as the user typed it (without "=value").
QString typedOption(const QString &name, const QStringList &arguments)
{
    for (const QString &argument : arguments.mid(1)) {
        if (argument == QLatin1String("--"))
            break;
        const QString spelled = argument.section(QLatin1Char('='), 0, 0);
        if (spelled.startsWith(QLatin1Char('-'))
            && spelled.mid(spelled.startsWith(QLatin1String("--")) ? 2 : 1) == name)
            return spelled;
    }
    return dashed(name);
}

} // namespace

std::optional<int> parseOrExit(QCommandLineParser &parser, const QStringList &arguments,
                               const CommandOptions &options, const QString &synopsis,
                               const QString &helpText)
{
    parser.addOption(options.help);
    parser.addOptions(options.options);
    if (!parser.parse(arguments)) {
        const QStringList unknown = parser.unknownOptionNames();
        if (unknown.isEmpty())
            return usageError(parser.errorText(), synopsis);
        QStringList known;
        for (const QCommandLineOption &option : options.options)
            if (!(option.flags() & QCommandLineOption::HiddenFromHelp))
                for (const QString &name : option.names())
                    known << dashed(name);
        for (const QString &name : options.help.names())
            known << dashed(name);
        return usageError(unknownOptionMessage(typedOption(unknown.first(), arguments), known),
                          synopsis);
    }
    if (parser.isSet(options.help)) {
        printLine(helpText);
        return kExitOk;
    }
    for (const QCommandLineOption &option : options.options) {
        const QString name = option.names().last();
        if (option.valueName().isEmpty() || options.repeatable.contains(name))
            continue;
        if (const QStringList values = parser.values(option); values.size() > 1)
            return usageError(CliCommonWords::tr("%1 given more than once ('%2', then '%3'): "
                                                 "give it once")
                                  .arg(dashed(name), values[0], values[1]),
                              synopsis);
    }
    return std::nullopt;
}

QString helpLine(const QCommandLineOption &option)
{
    QStringList names;
    for (const QString &name : option.names())
        names << dashed(name);
    QString head = QStringLiteral("  ") + names.join(QStringLiteral(", "));
    if (!option.valueName().isEmpty())
        head += QLatin1Char(' ') + option.valueName();
    const QString indent = QLatin1Char('\n') + QString(22, QLatin1Char(' '));
    return head.leftJustified(21) + QLatin1Char(' ')
        + QString(option.description()).replace(QLatin1Char('\n'), indent);
}

QString helpLines(const QList<QCommandLineOption> &options)
{
    QStringList lines;
    for (const QCommandLineOption &option : options)
        lines << helpLine(option);
    return lines.join(QLatin1Char('\n'));
}

std::optional<QSize> parseSizeArgument(const QString &text, int minSide, int maxSide)
{
    static const QRegularExpression re(QStringLiteral(R"(^(\d{1,6})[xX](\d{1,6})$)"));
    const auto m = re.match(text);
    if (!m.hasMatch())
        return std::nullopt;
    const int w = m.captured(1).toInt(), h = m.captured(2).toInt();
    if (w < minSide || h < minSide || w > maxSide || h > maxSide)
        return std::nullopt;
    return QSize(w, h);
}

QStringList argumentsFrom(int argc, char **argv)
{
    QStringList args;
    for (int i = 0; i < argc; ++i)
        args << QString::fromLocal8Bit(argv[i]);
    return args;
}

} // namespace phonglab::cli
