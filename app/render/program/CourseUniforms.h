#pragma once
#include "ShaderProgram.h"
#include "core/scene/Material.h"
#include "core/scene/Scene.h"

#include <glm/glm.hpp>
#include <span>

namespace phonglab {

// The meanings courses pass that mix two of the equation's values into one
// uniform (Angel & Shreiner's products Ia·ka, Id·kd, Is·ks; one colour for
// Id and Is, or for ka and kd) or move the light before the shader does (its
// position in camera coordinates). They depend on the object's material and
// on the lights drawn with it, so they are set per object, after the lights.
// A vec4 gets w = 1: a colour's alpha, a point's w.
void setCourseUniforms(ShaderProgram &program, const Scene &scene, std::span<const int> lights,
                       const Material &material, const glm::dmat4 &view);

} // namespace phonglab
