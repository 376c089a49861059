#pragma once
#include "ShaderMistake.h"
#include "core/reference/PhongEquation.h"
#include "core/scene/Material.h"
#include "core/scene/PointLight.h"

#include <glm/glm.hpp>
#include <span>

namespace phonglab {

// The CPU reference of PhongLab's illumination equation, in double precision:
//
//   I = Ia·ka + Σ_i f_att,i · (Id,i·kd·max(0, N·L_i) + Is,i·ks·max(0, R_i·V)^n)
//   f_att = min(1 / (c1 + c2·d + c3·d²), 1)
//
// Everything here is in camera coordinates (the eye sits at the origin).
// The one deliberate addition to the formula: where N·L ≤ 0 the light is
// behind the surface and contributes no specular term either (otherwise R·V
// can be positive for a light shining on the back and paint a highlight on an
// unlit side). shaders/phong.frag does exactly the same.

struct CameraSpaceLight {
    glm::dvec3 position{0.0};              // camera coordinates (a point)
    glm::dvec3 diffuse{1.0};               // Id
    glm::dvec3 specular{1.0};              // Is
    glm::dvec3 attenuation{1.0, 0.0, 0.0}; // c1, c2, c3
};

// f_att for distance d. Assumes c1 + c2·d + c3·d² > 0 (the scene loader
// refuses attenuation that could make it non-positive).
double attenuationFactor(const glm::dvec3 &c, double d);

// Light arriving at surface point `position` (camera space) with unit or
// non-unit normal `normal` (camera space; normalised here).
glm::dvec3 phongIntensity(const glm::dvec3 &position, const glm::dvec3 &normal,
                          const Material &material, const glm::dvec3 &ambient,
                          std::span<const CameraSpaceLight> lights);

// Blinn-Phong: phongIntensity() with the specular term built on the half
// vector H = normalize(L + V) instead of the reflected ray R:
//
//   Is·ks·max(0, N·H)^n'   with the matched exponent n' = kBlinnExponentFactor·n
//
// The angle between N and H is about half the angle between R and V, so the
// same exponent would make the highlight about twice as wide; 4n makes the
// two highlights match near their peak. Same N·L ≤ 0 rule as Phong.
// shaders/blinn-phong.frag computes the same.
inline constexpr double kBlinnExponentFactor = 4.0;
glm::dvec3 blinnPhongIntensity(const glm::dvec3 &position, const glm::dvec3 &normal,
                               const Material &material, const glm::dvec3 &ambient,
                               std::span<const CameraSpaceLight> lights);

// The same equations with the specular part reported on its own, for
// measuring the error inside a highlight alone: `specular` is
// Σ_i f_att,i · Is,i·ks·max(0, R_i·V)^n (N·H and n' for Blinn-Phong), not
// clamped. `intensity` is bit for bit what phongIntensity() /
// blinnPhongIntensity() return (they are these functions' first member).
struct IlluminationTerms {
    glm::dvec3 intensity{0.0};
    glm::dvec3 specular{0.0};
};
IlluminationTerms phongTerms(const glm::dvec3 &position, const glm::dvec3 &normal,
                             const Material &material, const glm::dvec3 &ambient,
                             std::span<const CameraSpaceLight> lights);
IlluminationTerms blinnPhongTerms(const glm::dvec3 &position, const glm::dvec3 &normal,
                                  const Material &material, const glm::dvec3 &ambient,
                                  std::span<const CameraSpaceLight> lights);

// phongTerms() as a fragment shader with `mistakes` computes it (several at
// once as real code makes them, one form of a key at most), for the
// pointwise mistakes (isPointwiseMistake()): N left unnormalised,
// reflect(L, N), V = normalize(P), no f_att, no max(0, N·L) (the diffuse
// term goes negative behind the surface), a highlight where N·L <= 0, no
// ambient term, Blinn's N·H in place of R·V; and their other forms
// (MistakeForm): L left unnormalised, f_att unclamped or hard-coded, Ia·ka
// added once per light or attenuated with it, N·H with 4n. For the other mistakes the
// inputs differ, not the equation: this returns phongTerms() of the inputs
// it is given. With the slide's `equation` the highlight stays where
// N·L <= 0, and the mistake (if any) is made in that equation.
IlluminationTerms mistakenPhongTerms(const glm::dvec3 &position, const glm::dvec3 &normal,
                                     const Material &material, const glm::dvec3 &ambient,
                                     std::span<const CameraSpaceLight> lights,
                                     std::span<const MistakeVariant> mistakes,
                                     PhongEquation equation = PhongEquation::Guarded);

// The normals view (shaders/normals.frag): the unit camera-space normal as a
// colour, 0.5·N + 0.5 per channel. No lighting.
glm::dvec3 normalViewColor(const glm::dvec3 &normal);

// World-space lights moved into camera space with the view matrix alone.
CameraSpaceLight toCameraSpace(const PointLight &light, const glm::dmat4 &view);

// Output encoding shared with the GPU path: round(clamp(I, 0, 1) · 255).
int encodeChannel(double intensity);

} // namespace phonglab
