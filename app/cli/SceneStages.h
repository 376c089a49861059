#pragma once
#include "core/MistakeSourceLines.h"
#include "core/Scene.h"
#include "core/ShadingMethod.h"
#include "render/BuildReport.h"
#include "render/Renderer.h"

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

// --size and --shading, read the one way `render` and `check` take them.
// Each leaves its output alone when the option is not given and returns an
// empty string, or the message for usage() when the value is wrong.
QString readSizeOption(const QCommandLineParser &parser, const QCommandLineOption &option,
                       int maxSide, QSize *size);
QString readShadingOption(const QCommandLineParser &parser, const QCommandLineOption &option,
                          std::optional<ShadingMethod> *shading);

// Reads both files and builds the program: its report, or (nothing built)
// why a file cannot be read. `texts` receives what was read.
Result<BuildReport> buildStages(Renderer &renderer, const StageFiles &files,
                                std::vector<ShaderStageText> *texts = nullptr);

// Writes a PNG that appears only once complete.
Result<> writePng(const QImage &image, const QString &path);

} // namespace phonglab::cli
