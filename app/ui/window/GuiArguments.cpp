#include "GuiArguments.h"

namespace phonglab {

namespace {

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
            error = QStringLiteral("%1 needs a file").arg(option);
            return true;
        }
        value = arguments[++i];
    } else {
        return false;
    }
    if (value.isEmpty())
        error = QStringLiteral("%1 needs a file").arg(option);
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
                       || takeValue(QStringLiteral("--fragment"), arguments, i,
                                    out.fragmentShader, out.error))) {
            continue;
        } else if (options && argument.startsWith(QLatin1Char('-')) && argument.size() > 1) {
            out.error = QStringLiteral("unknown option %1 (phonglab --help lists the commands)")
                            .arg(argument);
        } else {
            out.files << argument;
        }
    }
    if (out.error.isEmpty() && out.hasShaders()
        && (out.files.size() != 1
            || !out.files.front().endsWith(QLatin1String(".json"), Qt::CaseInsensitive)))
        out.error = QStringLiteral(
            "--vertex and --fragment open one scene with those shaders: phonglab SCENE.json "
            "--vertex FILE --fragment FILE");
    return out;
}

} // namespace phonglab
