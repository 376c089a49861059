#pragma once
#include "core/program/ShaderBindings.h"
#include "core/scene/Scene.h"

#include <QStringList>

namespace phonglab {

// A uniform bound to one colour for two of the equation's values
// (light-color: Id and Is; material-color: ka and kd) can hold the scene
// only where the scene gives both the same value. Where it does not, the
// program cannot draw the scene, and no verdict may rest on it: one
// sentence per uniform and light or object, naming both values.
QStringList bindingConflicts(const ProgramBindings &bindings, const Scene &scene);

} // namespace phonglab
