#pragma once
#include "core/reference/PhongEquation.h"
#include "core/reference/SceneHits.h"

#include <QString>
#include <optional>
#include <vector>

namespace phonglab {

// The exact illumination equation at one pixel, term by term: what the pixel
// inspector shows. Every value is the reference's (double precision, the
// same hit and the same sequence as phongTerms()), in camera coordinates
// unless named world.

struct LightTerms {
    int light = 0;      // index into Scene::lights
    glm::dvec3 L{0.0};  // unit, towards the light
    glm::dvec3 R{0.0};  // reflect(-L, N)
    glm::dvec3 H{0.0};  // normalize(L + V), Blinn-Phong's half vector
    double NdotH = 0.0; // unclamped; Blinn-Phong's specular factor is max(0, N·H)^(4n)
    glm::dvec3 positionCamera{0.0};
    double distance = 0.0;    // d
    double attenuation = 0.0; // f_att
    double NdotL = 0.0;       // unclamped
    double RdotV = 0.0;       // unclamped
    glm::dvec3 diffuse{0.0};  // f_att · Id·kd·max(0, N·L)
    glm::dvec3 specular{0.0}; // f_att · Is·ks·max(0, R·V)^n (Blinn-Phong: N·H), 0 where N·L <= 0
};

struct PixelTerms {
    ReferenceShading shading = ReferenceShading::Phong; // the equation the terms are of
    PhongEquation equation = PhongEquation::Guarded;    // ... and with Phong, which form
    int x = 0, y = 0;
    int object = -1;
    glm::dvec3 positionWorld{0.0};
    glm::dvec3 positionCamera{0.0};
    glm::dvec3 N{0.0};              // unit
    glm::dvec3 V{0.0};              // unit, towards the eye
    glm::dvec3 ambient{0.0};        // Ia·ka
    std::vector<LightTerms> lights; // the enabled ones; none for the normals view
    glm::dvec3 intensity{
        0.0}; // I, unclamped: ambient + Σ (diffuse + specular); the normals view: 0.5·N + 0.5

    // Plain text, one value per line, for the clipboard.
    QString toText() const;
};

// Nullopt where pixel (x, y) shows no object. `shading` is the exact
// equation of the view (CheckReference::shader): Phong, Blinn-Phong, or the
// normals view, which lights nothing. With Phong, `equation` says which
// form: the slide's keeps a light's highlight where N·L <= 0 (and no
// diffuse light there).
std::optional<PixelTerms> pixelTerms(const SceneHits &hits, const Scene &scene,
                                     ReferenceShading shading, int x, int y,
                                     PhongEquation equation = PhongEquation::Guarded);

} // namespace phonglab
