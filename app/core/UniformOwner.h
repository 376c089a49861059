#pragma once
#include <QString>

namespace phonglab {

// Who sets a uniform of the lighting program. The renderer sets its own
// uniforms on every frame, so a value typed for them would be overwritten
// at once: the Uniforms dock shows them read-only and says where to edit.
enum class UniformOwner {
    User,     // nobody else sets it: the dock edits it
    Renderer, // the matrices
    Scene,    // material, ambient and lights: the Material/Lights docks
};

// `name` without an element index ("Id", not "Id[2]").
UniformOwner uniformOwner(const QString &name);
QString uniformOwnerNote(UniformOwner owner);

} // namespace phonglab
