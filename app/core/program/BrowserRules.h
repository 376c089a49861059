#pragma once
#include "core/program/ShaderStage.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <vector>

namespace phonglab {

// What a desktop browser's WebGL does to a shader before its GPU sees it,
// done to the text here so that a student's shader draws the pixels their
// browser drew. Chromium hands WebGL shaders to ANGLE with
// initializeUninitializedLocals and initOutputVariables on:
//  - every local and global variable declared without a value starts at
//    zero (arrays element by element, structs member by member), also each
//    time a loop body declares it again;
//  - every output of the stage (`out` variables, ES 1.00's `varying`s in
//    the vertex shader, gl_Position, gl_FragColor) starts main() at zero,
//    so a component or a path that never writes it reads 0.
// GLSL leaves all of these undefined; Mesa keeps whatever the register held.
// The lint's warning (ShaderLint) still says so: another GPU may not zero.
// The precision half of the browser's rules is CoursePrelude's.
//
// Every insertion stays on the line it belongs to, so the compiler's lines
// are the student's; `sourceColumn` takes a column back past what was
// inserted before it.
struct SourceInsertion {
    qsizetype offset = 0; // in the source's bytes: the text goes before this byte
    int line = 0;         // 1-based, of the source
    int column = 0;       // 1-based, in characters, of the source
    QByteArray text;
};

struct BrowserRewrite {
    QByteArray code;                         // the source with every insertion made
    std::vector<SourceInsertion> insertions; // in the order of the source
    QStringList zeroed;                      // the names started at zero, in order

    // The column of the source for `column` of the rewritten `line`; a
    // column inside an insertion is the place it was inserted at.
    int sourceColumn(int line, int column) const;
};

BrowserRewrite applyBrowserRules(const QByteArray &code, ShaderStage stage);

} // namespace phonglab
