#include "GuiArguments.h"

#include "core/support/NearestSpelling.h"

#include <QCoreApplication>

namespace phonglab {

namespace {

struct GuiArgumentsWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::GuiArguments)
};

// "--vertex FILE" or "--vertex=FILE": the value, taking the next argument
// when it is separate; false when `argument` is not `option`.
bool takeValue(const QString &option, const QStringList &arguments, qsizetype &i, QString &value,
               QString &error)
{
    const QString &argument = arguments[i];
    if (argument.startsWith(option + QLatin1Char('='))) {
        value = argument.mid(option.size() + 1);
    } else if (argument == option) {
        if (i + 1 >= arguments.size()) {
            error = GuiArgumentsWords::tr("%1 needs a file").arg(option);
            return true;
        }
        value = arguments[++i];
    } else {
        return false;
    }
    if (value.isEmpty())
        error = GuiArgumentsWords::tr("%1 needs a file").arg(option);
    return true;
}

} // namespace

GuiArguments parseGuiArguments(const QStringList &arguments)
{
    GuiArguments out;
    bool options = true;
    for (qsizetype i = 0; i < arguments.size() && out.error.isEmpty(); ++i) {
        const QString &argument = arguments[i];
        if (options && argument == QLatin1String("--")) {
            options = false;
        } else if (options
                   && (takeValue(QStringLiteral("--vertex"), arguments, i, out.vertexShader,
                                 out.error)
                       || takeValue(QStringLiteral("--fragment"), arguments, i, out.fragmentShader,
                                    out.error)
                       || takeValue(QStringLiteral("--project"), arguments, i, out.project,
                                    out.error)
                       || takeValue(QStringLiteral("--program"), arguments, i, out.program,
                                    out.error))) {
            continue;
        } else if (options && argument.startsWith(QLatin1Char('-')) && argument.size() > 1) {
            // --lang was taken out before (core/support/Language); the rest are
            // the commands' own or slips.
            out.error = unknownOptionMessage(
                argument.section(QLatin1Char('='), 0, 0),
                {QStringLiteral("--vertex"), QStringLiteral("--fragment"),
                 QStringLiteral("--project"), QStringLiteral("--program"), QStringLiteral("--lang"),
                 QStringLiteral("--help"), QStringLiteral("--version")});
        } else {
            out.files << argument;
        }
    }
    if (out.error.isEmpty() && out.hasShaders()
        && (out.files.size() != 1
            || !out.files.front().endsWith(QLatin1String(".json"), Qt::CaseInsensitive)))
        out.error = GuiArgumentsWords::tr(
            "--vertex and --fragment open one scene with those shaders: phonglab SCENE.json "
            "--vertex FILE --fragment FILE");
    if (out.error.isEmpty() && !out.project.isEmpty()
        && (!out.vertexShader.isEmpty() || !out.fragmentShader.isEmpty()))
        out.error = GuiArgumentsWords::tr(
            "--project takes both stages from the project; leave out --vertex and --fragment");
    if (out.error.isEmpty() && !out.program.isEmpty() && out.project.isEmpty())
        out.error = GuiArgumentsWords::tr("--program names a program of --project");
    return out;
}

} // namespace phonglab
