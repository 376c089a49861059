#pragma once
#include "core/check/MistakeSourceLines.h"
#include "core/check/ShaderCheck.h"
#include "core/check/Verdict.h"
#include "core/scene/Scene.h"
#include "render/program/ShaderDiagnostic.h"

#include <QJsonObject>
#include <QString>
#include <optional>
#include <vector>

namespace phonglab {

// How `phonglab check` reports, for people (text) and for scripts (--json).
// The JSON keys are an interface: verdict, psnr_db, max_error, bad_fraction,
// worst {x, y, object}, unchecked_terms [{term, why}], diagnosis [{key, also, confidence, from_code,
// message, lines [{file, line, text}]}], undetectable, errors [{file, line,
// column, message}], bindings {name: meaning or "none"}, bindings_by_use
// {name: {meaning, reason, stage, line}}, equation ("guarded", "slide", null
// on error), notes [text], warnings [text], together {keys, explains, forms,
// lines [{key, file, line, text}], beyond_limit} (null unless it fails and
// the set explains at least kExplainedConfidence), partial (the same shape:
// the closest set where it explains less), precision {checked, declared,
// as_written_max_error, as_written_psnr_db, as_written_error}.
// Never renamed; new keys may be added.

// How precision was checked, and what the declared one would change: a
// finding, never a verdict (a desktop browser computes floats at 32 bits).
struct PrecisionFinding {
    PrecisionRule checkedAt = PrecisionRule::Highp;
    QStringList declared; // the lower precisions the shaders declare: "mediump", "lowp"
    // Checked at highp with a lower precision declared: the render as
    // written against the one checked, on this driver.
    std::optional<int> asWrittenMaxError;
    double asWrittenPsnr = 0.0;
    // Or why the program as written does not build there (a uniform both
    // stages declare, at two precisions, does not link in a browser either).
    QString asWrittenError;
};

// What a check found, its verdict aside: a drawing not checked yet has
// none, and a row of `grade` has its own (GradeRow).
struct CheckFindings {
    CheckReport report;                   // when it passed or failed
    std::vector<ShaderDiagnostic> errors; // compile errors, or one for bad input
    std::vector<ShaderStageText> stages;  // the user's sources, for the diagnosis' lines
    ProgramBindings bindings;             // what each of the program's names was bound to
    QStringList notes;                    // what the verdict rests on that the user should know
    QStringList warnings; // the scene file's: a key ignored, a format-1 "flat" read as "faceted"
    PrecisionFinding precision;
};

// `check`'s: the findings and their verdict.
struct CheckOutcome : CheckFindings {
    Verdict verdict = Verdict::Error; // Pass, Fail or Error
};

QJsonObject checkJson(Verdict verdict, const CheckFindings &findings);
// `precision`, and read back (grade's child hands it to its parent).
QJsonObject precisionJson(const PrecisionFinding &precision);
PrecisionFinding precisionFromJson(const QJsonObject &json);
// "precision: mediump checked at highp ...", or empty where none is declared.
QString precisionText(const PrecisionFinding &precision);
QString checkText(const CheckOutcome &outcome, const Scene &scene);

} // namespace phonglab
