#pragma once
#include "AnalyticRaycaster.h"
#include "Material.h"
#include "PhongReference.h"
#include "Scene.h"

#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace phonglab {

// The shading step both CPU references share (AnalyticRaycaster for analytic
// surfaces, MeshRaycaster for triangle meshes): once a ray has found its hit
// point and normal, what the pixel is must not depend on which surface
// representation found it, so the one function below is the only place that
// turns a hit into a colour.

// What one reference pixel holds besides coverage and depth.
struct ReferenceSample {
    glm::dvec3 color{0.0};    // the unclamped intensity I (or the normals view colour)
    glm::dvec3 specular{0.0}; // the specular part of I alone; zero for the normals view
};

// Shades a hit at camera-space `position` with camera-space `normal` (the
// object-space normal already mapped by the normal matrix; not necessarily
// unit length: it is normalised here, per pixel, as the fragment shaders do).
// No flip towards the viewer: the shipped fragment shaders do not flip either.
ReferenceSample shadeReferenceSample(const glm::dvec3 &position, const glm::dvec3 &normal,
                                     const Material &material, const glm::dvec3 &ambient,
                                     std::span<const CameraSpaceLight> lights, ReferenceShading shading);

// The scene's enabled lights in camera space (a disabled light lights
// nothing, as on the GPU).
std::vector<CameraSpaceLight> enabledCameraSpaceLights(const Scene &scene);

} // namespace phonglab
