#pragma once
#include "core/program/CoursePrelude.h"
#include "core/program/ShaderBindings.h"
#include "core/support/JsonText.h"
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
