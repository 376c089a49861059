#pragma once
#include "core/scene/Scene.h"

// Scenes for the shader-mistake tests.
namespace phonglab::test {

// A sphere scaled by `scale` and moved off the origin, seen from the default
// camera (on +Z at distance 4), lit from the front with attenuation and from
// behind, almost opposite the eye (near the rim the surface faces away from
// that light while R·V > 0: where backface-specular shows). Under the
// default non-uniform scale every mistake but gouraud shows.
inline Scene mistakeScene(const glm::dvec3 &scale = {1.2, 0.7, 0.9})
{
    SceneObject o;
    o.mesh = QStringLiteral("builtin:sphere");
    o.transform.scale = scale;
    o.transform.translate = {0.2, -0.1, 0.0};
    o.material.ka = {0.2, 0.2, 0.2};
    o.material.kd = {0.6, 0.5, 0.4};
    o.material.ks = {0.5, 0.5, 0.5};
    o.material.shininess = 20.0;
    Scene scene;
    scene.objects.push_back(o);
    PointLight front;
    front.position = {3.0, 4.0, 5.0};
    front.attenuation = {1.0, 0.05, 0.0};
    scene.lights.push_back(front);
    PointLight back;
    back.position = {-1.0, 1.5, -6.0};
    scene.lights.push_back(back);
    return scene;
}

} // namespace phonglab::test
