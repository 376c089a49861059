#pragma once
#include "core/program/ShaderStage.h"
#include "core/support/Result.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <vector>

namespace phonglab {

// A shader as a WebGL project holds it: in a <script> or <textarea> of an
// HTML page, in a JavaScript string (a template literal, a concatenation,
// an array joined), or in a file of its own.

// What holds a shader's text in its file, which decides how it is written
// back (ProjectSave).
enum class ShaderContainer {
    File,          // a file of its own: the text as it is
    ScriptElement, // <script type="x-shader/...">: raw text
    Textarea,      // <textarea>: & and < as references
    JsTemplate,    // `...`: \ ` and ${ escaped
    JsString,      // '...' or "...": \, the quote and line ends escaped
    JsPieces,      // strings joined by + or an array joined: never written back
};

struct ProjectShader {
    QString file; // the file it is in, as found
    // What names it in its file: the element's id, the variable or property
    // holding it, a file's name; "line N" where nothing names it.
    QString key;
    ShaderStage stage = ShaderStage::Vertex;
    QByteArray text; // as written, the way the page hands it to WebGL
    // Its text laid out as in the file: blank lines before it and spaces
    // before each line's first character, so that every line and column a
    // compiler or the check reports is the file's (index.html:57:12).
    // Whitespace only is added, and only between lines.
    QByteArray code;
    int line = 0; // the file's line its text starts on
    // The file's bytes [begin, end) hold the text (inside a literal's
    // quotes), escaped as its container escapes it.
    qsizetype begin = 0;
    qsizetype end = 0;
    ShaderContainer container = ShaderContainer::File;
    char quote = 0; // a JavaScript string's quote
    // Writing the text back as its container escapes it gives the file's
    // very bytes: Save can replace it there and leave every other byte.
    bool writable = false;
    QString notWritable; // why not, in a sentence
};

// "FILE#KEY": how a project's shader is named where a file path is
// expected (check's and grade's stage paths).
QString shaderLocator(const ProjectShader &shader);
// The shader a locator names, read again from its file; an error names the
// file and the key. `isShaderLocator` is false for a path that exists as
// it is (a file whose name holds '#').
bool isShaderLocator(const QString &path);
Result<ProjectShader> shaderAtLocator(const QString &locator);

// A page (.html .htm .xhtml) and a script (.js .mjs .cjs) by their names'
// suffixes, in any case: with shader files (core/program/ShaderStage), the
// files a project's shaders are read from.
bool isPageFile(const QString &path);
bool isScriptFile(const QString &path);

// Every shader in one file: a page, a script, or a shader file of its own
// (shaderFileSuffixes()). Texts without `main` or whose
// stage cannot be told are left out.
std::vector<ProjectShader> shadersInFile(const QString &path);
// The same for a file's bytes already read (`path` names it and its kind).
std::vector<ProjectShader> shadersInText(const QString &path, const QByteArray &file);
// The stage a text's content gives: gl_Position writes a vertex shader,
// gl_FragColor, gl_FragData or an `out vec4` a fragment shader.
std::optional<ShaderStage> stageOfShaderText(const QByteArray &text);

} // namespace phonglab
