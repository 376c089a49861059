#pragma once
#include "core/scene/ShadingMethod.h"
#include "core/support/Result.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

namespace phonglab {

// A shader stage's text as the user wrote it, with the name diagnostics
// report it under (a file path, or a label such as ":/shaders/phong.frag").
struct ShaderSource {
    QString name;
    QByteArray code;

    bool operator==(const ShaderSource &) const = default;
    // The file's text, or why it cannot be read ("PATH: cannot read shader: ...").
    // A "FILE#KEY" locator (core/project) gives the shader in that page or
    // script, laid out so its lines are the file's, named by the file.
    static Result<ShaderSource> fromFile(const QString &path);
    // What an editor shows: the same, but a locator's shader as written
    // (no layout), named by the locator.
    static Result<ShaderSource> forEditing(const QString &path);
};

// A program's two stages.
struct StageSources {
    ShaderSource vertex;
    ShaderSource fragment;

    bool operator==(const StageSources &) const = default;
};
// Both files read, or the first one's failure.
Result<StageSources> readStageFiles(const QString &vertexPath, const QString &fragmentPath);
// The shaders PhongLab ships for `method` (shippedShaderPath).
Result<StageSources> readShippedStages(ShadingMethod method);

// The text handed to the driver: the user's #version line first (GLSL needs
// it there), then the injected `#define`s, then `#line` so that every line
// after it is numbered exactly as in the user's file. Without a #version line
// the prologue goes first and `#line 1` follows it. A shader with no #version
// line at all is GLSL ES 1.00 (WebGL 1): `#version 100` is put before it.
// `prelude` (whole lines: what the course's page adds, core/program/CoursePrelude)
// goes before the `#define`s.
QByteArray withPrologue(const QByteArray &code, const QStringList &defines,
                        const QByteArray &prelude = {});

} // namespace phonglab
