#pragma once
#include "CheckReportOutput.h"
#include "core/program/ShaderBindings.h"
#include "core/scene/Scene.h"
#include "render/draw/OffscreenRenderer.h"
#include "render/program/ShaderProgram.h"
#include "render/program/UniformSnapshot.h"

#include <QImage>
#include <QSize>
#include <QString>
#include <QStringList>
#include <optional>
#include <vector>

namespace phonglab {

// What a built program says before any pixel is compared, found the one way
// for `phonglab check`, `grade` and the window's live check, so that they
// give the same verdict: what each name was bound to, what nothing could
// place, how many lights the program takes. Where something cannot be
// placed there is no verdict: the student's names are PhongLab's gap, never
// the student's mistake.

// A uniform of the built program that PhongLab binds to nothing and that
// nobody gives a value (no scene "uniforms" entry, no initialiser, nothing
// typed in the Uniforms dock): the shader reads zero.
struct UnboundUniform {
    QString name;
    GlslType type = GlslType::Other;
    std::optional<BindingMeaning> likely; // likelyMeaning(): what its name or type suggests
};
std::vector<UnboundUniform> unboundUniforms(ShaderProgram &program, const Scene &scene);
// The 1-based line of `text` that declares uniform `name`, or 0: where
// `check` and the editor say an unbound uniform is.
int uniformDeclarationLine(const QString &text, const QString &name);
// "uniform uZork (vec3) is bound to nothing, so the shader reads zero": what
// each front end follows with how to bind it there.
QString unboundSentence(const UnboundUniform &unbound);

struct ProgramFindings {
    ProgramBindings bindings;         // its notes too: what the verdict rests on
    std::optional<int> lightCapacity; // ProgramBindings::lightCapacity()
    QStringList problems;             // an explicit binding that names nothing here
    std::vector<UnboundUniform> unbound;
    QStringList
        conflicts; // two names for one meaning, a value the scene cannot give: bindingConflicts()
    Scene checked; // what the program can light of the scene: sceneForCapacity()
    QString lightsNote; // which lights were left out of `checked`, or empty

    bool placesEverything() const
    {
        return problems.isEmpty() && unbound.empty() && conflicts.isEmpty();
    }
};
ProgramFindings findProgramFindings(ShaderProgram &program, const Scene &scene);

// "aPosition=position, uModel=model, uGain=none" for a person; empty where
// every variable has PhongLab's own name (nothing worth saying).
QString bindingsText(const ProgramBindings &bindings);
// One line per variable bound by its use (core/program/BindingsByUse):
// "shininessVal=shininess: the exponent of pow (fragment shader, line 41)".
QStringList bindingsByUseText(const ProgramBindings &bindings);

// The scene as far as the program can light it: where it takes fewer lights
// (ProgramBindings::lightCapacity(): a single light uniform, a short array)
// than the scene has enabled, the first ones it takes. `note` says what was
// left out, or stays empty.
Scene sceneForCapacity(const Scene &scene, std::optional<int> lightCapacity, QString *note);

// The lower precisions the stages declare and, where they were checked at
// highp, how far the render as written is from the one checked: drawn again
// with the declared precision (a second build and draw, only for shaders
// that declare mediump or lowp). Leaves `offscreen` with the program as
// written where it built it. `stages`: the texts the first build read;
// `values`: the user's own uniforms' values where the window has them.
PrecisionFinding measurePrecision(OffscreenRenderer &offscreen,
                                  const std::vector<ShaderStageText> &stages, const Scene &checked,
                                  QSize size, const QImage &checkedImage,
                                  const UniformSnapshot *values = nullptr);
// What measurePrecision() finds without drawing: the lower precisions
// declared and the rule they were checked by.
PrecisionFinding declaredPrecision(const std::vector<ShaderStageText> &stages,
                                   const Scene &checked);

} // namespace phonglab
