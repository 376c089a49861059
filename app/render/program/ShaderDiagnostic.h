#pragma once
#include "core/program/ShaderStage.h"

#include <QString>
#include <vector>

namespace phonglab {

// The step of a build a message comes from: compiling one stage, or
// linking the two.
enum class BuildStep {
    CompileVertex,
    CompileFragment,
    Link
};

// Where the editor shows a message of `step`: its stage's tab; the
// fragment tab for link messages.
ShaderStage editorStage(BuildStep step);
QString stepName(BuildStep step); // "vertex", "fragment", "link"

// One compiler or linker message, located in the user's file: `line` and
// `column` are 1-based in the text the user wrote (0 = unknown), whatever
// the driver saw after any injected prologue.
struct ShaderDiagnostic {
    enum class Severity {
        Error,
        Warning
    };

    BuildStep step = BuildStep::CompileFragment;
    Severity severity = Severity::Error;
    QString file; // path or label of the user's source
    int line = 0;
    int column = 0;
    QString message;

    // "FILE:LINE:COL: error: MESSAGE" (LINE/COL left out when unknown).
    QString format() const;
    bool isError() const { return severity == Severity::Error; }
};

// Parses a driver info log into diagnostics. Understands Mesa
// ("0:12(5): error: ..."), NVIDIA ("0(12) : error C0000: ...") and the
// "ERROR: 0:12: ..." form of AMD/ANGLE. `prologueLines` is the number of lines
// the driver saw before the user's line 1 when no #line directive maps them
// back; lines that fall inside the prologue are reported as line 0.
std::vector<ShaderDiagnostic> parseShaderLog(const QString &log, BuildStep step,
                                             const QString &file, int prologueLines = 0);

// Mesa reports columns in its preprocessor's output, where every run of
// whitespace has become a single space. Maps such columns back onto the
// user's text (the line of `code` the diagnostic names); columns beyond the
// line are dropped. Lines are untouched.
void mapColumnsToSource(std::vector<ShaderDiagnostic> &diagnostics, const QByteArray &code);

// A missing ';' is found by the compiler at the next token, which is often
// the first of the next statement's line: "x = 1\n    y = 2;" is reported
// at the y. Where an error expecting a ';' sits on the first token of its
// line, this moves it to just past the end of the previous line with code,
// where the ';' belongs (as other editors point). Columns must already be
// the source's (mapColumnsToSource).
void pointAtMissingSemicolons(std::vector<ShaderDiagnostic> &diagnostics, const QByteArray &code);

} // namespace phonglab
