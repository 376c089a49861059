#include "SceneJsonText.h"

#include <QCoreApplication>
#include <QJsonArray>

#include <QJsonObject>
#include <QRegularExpression>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

namespace phonglab::scenejson {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct SceneJsonTextWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::SceneJsonText)
};

Result<NormalOptions> readNormalOptions(const QJsonValue &value, const QString &path,
                                        NormalOptions out)
{
    if (value.isUndefined())
        return out;
    const auto located = [](const QString &where, const QString &reason) {
        return fail(where + QStringLiteral(": ") + reason);
    };
    const auto readMethod = [&](const QJsonValue &v, const QString &where) -> Result<> {
        if (!v.isString())
            return located(
                where, SceneJsonTextWords::tr("expected a string (got %1)").arg(describeType(v)));
        const auto method = normalMethodFromName(v.toString());
        if (!method)
            return located(where,
                           SceneJsonTextWords::tr("unknown normal method \"%1\" (known: %2)")
                               .arg(v.toString(), normalMethodNames().join(QStringLiteral(", "))));
        out.method = *method;
        return {};
    };
    if (value.isString()) {
        if (const Result<> method = readMethod(value, path); !method)
            return fail(method.error());
        return out;
    }
    if (!value.isObject())
        return located(path,
                       SceneJsonTextWords::tr("expected a string or an object (got %1)")
                           .arg(describeType(value)));
    const QJsonObject object = value.toObject();
    for (auto it = object.begin(); it != object.end(); ++it)
        if (it.key() != QLatin1String("method") && it.key() != QLatin1String("crease_deg"))
            return located(path + QLatin1Char('.') + it.key(),
                           SceneJsonTextWords::tr("unknown key"));
    if (object.contains(QLatin1String("method")))
        if (const Result<> method =
                readMethod(object.value(QLatin1String("method")), path + QStringLiteral(".method"));
            !method)
            return fail(method.error());
    const QJsonValue crease = object.value(QLatin1String("crease_deg"));
    if (crease.isUndefined() || crease.isNull()) {
        out.creaseAngleDeg.reset();
        return out;
    }
    const QString creasePath = path + QStringLiteral(".crease_deg");
    if (!crease.isDouble() || overflowLiteral(crease))
        return located(
            creasePath,
            SceneJsonTextWords::tr("expected a finite number (got %1)").arg(describeType(crease)));
    const double degrees = crease.toDouble();
    if (!(degrees >= 0.0 && degrees <= 180.0))
        return located(creasePath,
                       SceneJsonTextWords::tr("must be in [0, 180] degrees (got %1)").arg(degrees));
    out.creaseAngleDeg = degrees;
    return out;
}

QJsonValue normalOptionsJson(const NormalOptions &options)
{
    if (!options.creaseAngleDeg)
        return normalMethodName(options.method);
    QJsonObject object;
    object.insert(QStringLiteral("method"), normalMethodName(options.method));
    object.insert(QStringLiteral("crease_deg"), *options.creaseAngleDeg);
    return object;
}

namespace {

Result<double> readUniformNumber(const QJsonValue &v, const QString &where)
{
    if (!v.isDouble() || overflowLiteral(v) || !std::isfinite(v.toDouble()))
        return fail(
            where
            + SceneJsonTextWords::tr(": expected a finite number (got %1)").arg(describeType(v)));
    return v.toDouble();
}

} // namespace

Result<UserUniforms> readUserUniforms(const QJsonValue &value, const QString &path)
{
    if (value.isUndefined())
        return UserUniforms{};
    if (!value.isObject())
        return fail(path
                    + SceneJsonTextWords::tr(": expected an object of name: value (got %1)")
                          .arg(describeType(value)));
    const QJsonObject object = value.toObject();
    UserUniforms read;
    for (auto it = object.begin(); it != object.end(); ++it) {
        const QString where = path + QLatin1Char('.') + it.key();
        if (it.key().trimmed().isEmpty())
            return fail(path + SceneJsonTextWords::tr(": a uniform name must not be empty"));
        std::vector<double> values;
        if (it.value().isArray()) {
            const QJsonArray array = it.value().toArray();
            if (array.isEmpty() || array.size() > 16)
                return fail(where
                            + SceneJsonTextWords::tr(": expected 1 to 16 numbers (got %1)")
                                  .arg(array.size()));
            for (qsizetype i = 0; i < array.size(); ++i) {
                const Result<double> v =
                    readUniformNumber(array.at(i), where + QStringLiteral("[%1]").arg(i));
                if (!v)
                    return fail(v.error());
                values.push_back(*v);
            }
        } else {
            const Result<double> v = readUniformNumber(it.value(), where);
            if (!v)
                return fail(v.error());
            values.push_back(*v);
        }
        read[it.key()] = std::move(values);
    }
    return read;
}

