#include "JsonText.h"

#include <QCoreApplication>
#include <QJsonObject>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <utility>
#include <vector>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct JsonTextWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::JsonText)
};

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
    static const QRegularExpression jsonNumber(
        QStringLiteral("^-?(0|[1-9][0-9]*)(\\.[0-9]+)?([eE][+-]?[0-9]+)?$"));
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

QString syntaxError(const QByteArray &json, qsizetype offset, const QString &reason, int *lineOut,
                    int *columnOut)
{
    offset = std::min(offset, json.size());
    const QByteArray before = json.left(offset);
    const qsizetype line = before.count('\n') + 1;
    const qsizetype column = offset - (before.lastIndexOf('\n') + 1) + 1;
    if (lineOut)
        *lineOut = int(std::min<qsizetype>(line, std::numeric_limits<int>::max()));
    if (columnOut)
        *columnOut = int(std::min<qsizetype>(column, std::numeric_limits<int>::max()));
    return JsonTextWords::tr("JSON syntax error at line %1, column %2 (byte offset %3): %4")
        .arg(line)
        .arg(column)
        .arg(offset)
        .arg(reason);
}

} // namespace

Result<QJsonDocument> parseJsonText(const QByteArray &json, int *line, int *column)
{
    QByteArray text = json;
    std::vector<Rewrite> rewrites;
    for (;;) {
        QJsonParseError parseError;
        QJsonDocument doc = QJsonDocument::fromJson(text, &parseError);
        if (parseError.error == QJsonParseError::NoError)
            return doc;
        if (parseError.error == QJsonParseError::IllegalNumber
            && int(rewrites.size()) < kMaxRewrites
            && rewriteOutOfRangeLiteral(text, parseError.offset, rewrites))
            continue;
        return fail(syntaxError(json, originalOffset(parseError.offset, rewrites),
                                parseError.errorString(), line, column));
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
        return JsonTextWords::tr("out-of-range number %1").arg(*literal);
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

} // namespace phonglab
