#pragma once
#include "core/program/ShaderBindings.h"

#include <QByteArray>

namespace phonglab {

// Where no name rule and no word of the user's decides what a uniform means,
// what the shader does with it does:
//  - the exponent of the specular `pow` is the shininess;
//  - an int that bounds the loop over the light arrays (`i < n`, or
//    `if (i >= n) break;` in WebGL 1) is the light count;
//  - a matrix's place in the gl_Position chain makes it the projection,
//    view or model matrix, or a product of neighbours: the chain multiplies
//    to projection · view · model, and the matrices the names decided fix
//    the others' places (two unknowns and nothing known: projection and
//    model-view, as the exercise's course code writes it);
//  - colours and gains that scale the ambient, diffuse (dot) or specular
//    (pow) term are its factors: one takes what the names leave missing
//    (I·k, I or k), the rest are 1 (`gain`); any split whose factors
//    multiply to Ia·ka, Id·kd or Is·ks is right (BindingsByTerm.cpp); what
//    scales all three terms scales the whole colour and stays the user's;
//  - a vector subtracted from the surface position is a light's position,
//    in world coordinates as the exercise gives it: a shader that forgets
//    to move it into camera coordinates is then told `light-space`, never
//    excused by the binding.
// Each binding says why ("the exponent of pow"), and where (stage, line):
// VariableBinding::byUse.

// Binds the variables of `bindings` that are bound to nothing and not by
// the user's word, by their use in the two stages' text; returns how many.
int bindByUse(ProgramBindings &bindings, const QByteArray &vertex, const QByteArray &fragment);

} // namespace phonglab
