#pragma once
#include "JsScanner.h"

#include <QString>
#include <optional>
#include <vector>

namespace phonglab {

// What JavaScript says about shaders: the strings that hold one, and the
// calls that make a program of two.

// A string expression whose value has `main` in it: one literal, literals
// joined by `+`, or an array of literals joined with `.join(...)`. What the
// page computes in between is a token it replaces: a JavaScript expression
// between two pieces (`'lights[' + this.num_lights + '];'`) and a template
// literal's ${...} stand in the value as a placeholder name (below), which
// --define NAME=VALUE or the scene's "defines" give a value, as for any
// token a page replaces. Each placeholder byte comes from the expression's
// first byte.
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

// The placeholder for an expression's value: the last name it reads, in
// upper case with camelCase words split by `_` (`this.num_lights` and
// `this.numLights` are NUM_LIGHTS, `n` is N). Not counted: what it reads
// through or converts with (this, window, self, globalThis, String, Number,
// parseInt, parseFloat, toString, toFixed, Math, round, floor); a last
// `length` or `size` keeps the name before it (`lights.length` is
// LIGHTS_LENGTH). Made a name GLSL takes: runs of `_` and those at the ends
// dropped, JS_ before a digit or GL_, at most 64 characters; JS_VALUE where
// no name is left. In a shader's text, where it is the value of a `#define`
// of the same name (`"#define N " + n`), `_VALUE` follows it (N_VALUE):
// `#define N N` would clash with the --define N=... that gives it.
QByteArray jsPlaceholderName(std::string_view expression);

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
