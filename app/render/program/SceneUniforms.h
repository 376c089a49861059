#pragma once
#include "UniformSnapshot.h"
#include "core/program/ShaderBindings.h"

#include <QString>
#include <map>
#include <vector>

namespace phonglab {

// The values of a program's uniforms that only the user sets (the Uniforms
// dock's editable rows, core/UniformOwner) and that a scene file can hold:
// scalars, vectors and matrices of float, int, uint and bool, not samplers
// (whose values are texture units). A scene saved with them reopens with
// them (Scene::uniforms).
// `bindings` tells which uniforms PhongLab sets (core/ShaderBindings.h).
std::map<QString, std::vector<double>> userUniformValues(const UniformSnapshot &snapshot,
                                                         const ProgramBindings &bindings);

} // namespace phonglab
