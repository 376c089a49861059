#include "SceneJsonText.h"

#include <QJsonArray>

#include <QJsonObject>
#include <QRegularExpression>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace phonglab::scenejson {

namespace {

// The NUL makes a clash with a key someone actually wrote implausible.
const QString kOverflowKey = QStringLiteral("\u0000phonglab:out-of-range-number");
constexpr QByteArrayView kOverflowKeyJson = "\\u0000phonglab:out-of-range-number";

// Each rewrite costs a full re-parse; a file with more huge literals than this
// is reported as the syntax error Qt gives.
constexpr int kMaxRewrites = 64;

// A rewrite made at `position` (in the rewritten text) that grew it by `growth`.
struct Rewrite {
    qsizetype position;
    qsizetype growth;
};

bool isNumberChar(char c)
{
    return (c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-';
}

// Qt reports an illegal number at the byte just past the literal.
std::pair<qsizetype, qsizetype> literalBefore(const QByteArray &text, qsizetype end)
{
    end = std::min(end, text.size());
    qsizetype begin = end;
    while (begin > 0 && isNumberChar(text.at(begin - 1)))
        --begin;
    return {begin, end};
}

// Replaces the out-of-range literal that ends at `offset`; false when the
// literal is illegal for another reason (e.g. "01"), which stays an error.
bool rewriteOutOfRangeLiteral(QByteArray &text, qsizetype offset, std::vector<Rewrite> &rewrites)
{
    static const QRegularExpression jsonNumber(QStringLiteral("^-?(0|[1-9][0-9]*)(\\.[0-9]+)?([eE][+-]?[0-9]+)?$"));
    const auto [begin, end] = literalBefore(text, offset);
    const QByteArray literal = text.mid(begin, end - begin);
    if (literal.isEmpty() || !jsonNumber.match(QString::fromLatin1(literal)).hasMatch())
        return false;

    errno = 0;
    const double value = std::strtod(literal.constData(), nullptr);
    if (errno != ERANGE)
        return false;

    QByteArray replacement;
    if (std::isinf(value))
        replacement = "{\"" + kOverflowKeyJson.toByteArray() + "\":\"" + literal + "\"}";
    else
        replacement = "0"; // underflow: 0 is the nearest double
    text.replace(begin, literal.size(), replacement);
    rewrites.push_back({begin, replacement.size() - literal.size()});
    return true;
}

qsizetype originalOffset(qsizetype offset, const std::vector<Rewrite> &rewrites)
{
    for (auto it = rewrites.rbegin(); it != rewrites.rend(); ++it)
        if (it->position < offset)
            offset -= it->growth;
    return std::max<qsizetype>(offset, 0);
}

QString syntaxError(const QByteArray &json, qsizetype offset, const QString &reason)
{
    offset = std::min(offset, json.size());
    const QByteArray before = json.left(offset);
    const qsizetype line = before.count('\n') + 1;
    const qsizetype column = offset - (before.lastIndexOf('\n') + 1) + 1;
    return QStringLiteral("JSON syntax error at line %1, column %2 (byte offset %3): %4")
        .arg(line)
        .arg(column)
        .arg(offset)
        .arg(reason);
}

} // namespace

std::optional<QJsonDocument> parseJsonText(const QByteArray &json, QString *error)
{
    QByteArray text = json;
    std::vector<Rewrite> rewrites;
    for (;;) {
        QJsonParseError parseError;
        QJsonDocument doc = QJsonDocument::fromJson(text, &parseError);
        if (parseError.error == QJsonParseError::NoError)
            return doc;
        if (parseError.error == QJsonParseError::IllegalNumber && int(rewrites.size()) < kMaxRewrites
            && rewriteOutOfRangeLiteral(text, parseError.offset, rewrites))
            continue;
        *error = syntaxError(json, originalOffset(parseError.offset, rewrites), parseError.errorString());
        return std::nullopt;
    }
}

std::optional<QString> overflowLiteral(const QJsonValue &value)
{
    if (!value.isObject())
        return std::nullopt;
    const QJsonObject object = value.toObject();
    if (object.size() != 1 || !object.contains(kOverflowKey))
        return std::nullopt;
    return object.value(kOverflowKey).toString();
}

QString describeType(const QJsonValue &value)
{
    if (const auto literal = overflowLiteral(value))
        return QStringLiteral("out-of-range number %1").arg(*literal);
    switch (value.type()) {
    case QJsonValue::Null: return QStringLiteral("null");
    case QJsonValue::Bool: return QStringLiteral("boolean");
    case QJsonValue::Double: return QStringLiteral("number");
    case QJsonValue::String: return QStringLiteral("string");
    case QJsonValue::Array: return QStringLiteral("array");
    case QJsonValue::Object: return QStringLiteral("object");
    case QJsonValue::Undefined: break;
    }
    return QStringLiteral("nothing");
}

bool readNormalOptions(const QJsonValue &value, const QString &path, NormalOptions &out, QString *error)
{
    if (value.isUndefined())
        return true;
    auto fail = [&](const QString &where, const QString &reason) {
        *error = where + QStringLiteral(": ") + reason;
        return false;
    };
    auto readMethod = [&](const QJsonValue &v, const QString &where) {
        if (!v.isString())
            return fail(where, QStringLiteral("expected a string (got %1)").arg(describeType(v)));
        const auto method = normalMethodFromName(v.toString());
        if (!method)
            return fail(where,
                        QStringLiteral("unknown normal method \"%1\" (known: %2)")
                            .arg(v.toString(), normalMethodNames().join(QStringLiteral(", "))));
        out.method = *method;
        return true;
    };
    if (value.isString())
        return readMethod(value, path);
    if (!value.isObject())
        return fail(path, QStringLiteral("expected a string or an object (got %1)").arg(describeType(value)));
    const QJsonObject object = value.toObject();
    for (auto it = object.begin(); it != object.end(); ++it)
        if (it.key() != QLatin1String("method") && it.key() != QLatin1String("crease_deg"))
            return fail(path + QLatin1Char('.') + it.key(), QStringLiteral("unknown key"));
    if (object.contains(QLatin1String("method"))
        && !readMethod(object.value(QLatin1String("method")), path + QStringLiteral(".method")))
        return false;
    const QJsonValue crease = object.value(QLatin1String("crease_deg"));
    if (crease.isUndefined() || crease.isNull()) {
        out.creaseAngleDeg.reset();
        return true;
    }
    const QString creasePath = path + QStringLiteral(".crease_deg");
    if (!crease.isDouble() || overflowLiteral(crease))
        return fail(creasePath, QStringLiteral("expected a finite number (got %1)").arg(describeType(crease)));
    const double degrees = crease.toDouble();
    if (!(degrees >= 0.0 && degrees <= 180.0))
        return fail(creasePath, QStringLiteral("must be in [0, 180] degrees (got %1)").arg(degrees));
    out.creaseAngleDeg = degrees;
    return true;
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

bool readUniformNumber(const QJsonValue &v, const QString &where, double &out, QString *error)
{
    if (!v.isDouble() || overflowLiteral(v) || !std::isfinite(v.toDouble())) {
        *error = where + QStringLiteral(": expected a finite number (got %1)").arg(describeType(v));
        return false;
    }
    out = v.toDouble();
    return true;
}

} // namespace

bool readUserUniforms(const QJsonValue &value, const QString &path, std::map<QString, std::vector<double>> &out,
                      QString *error)
{
    if (value.isUndefined())
        return true;
    if (!value.isObject()) {
        *error = path + QStringLiteral(": expected an object of name: value (got %1)").arg(describeType(value));
        return false;
    }
    const QJsonObject object = value.toObject();
    std::map<QString, std::vector<double>> read;
    for (auto it = object.begin(); it != object.end(); ++it) {
        const QString where = path + QLatin1Char('.') + it.key();
        if (it.key().trimmed().isEmpty()) {
            *error = path + QStringLiteral(": a uniform name must not be empty");
            return false;
        }
        std::vector<double> values;
        if (it.value().isArray()) {
            const QJsonArray array = it.value().toArray();
            if (array.isEmpty() || array.size() > 16) {
                *error = where + QStringLiteral(": expected 1 to 16 numbers (got %1)").arg(array.size());
                return false;
            }
            for (qsizetype i = 0; i < array.size(); ++i) {
                double v = 0;
                if (!readUniformNumber(array.at(i), where + QStringLiteral("[%1]").arg(i), v, error))
                    return false;
                values.push_back(v);
            }
        } else {
            double v = 0;
            if (!readUniformNumber(it.value(), where, v, error))
                return false;
            values.push_back(v);
        }
        read[it.key()] = std::move(values);
    }
    out = std::move(read);
    return true;
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
