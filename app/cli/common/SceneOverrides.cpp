#include "SceneOverrides.h"

#include <QCoreApplication>
#include <QRegularExpression>

namespace phonglab::cli {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct SceneOverridesWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::cli::SceneOverrides)
};

namespace {

// "1", "0,0,0", "-0.5, 2e-3": the numbers of a constant, or nullopt where
// the text is a meaning's name.
std::optional<std::vector<double>> constantOf(const QString &text)
{
    std::vector<double> numbers;
    for (const QString &part : text.split(QLatin1Char(','))) {
        bool ok = false;
        const double v = part.trimmed().toDouble(&ok);
        if (!ok || !std::isfinite(v))
            return std::nullopt;
        numbers.push_back(v);
    }
    return numbers;
}

QString numbersText(const std::vector<double> &numbers)
{
    QStringList parts;
    for (double v : numbers)
        parts << QString::number(v, 'g', 17);
    return parts.join(QLatin1Char(','));
}

} // namespace

SceneOverrideOptions::SceneOverrideOptions(Use use)
    : bind(QStringLiteral("bind"),
           SceneOverridesWords::tr("what the shader's uniform or input NAME holds; repeatable. "
                                   "Names are\nbound by themselves where they say it "
                                   "(uModelMatrix, aPosition, u_kd);\nthis wins over that. "
                                   "Meanings: %1, or none; or a constant the\npage sets "
                                   "(--bind mode=1, --bind 'u_MatlSet[0].emit=0,0,0')")
               .arg(bindingMeaningKeys().join(QStringLiteral(", "))),
           QStringLiteral("NAME=MEANING"))
    , define(QStringLiteral("define"),
             SceneOverridesWords::tr("a token the page's JavaScript replaces before compiling "
                                     "(NUM_LIGHTS=2);\nrepeatable"),
             QStringLiteral("NAME=VALUE"))
    , precision(QStringLiteral("precision"),
                use == Use::Check
                    ? SceneOverridesWords::tr("highp (default): every float checked at 32 bits, "
                                              "as a desktop browser\ncomputes it, and what "
                                              "mediump or lowp would change said apart;\n"
                                              "as-written: the declared precision, as this "
                                              "driver computes it")
                    : SceneOverridesWords::tr("highp (default: every float at 32 bits, as a "
                                              "desktop browser\ncomputes it) or as-written (the "
                                              "declared precision, as this driver\ncomputes it)"),
                QStringLiteral("RULE"))
{
}

void SceneOverrides::applyTo(Scene &scene) const
{
    for (const auto &[name, meaning] : bindings)
        scene.bindings[name] = meaning;
    for (const auto &[name, values] : constants) {
        scene.uniforms[name] = values;
        scene.bindings[name] = std::nullopt; // the page's value, not a meaning
    }
    for (const auto &[name, value] : defines)
        scene.course.defines[name] = value;
    if (precision)
        scene.course.precision = *precision;
}

QStringList SceneOverrides::arguments() const
{
    QStringList out;
    for (const auto &[name, meaning] : bindings)
        out << QStringLiteral("--bind")
            << QStringLiteral("%1=%2").arg(name,
                                           meaning ? bindingMeaningKey(*meaning) : kUnboundWord);
    for (const auto &[name, values] : constants)
        out << QStringLiteral("--bind") << QStringLiteral("%1=%2").arg(name, numbersText(values));
    for (const auto &[name, value] : defines)
        out << QStringLiteral("--define") << QStringLiteral("%1=%2").arg(name, value);
    if (precision)
        out << QStringLiteral("--precision") << precisionRuleKey(*precision);
    return out;
}

QString readSceneOverrides(const QCommandLineParser &parser, const SceneOverrideOptions &options,
                           SceneOverrides *out)
{
    for (const QString &text : parser.values(options.bind)) {
        const qsizetype eq = text.indexOf(QLatin1Char('='));
        if (eq > 0) {
            if (const auto values = constantOf(text.mid(eq + 1))) {
                out->constants[text.left(eq).trimmed()] = *values;
                continue;
            }
        }
        QString error;
        const std::optional<ParsedBinding> parsed = parseBindingArgument(text, &error);
        if (!parsed)
            return QStringLiteral("--bind: %1").arg(error);
        out->bindings[parsed->name] = parsed->meaning;
    }
    for (const QString &text : parser.values(options.define)) {
        QString error;
        const std::optional<ParsedDefine> parsed = parseDefineArgument(text, &error);
        if (!parsed)
            return QStringLiteral("--define: %1").arg(error);
        out->defines[parsed->name] = parsed->value;
    }
    if (parser.isSet(options.precision)) {
        out->precision = precisionRuleFromKey(parser.value(options.precision));
        if (!out->precision)
            return SceneOverridesWords::tr("--precision: expected highp or as-written, got '%1'")
                .arg(parser.value(options.precision));
    }
    return {};
}

} // namespace phonglab::cli
