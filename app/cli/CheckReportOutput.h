#pragma once
#include "core/MistakeSourceLines.h"
#include "core/Scene.h"
#include "core/ShaderCheck.h"
#include "render/ShaderDiagnostic.h"

#include <QJsonObject>
#include <QString>
#include <vector>

namespace phonglab::cli {

// How `phonglab check` reports, for people (text) and for scripts (--json).
// The JSON keys are an interface: verdict, psnr_db, max_error, bad_fraction,
// worst {x, y, object}, diagnosis [{key, also, confidence, message, lines
// [{file, line, text}]}], undetectable, errors [{file, line, column,
// message}], bindings {name: meaning or "none"}, equation ("guarded",
// "slide", null on error), notes [text]. Never renamed; new keys may be added.

struct CheckOutcome {
    enum class Verdict {
        Pass,
        Fail,
        Error
    };
    Verdict verdict = Verdict::Error;
    CheckReport report;                   // Pass and Fail
    std::vector<ShaderDiagnostic> errors; // Error: compile errors, or one for bad input
    std::vector<ShaderStageText> stages;  // the user's sources, for the diagnosis' lines
    ProgramBindings bindings;             // what each of the program's names was bound to
    QStringList notes;                    // what the verdict rests on that the user should know
    QStringList warnings; // the scene file's: a key ignored, a format-1 "flat" read as "faceted"
};

QJsonObject checkJson(const CheckOutcome &outcome);
QString checkText(const CheckOutcome &outcome, const Scene &scene);

} // namespace phonglab::cli
