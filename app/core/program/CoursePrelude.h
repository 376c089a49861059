#pragma once
#include "core/program/ShaderStage.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <map>
#include <optional>

namespace phonglab {

// What a course's web page does to a shader before the browser compiles it,
// done the same way before the driver here compiles it, so that a student's
// file is checked as their page runs it:
//  - precision: a desktop browser computes every float in 32 bits, whatever
//    the shader declares; Mesa computes `mediump` in 16. By default PhongLab
//    checks at highp too (`#define mediump highp`, `#define lowp highp`) and
//    says so; "as-written" leaves the driver the declared precision.
//  - three.js's ShaderMaterial declares modelViewMatrix, projectionMatrix,
//    normalMatrix, viewMatrix, modelMatrix, cameraPosition, position and
//    normal itself: a source that uses them undeclared gets those
//    declarations, as three.js prepends them.
//  - a GLSL ES fragment shader with no default float precision gets
//    `precision highp float;`, as the page's JavaScript adds it.
//  - tokens the JavaScript replaces before compiling (NUM_POINT_LIGHTS)
//    come from --define NAME=VALUE and the scene's "defines".
// All of it goes before `#line`, so every message stays on the student's own
// lines (ShaderSource's prologue).

enum class PrecisionRule {
    Highp,     // "highp": every float at 32 bits, as a desktop browser computes it
    AsWritten, // "as-written": the declared precision, as this driver honours it
};
QString precisionRuleKey(PrecisionRule rule);
std::optional<PrecisionRule> precisionRuleFromKey(const QString &key);

// NAME -> VALUE, each becoming `#define NAME VALUE`.
using PageDefines = std::map<QString, QString>;

struct CourseOptions {
    PrecisionRule precision = PrecisionRule::Highp;
    PageDefines defines;

    bool operator==(const CourseOptions &) const = default;
};

// "NAME=VALUE" read (VALUE may be empty: `#define NAME`), or why not.
struct ParsedDefine {
    QString name;
    QString value;
};
std::optional<ParsedDefine> parseDefineArgument(const QString &text, QString *error);

struct CoursePrelude {
    QByteArray text; // whole lines, to go between #version and #line
    // Said to the user as warnings of the stage: what was added and why.
    QStringList added;
    // The lower precisions the source declares ("mediump", "lowp"), in order.
    QStringList lowerPrecisions;
    bool usesThreeJs = false;
};

// The prelude for one stage of `code` (the student's text).
CoursePrelude coursePreludeFor(const QByteArray &code, ShaderStage stage,
                               const CourseOptions &options);

// For a compiler message about an identifier the source never defines
// ("undefined macro NUM_POINT_LIGHTS", "`NUM_LIGHTS' undeclared"): the same
// message with what to do about a token the page replaces, when the name
// looks like one (upper case); else the message unchanged.
QString explainUndefinedToken(const QString &message, const PageDefines &defines);

} // namespace phonglab
