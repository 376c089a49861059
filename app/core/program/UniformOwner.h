#pragma once
#include "core/program/ShaderBindings.h"

#include <QString>
#include <optional>

namespace phonglab {

// Who sets a uniform of the lighting program. The renderer sets its own
// uniforms on every frame, so a value typed for them would be overwritten
// at once: the Uniforms dock shows them read-only and says where to edit.
enum class UniformOwner {
    User,     // nobody else sets it: the dock edits it
    Renderer, // the matrices
    Scene,    // material, ambient and lights: the Material/Lights docks
};

// A uniform bound to a meaning (core/ShaderBindings.h) is set by the renderer
// (matrices, the eye) or the scene (material, ambient, lights); one bound to
// nothing is the user's.
UniformOwner uniformOwner(std::optional<BindingMeaning> meaning);
QString uniformOwnerNote(UniformOwner owner);

} // namespace phonglab
