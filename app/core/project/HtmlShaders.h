#pragma once
#include "JsShaders.h"
#include "ProjectShader.h"

#include <QByteArray>
#include <QString>
#include <vector>

namespace phonglab {

// Where shaders sit in a page and its scripts, read with a
// real HTML5 parser (gumbo): <script> elements of any type and id, hidden
// <textarea>s, and the JavaScript of inline scripts.

// A text that may be a shader, before its stage is told.
struct FoundText {
    QByteArray value;
    std::vector<qsizetype> from; // the file's offset of each byte of value
    QString name;                // an id, a variable, a property; empty: none
    qsizetype begin = 0;         // the file's bytes that hold it
    qsizetype end = 0;
    ShaderContainer container = ShaderContainer::File;
    char quote = 0; // a JavaScript literal's
};

std::vector<FoundText> shaderTextsInHtml(const QByteArray &html);
// In JavaScript that starts at `base` in its file.
std::vector<FoundText> foundInJs(const QByteArray &js, qsizetype base);
// Whether a file is JavaScript that holds a shader in a string: a quoted or
// template string whose value has `main` and a stage's output. GLSL has no
// strings, so a shader file (phong.vert) that does is a script in disguise
// (`var phongVS = `...`;`, loaded by <script src="phong.vert">).
bool holdsShaderStrings(const QByteArray &file);
// The program calls of a page's inline scripts or a script file; literal
// offsets are the file's.
std::vector<JsProgramCall> programCallsInFile(const QString &path);

} // namespace phonglab