Result<ExplicitBindings> readBindings(const QJsonValue &value, const QString &path)
{
    if (value.isUndefined())
        return ExplicitBindings{};
    if (!value.isObject())
        return fail(path
                    + SceneJsonTextWords::tr(": expected an object of name: meaning (got %1)")
                          .arg(describeType(value)));
    const QJsonObject object = value.toObject();
    ExplicitBindings read;
    for (auto it = object.begin(); it != object.end(); ++it) {
        const QString where = path + QLatin1Char('.') + it.key();
        if (it.key().trimmed().isEmpty())
            return fail(path + SceneJsonTextWords::tr(": a variable name must not be empty"));
        if (!it.value().isString())
            return fail(where
                        + SceneJsonTextWords::tr(": expected a meaning's name (got %1)")
                              .arg(describeType(it.value())));
        const QString key = it.value().toString();
        if (key == kUnboundWord) {
            read[it.key()] = std::nullopt;
            continue;
        }
        const std::optional<BindingMeaning> meaning = bindingMeaningFromKey(key);
        if (!meaning)
            return fail(
                where
                + SceneJsonTextWords::tr(": unknown meaning \"%1\" (known: %2, %3)")
                      .arg(key, bindingMeaningKeys().join(QStringLiteral(", ")), kUnboundWord));
        read[it.key()] = *meaning;
    }
    return read;
}

Result<PageDefines> readDefines(const QJsonValue &value, const QString &path)
{
    if (value.isUndefined())
        return PageDefines{};
    if (!value.isObject())
        return fail(path
                    + SceneJsonTextWords::tr(": expected an object of NAME: VALUE (got %1)")
                          .arg(describeType(value)));
    const QJsonObject object = value.toObject();
    PageDefines read;
    for (auto it = object.begin(); it != object.end(); ++it) {
        const QString where = path + QLatin1Char('.') + it.key();
        QString text;
        if (it.value().isString())
            text = it.value().toString();
        else if (it.value().isDouble())
            text = QString::number(it.value().toDouble(), 'g', 17);
        else
            return fail(where
                        + SceneJsonTextWords::tr(": expected the token's value, a string or a "
                                                 "number (got %1)")
                              .arg(describeType(it.value())));
        QString error;
        const std::optional<ParsedDefine> parsed =
            parseDefineArgument(it.key() + QLatin1Char('=') + text, &error);
        if (!parsed)
            return fail(where + QStringLiteral(": ") + error);
        read[parsed->name] = parsed->value;
    }
    return read;
}

QJsonValue definesJson(const PageDefines &defines)
{
    QJsonObject object;
    for (const auto &[name, value] : defines)
        object.insert(name, value);
    return object;
}

Result<PrecisionRule> readPrecision(const QJsonValue &value, const QString &path)
{
    if (value.isUndefined())
        return PrecisionRule::Highp;
    const std::optional<PrecisionRule> rule = precisionRuleFromKey(value.toString());
    if (!value.isString() || !rule)
        return fail(path
                    + SceneJsonTextWords::tr(": expected \"highp\" or \"as-written\" (got %1)")
                          .arg(value.isString() ? QStringLiteral("\"%1\"").arg(value.toString())
                                                : describeType(value)));
    return *rule;
}

QJsonValue bindingsJson(const ExplicitBindings &bindings)
{
    QJsonObject object;
    for (const auto &[name, meaning] : bindings)
        object.insert(name, meaning ? bindingMeaningKey(*meaning) : kUnboundWord);
    return object;
}

QJsonValue userUniformsJson(const std::map<QString, std::vector<double>> &uniforms)
{
    QJsonObject object;
    for (const auto &[name, values] : uniforms) {
        if (values.size() == 1) {
            object.insert(name, values.front());
            continue;
        }
        QJsonArray array;
        for (double v : values)
            array.append(v);
        object.insert(name, array);
    }
    return object;
}

} // namespace phonglab::scenejson
