#pragma once
#include "JsScanner.h"

#include <QString>
#include <optional>
#include <vector>

namespace phonglab {

// What JavaScript says about shaders: the strings that hold one, and the
// calls that make a program of two.

// A string expression whose value has `main` in it: one literal, literals
// joined by `+`, or an array of literals joined with `.join(...)`.
struct JsShaderText {
    QByteArray value;
    std::vector<qsizetype> from; // the offset in the scanned text of each byte of value
    // The variable or property it is assigned to (`const vsSource = ...`,
    // `vertexShader: ...`, `this.fs = ...`); empty where there is none.
    QString name;
    qsizetype begin = 0; // the expression's bytes in the scanned text
    qsizetype end = 0;
    int pieces = 0; // literals it is made of
    char quote = 0; // the one literal's quote: ' " or `
};
std::vector<JsShaderText> shaderTextsInJs(std::string_view js);

// How a call names a shader: an element id or file name (a string), a
// variable, or a literal written right into the call (by its offset).
struct JsShaderRef {
    QString name;
    std::optional<qsizetype> literalAt;
};

// Two shaders a call makes a program of: initShaders(gl, "vs", "fs"),
// initShaderProgram(gl, vsSource, fsSource), createProgram(gl, vs, fs),
// createProgramFromScripts / createProgramFromSources(gl, [vs, fs]),
// new THREE.ShaderMaterial({vertexShader, fragmentShader}). A variable that
// holds a compiled shader (`vs = createShader(gl, type, source)`) is
// followed to its source.
struct JsProgramCall {
    JsShaderRef vertex;
    JsShaderRef fragment;
};
std::vector<JsProgramCall> programCallsInJs(std::string_view js);

} // namespace phonglab
