#pragma once
#include "core/scene/Scene.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QString>
#include <QStringList>

#include <map>
#include <optional>
#include <vector>

namespace phonglab::cli {

// What the command line says over a scene's own words on the student's
// program, the one way render, check and grade (and grade's children) take
// it:
//   --bind NAME=MEANING   what a uniform or input means ("none": the user's own)
//   --bind NAME=1,0,0     a constant for a uniform the page sets (a mode switch)
//   --define NAME=VALUE   a token the page's JavaScript replaces before compiling
//   --precision RULE      highp (default) or as-written
struct SceneOverrides {
    ExplicitBindings bindings;
    std::map<QString, std::vector<double>> constants;
    PageDefines defines;
    std::optional<PrecisionRule> precision;

    // Name by name over the scene's "bindings", "uniforms" and "defines".
    void applyTo(Scene &scene) const;
    // The same words again, for a child process.
    QStringList arguments() const;
};

// The options, declared once with their help (helpLine()) for every command
// that takes them. --precision's help says what the command does with it:
// `check` and `grade` judge at highp and say apart what the declared
// precision changes; `render` draws.
struct SceneOverrideOptions {
    enum class Use {
        Draw,
        Check
    };
    explicit SceneOverrideOptions(Use use);
    QCommandLineOption bind;
    QCommandLineOption define;
    QCommandLineOption precision;

    QList<QCommandLineOption> all() const { return {bind, define, precision}; }
    // The options that may be given more than once.
    static QStringList repeatable() { return {QStringLiteral("bind"), QStringLiteral("define")}; }
};

// Reads them: empty, or the message for usage().
QString readSceneOverrides(const QCommandLineParser &parser, const SceneOverrideOptions &options,
                           SceneOverrides *out);

} // namespace phonglab::cli
