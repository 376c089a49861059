#pragma once
#include "core/program/CoursePrelude.h"
#include "core/program/ShaderBindings.h"
#include "core/support/Result.h"
#include <QByteArray>
#include <QJsonDocument>
#include <QJsonValue>
#include <QString>
#include <map>
#include <optional>
#include <vector>

#include "NormalOptions.h"

// Internal to SceneJson*.cpp: the JSON-text layer under the scene reader.
namespace phonglab::scenejson {

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

// The "normals" field of an object: "auto" | "flat" | "average" | "area" |
// "angle", or {"method": <one of those>, "crease_deg": <0..180>}: `defaults`
// with what the field sets, or the failure "<path>: <reason>".
Result<NormalOptions> readNormalOptions(const QJsonValue &value, const QString &path,
                                        NormalOptions defaults);
QJsonValue normalOptionsJson(const NormalOptions &options);

// The "uniforms" field: {"name": number | [numbers (1..16)], ...}, values of
// the shader's own uniforms (none when the field is absent), or the failure
// "<path>.<name>: <reason>".
using UserUniforms = std::map<QString, std::vector<double>>;
Result<UserUniforms> readUserUniforms(const QJsonValue &value, const QString &path);
QJsonValue userUniformsJson(const std::map<QString, std::vector<double>> &uniforms);
// "bindings": {"uKd": "kd", "uGain": "none"} (core/ShaderBindings.h).
Result<ExplicitBindings> readBindings(const QJsonValue &value, const QString &path);
QJsonValue bindingsJson(const ExplicitBindings &bindings);
// "defines": {"NAME": "VALUE"} (a number is written as its text), and
// "precision": "highp" or "as-written" (core/program/CoursePrelude.h).
Result<PageDefines> readDefines(const QJsonValue &value, const QString &path);
QJsonValue definesJson(const PageDefines &defines);
Result<PrecisionRule> readPrecision(const QJsonValue &value, const QString &path);

} // namespace phonglab::scenejson
