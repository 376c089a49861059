#pragma once
#include "PageCapture.h"
#include "core/program/ShaderBindings.h"

#include <glm/mat4x4.hpp>

#include <optional>

namespace phonglab {

// What a captured draw's uniforms and attributes mean, found as for a
// static check (core/program/ShaderBindings: by name and type, or by the
// user's word).
ProgramBindings drawBindings(const CapturedOp &draw, const ExplicitBindings &explicitBindings = {});

// The first variable bound to `meaning`, or null.
const CapturedUniform *uniformMeaning(const CapturedOp &draw, const ProgramBindings &bindings,
                                      BindingMeaning meaning);
const CapturedAttribute *attributeMeaning(const CapturedOp &draw, const ProgramBindings &bindings,
                                          BindingMeaning meaning);

// A mat3 or mat4 uniform's first element as a 4x4 matrix (a mat3 in the
// upper left); nullopt for any other type.
std::optional<glm::dmat4> uniformMatrix(const CapturedUniform &uniform);

} // namespace phonglab
