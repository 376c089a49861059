#include "CourseUniforms.h"

#include <array>
#include <vector>

namespace phonglab {

void setCourseUniforms(ShaderProgram &program, const Scene &scene, std::span<const int> lights,
                       const Material &material, const glm::dmat4 &view)
{
    using M = BindingMeaning;
    std::vector<glm::dvec3> diffuseProduct, specularProduct, color, cameraPosition;
    for (int i : lights) {
        const PointLight &l = scene.lights[std::size_t(i)];
        diffuseProduct.push_back(l.diffuse * material.kd);
        specularProduct.push_back(l.specular * material.ks);
        // Where Id and Is differ no colour is right: bindingConflicts() says
        // so before anything is checked.
        color.push_back(l.diffuse);
        cameraPosition.push_back(glm::dvec3(view * glm::dvec4(l.position, 1.0)));
    }
    program.setVector(M::AmbientProduct, scene.ambient * material.ka);
    program.setVector(M::MaterialColor, material.kd);
    program.setPerLight(M::DiffuseProduct, diffuseProduct);
    program.setPerLight(M::SpecularProduct, specularProduct);
    program.setPerLight(M::LightColor, color);
    program.setPerLight(M::LightPositionCamera, cameraPosition, 1.0);
    // The terms' parts in one uniform: a mat3's columns, or a vec3[3].
    glm::dvec3 id(0.0);
    glm::dvec3 is(0.0);
    if (!lights.empty()) {
        id = scene.lights[std::size_t(lights.front())].diffuse;
        is = scene.lights[std::size_t(lights.front())].specular;
    }
    const std::array<glm::dvec3, 3> light = {scene.ambient, id, is};
    const std::array<glm::dvec3, 3> coefficients = {material.ka, material.kd, material.ks};
    program.setMatrix(M::LightTerms, glm::dmat3(light[0], light[1], light[2]));
    program.setPerLight(M::LightTerms, light);
    program.setMatrix(M::MaterialTerms,
                      glm::dmat3(coefficients[0], coefficients[1], coefficients[2]));
    program.setPerLight(M::MaterialTerms, coefficients);
}

} // namespace phonglab
