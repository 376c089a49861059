#pragma once
#include "core/check/MistakeSourceLines.h"
#include "core/scene/Scene.h"
#include "core/scene/ShadingMethod.h"
#include "render/check/ProgramFindings.h"
#include "render/draw/Renderer.h"
#include "render/program/BuildReport.h"

#include <QCommandLineParser>
#include <QImage>
#include <QString>
#include <optional>
#include <vector>

namespace phonglab::cli {

// The shader files a command draws a scene with, chosen the one way both
// `render` and `check` choose them. Each stage, first found: --vertex /
// --fragment, the scene's "shaders" (unless --shading chose a method), the
// shipped file of the shading method.
struct StageFiles {
    QString vertex;
    QString fragment;
};
StageFiles chooseStageFiles(const Scene &scene, const QString &vertexArg,
                            const QString &fragmentArg, bool methodChosen);

// --size, --shading, --vertex and --fragment, declared once with their help
// (helpLine()) for `render` and `check`; `grade` takes --size alone (each
// submission brings its own stages).
struct StageOptions {
    StageOptions();
    QCommandLineOption size;
    QCommandLineOption vertex;
    QCommandLineOption fragment;
    QCommandLineOption shading;

    QList<QCommandLineOption> all() const { return {size, vertex, fragment, shading}; }
};

// The largest side --size takes: `render` draws into a GL framebuffer alone;
// a check also holds the exact reference, a hit and doubles per pixel.
inline constexpr int kMaxRenderedSide = 16384;
inline constexpr int kMaxCheckedSide = 4096;

// --size and --shading, read the one way every command takes them.
// Each leaves its output alone when the option is not given and returns an
// empty string, or the message for usage() when the value is wrong.
QString readSizeOption(const QCommandLineParser &parser, const QCommandLineOption &option,
                       int maxSide, QSize *size);
QString readShadingOption(const QCommandLineParser &parser, const QCommandLineOption &option,
                          std::optional<ShadingMethod> *shading);

// unboundSentence() and how to bind it on the command line: "; if it is the
// light's position, add --bind uLight=light-position (or \"bindings\" in the
// scene)".
QString unboundMessage(const UnboundUniform &unbound);

// Reads both files and builds the program: its report, or (nothing built)
// why a file cannot be read. `texts` receives what was read.
Result<BuildReport> buildStages(Renderer &renderer, const StageFiles &files,
                                std::vector<ShaderStageText> *texts = nullptr);

} // namespace phonglab::cli
