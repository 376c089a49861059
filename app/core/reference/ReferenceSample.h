#pragma once
#include "core/reference/AnalyticRaycaster.h"
#include "core/reference/PhongReference.h"
#include "core/scene/Material.h"
#include "core/scene/Scene.h"

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
                                     std::span<const CameraSpaceLight> lights,
                                     ReferenceShading shading);

// A ray's hit on an object before the vertex shader's transforms: the point
// and normal in object space, and the object's matrices.
struct ObjectSpaceHit {
    glm::dvec3 point{0.0};
    glm::dvec3 normal{0.0, 0.0, 1.0};
    const glm::dmat4 &modelView;
    const glm::dmat3 &normalMatrix; // inverse transpose of modelView's upper 3×3
    const glm::dmat4 &model;        // for the mistake of moving N by the model matrix alone
};

// Moves a hit into camera space as the vertex shader does (P = MV·(p, 1),
// N = normal matrix · n) and shades it there; with `shader.mistakes` the
// transforms and the equation are the mistaken ones, in the forms they
// say (normal-matrix: N = MV·(n, 0), M·(n, 0) or MVᵀ·n;
// homogeneous-w: P = MV·(p, 0), or N = MV·(n, 1); light-space by the
// model-view matrix: each light moved by the hit's MV). The one function both
// ray-casters shade with.
ReferenceSample shadeReferenceHit(const ObjectSpaceHit &hit, const Material &material,
                                  const glm::dvec3 &ambient,
                                  std::span<const CameraSpaceLight> lights,
                                  const ReferenceShader &shader);

// The scene's enabled lights in camera space (a disabled light lights
// nothing, as on the GPU); with the light-space mistake, their world
// positions taken as camera coordinates.
std::vector<CameraSpaceLight> enabledCameraSpaceLights(const Scene &scene,
                                                       const ReferenceShader &shader = {});

} // namespace phonglab
