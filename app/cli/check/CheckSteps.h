#pragma once
#include "core/check/ShaderCheck.h"
#include "core/reference/PhongEquation.h"
#include "core/scene/MeshData.h"
#include "core/scene/Scene.h"
#include "core/scene/SceneJson.h"
#include "render/check/CheckReportOutput.h"
#include "render/program/ShaderDiagnostic.h"

#include <QImage>
#include <QJsonObject>
#include <QSize>
#include <QString>

#include <memory>
#include <optional>
#include <vector>

namespace phonglab::cli {

// A check in its two steps. Drawing needs the GPU and runs the student's
// code; checking needs only the exact reference and the drawn pixels.
// `check` takes both in one process. `grade` draws in a child process per
// submission (a shader may hang the driver or eat memory) and checks in its
// own, against one reference per scene: the same functions, so the same
// verdict.

// What a check draws: the scene and the shader files it is drawn with.
struct CheckInput {
    QString scenePath;
    QString vertexPath;        // empty: the scene's, else the method's shipped one
    QString fragmentPath;      // likewise
    bool methodChosen = false; // --shading named the method: its shipped files win over the scene's
    QSize size{800, 600};
};

struct CheckDrawing {
    // errors, stages, bindings and notes; no verdict (nothing checked yet).
    // Errors, when there are any, end the check.
    CheckFindings findings;
    std::optional<int> lightCapacity;               // ProgramBindings::lightCapacity()
    QImage image;                                   // the render; null where there are errors
    std::vector<ShaderDiagnostic> compilerMessages; // errors and warnings, for stderr
    std::vector<std::shared_ptr<const MeshData>>
        objectMeshes; // per scene object, for the reference

    bool drawn() const { return findings.errors.empty() && !image.isNull(); }
};

// Loads the meshes, builds the program, binds it and draws `scene` (already
// loaded from input.scenePath, with any --shading and --bind applied).
CheckDrawing drawForCheck(const CheckInput &input, const Scene &scene);

// The scene as far as a program with `lightCapacity` lights can light it
// (sceneForCapacity()): what the reference is made of.
Scene sceneForCheck(const Scene &scene, std::optional<int> lightCapacity);

// Checks a drawn image: sets the findings' report and returns the verdict;
// Error, with an error added, when no pixel could be compared.
Verdict checkDrawing(CheckFindings *findings, const QImage &image, const CheckReference &reference,
                     int toleranceSteps, std::optional<PhongEquation> equation,
                     const QString &scenePath);

// An error not from the compiler: bad input, no GL, a file not read.
ShaderDiagnostic inputError(const QString &file, const QString &message);
// The build's warnings (the compiler's, what the page's prelude added, and
// what the image cannot show), each "FILE:LINE:COL: warning: MESSAGE", for
// the check's `warnings`.
QStringList buildWarnings(const std::vector<ShaderDiagnostic> &compilerMessages);
// The scene file's error, at its line and column where the JSON text has
// one (a syntax error).
ShaderDiagnostic sceneError(const QString &path, const SceneLoadResult &loaded);

// The drawing as `grade`'s child hands it to its parent (stdout, one JSON
// object), and read back. The image travels as a PNG file beside it.
QJsonObject drawingJson(const CheckDrawing &drawing);
CheckDrawing drawingFromJson(const QJsonObject &json);

} // namespace phonglab::cli
