#pragma once
#include "PageCapture.h"
#include "core/project/ProjectPrograms.h"

#include <QByteArray>
#include <QString>

#include <map>
#include <optional>
#include <vector>

namespace phonglab {

// The program of a captured frame that a check of the course scene takes
// (phonglab check SCENE --page): the one drawn that lights (it binds a
// light, a material product or a shininess), drawing the most vertices,
// with the values the page gave the uniforms no meaning binds (a mode
// switch) and its stages' texts as the browser compiled them.
struct PageProgram {
    const CapturedProgram *program = nullptr;
    const CapturedOp *draw = nullptr; // its largest draw in the frame
    // NAME -> value for every uniform bound to no meaning: the page's
    // switches and constants, as --bind NAME=VALUE would give them.
    std::map<QString, std::vector<double>> constants;
};

// nullopt when the frame draws no program that lights.
std::optional<PageProgram> litPageProgram(const PageCapture &capture);

// Where a compiled stage's text is in the project as written: "FILE#KEY"
// (core/project/ProjectShader) when the page compiled one of its shaders
// unchanged, so that every line a check names is the student's; empty
// when the page rewrote it (a token replaced, a prelude added).
QString stageLocatorInProject(const Project &project, ShaderStage stage, const QString &compiled);
// The same shader itself (its file and first line), or null.
const ProjectShader *stageInProject(const Project &project, ShaderStage stage,
                                    const QString &compiled);

} // namespace phonglab
