#pragma once
#include "Result.h"
#include <QByteArray>
#include <QJsonDocument>
#include <QJsonValue>
#include <QString>
#include <optional>

// The JSON-text layer under every reader of a JSON file the user writes
// (scenes, camera paths): Qt's parser, with out-of-range numbers and syntax
// errors located.
namespace phonglab {

// QJsonDocument::fromJson rejects a number literal that overflows a double
// (1e999) as a syntax error at a byte offset, which would hide which field it
// was in. parseJsonText rewrites such literals into marker values so the
// scene reader can refuse them with the field's path instead; literals that
// underflow (1e-999) read as 0, the nearest double.
//
// On a genuine syntax error fails with
// "JSON syntax error at line L, column C (byte offset N): <Qt's reason>",
// positions counted in the caller's original text; `line` and `column`
// (1-based) are set too where given.
Result<QJsonDocument> parseJsonText(const QByteArray &json, int *line = nullptr,
                                    int *column = nullptr);

// The literal as written ("1e999") if `value` is an overflow marker.
std::optional<QString> overflowLiteral(const QJsonValue &value);

// "number", "string", ... for messages like "expected an array (got string)".
QString describeType(const QJsonValue &value);

} // namespace phonglab
