#include "CliCommon.h"

#include <QCommandLineParser>
#include <QRegularExpression>

#include <cstdio>

namespace phonglab::cli {

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

std::optional<int> parseOrExit(QCommandLineParser &parser, const QStringList &arguments,
                               const QCommandLineOption &help, const QString &synopsis,
                               const QString &helpText)
{
    if (!parser.parse(arguments))
        return usageError(parser.errorText(), synopsis);
    if (parser.isSet(help)) {
        printLine(helpText);
        return kExitOk;
    }
    return std::nullopt;
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
