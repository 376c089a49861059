#pragma once
#include "core/Result.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <vector>

namespace phonglab {

// A shader as a WebGL project holds it: in a <script> or <textarea> of an
// HTML page, in a JavaScript string (a template literal, a concatenation,
// an array joined), or in a file of its own (issue 42, A).

enum class ProjectStage {
    Vertex,
    Fragment
};

struct ProjectShader {
    QString file; // the file it is in, as found
    // What names it in its file: the element's id, the variable or property
    // holding it, a file's name; "line N" where nothing names it.
    QString key;
    ProjectStage stage = ProjectStage::Vertex;
    // Its text laid out as in the file: blank lines before it and spaces
    // before each line's first character, so that every line and column a
    // compiler or the check reports is the file's (index.html:57:12).
    // Whitespace only is added, and only between lines.
    QByteArray code;
    int line = 0; // the file's line its text starts on
    // The file's bytes [begin, end) are exactly the shader's text (a script
    // or textarea without character references, a literal without
    // escapes): Save can write it back there.
    qsizetype begin = 0;
    qsizetype end = 0;
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

// Every shader in one file: .html/.htm, .js/.mjs, or a shader file of its
// own (.vert .frag .vs .fs .vsh .fsh .glsl). Texts without `main` or whose
// stage cannot be told are left out.
std::vector<ProjectShader> shadersInFile(const QString &path);
// The stage a text's content gives: gl_Position writes a vertex shader,
// gl_FragColor, gl_FragData or an `out vec4` a fragment shader.
std::optional<ProjectStage> stageOfShaderText(const QByteArray &text);

} // namespace phonglab
