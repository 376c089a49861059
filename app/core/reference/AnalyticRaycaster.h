#pragma once
#include "ShaderMistake.h"
#include "core/reference/PhongEquation.h"
#include "core/reference/ReferenceImage.h"
#include "core/scene/Scene.h"
#include "core/support/Result.h"
#include "core/view/Camera.h"

#include <QHash>
#include <QString>
#include <algorithm>
#include <optional>
#include <vector>

namespace phonglab {

// The analytic surfaces the builtins approximate ("builtin:sphere" is the
// unit sphere, "builtin:torus" the torus of AnalyticShapes.h, "builtin:cube"
// the box [-1, 1]³) and their exact intersections and normals, the camera
// ray through a pixel, and what a hit is shaded with (ReferenceShader). The
// scene itself is ray-cast in one place, MeshRaycaster.h, where an object is
// either one of these surfaces or a triangle mesh.

// What the reference computes at each hit point. Gouraud and flat shading
// have no per-pixel analytic counterpart: their result depends on the mesh's
// vertices and faces, which the analytic surface does not have.
enum class ReferenceShading {
    Phong,      // phongIntensity()
    BlinnPhong, // blinnPhongIntensity()
    Normals,    // normalViewColor(): the normals view
};

// The per-pixel shading a method computes, or for Gouraud and flat the one
// they approximate (Phong), so that their error can be measured against it.
ReferenceShading idealShadingFor(ShadingMethod method);

// What the reference shades a hit with: a shading, exact, or Phong with one
// of the classic mistakes made (ShaderMistake.h), to tell which one explains
// a wrong render. Every mistake but `gouraud` is made where a shader makes
// it: the normal's or the position's transform, the lights' coordinates, the
// equation at the point. `gouraud` needs the mesh's vertices, which a ray
// does not see: it shades exactly.
struct ReferenceShader {
    ReferenceShading shading = ReferenceShading::Phong;
    // With Phong only: the mistakes made, one form of each key at most.
    // Several at once, as real code makes them (MistakeSets).
    std::vector<MistakeVariant> mistakes;
    // Phong's form: the slide's keeps a highlight where N·L <= 0 (what the
    // backface-specular mistake makes of the guarded one); the mistakes are
    // then made in that equation.
    PhongEquation equation = PhongEquation::Guarded;

    ReferenceShader(ReferenceShading s = ReferenceShading::Phong,
                    std::optional<ShaderMistake> m = std::nullopt, int f = 0)
        : shading(s)
    {
        if (m)
            mistakes.push_back({*m, f});
    }
    ReferenceShader(ReferenceShading s, MistakeVariant v)
        : ReferenceShader(s, v.key, v.form)
    {
    }
    ReferenceShader(ReferenceShading s, std::vector<MistakeVariant> v)
        : shading(s)
        , mistakes(std::move(v))
    {
    }
    // Whether `m` is made in form `f`.
    bool makes(ShaderMistake m, int f = 0) const
    {
        return std::find(mistakes.begin(), mistakes.end(), MistakeVariant{m, f}) != mistakes.end();
    }
    // The form `m` is made in, if it is made at all.
    std::optional<int> formOf(ShaderMistake m) const
    {
        for (const MistakeVariant &v : mistakes)
            if (v.key == m)
                return v.form;
        return std::nullopt;
    }
};

// A ray o + t·d; d need not be unit length (t then keeps its meaning across a
// change of coordinates, which is what lets camera-space depth be compared
// between objects intersected in their own object space).
struct Ray {
    glm::dvec3 origin{0.0};
    glm::dvec3 direction{0.0, 0.0, -1.0};

    glm::dvec3 at(double t) const { return origin + t * direction; }
};

// Camera-space ray through the centre of pixel (x, y), y = 0 the top row.
// Its direction has z = -1, so the ray parameter t IS the camera-space depth -z.
Ray cameraRay(const Camera &camera, int x, int y, int width, int height);

// Smallest t in [tMin, tMax] where the ray meets the surface, if any.
std::optional<double> intersectUnitSphere(const Ray &ray, double tMin, double tMax);
std::optional<double> intersectTorus(const Ray &ray, double tMin, double tMax, double majorRadius,
                                     double minorRadius);

std::optional<double> intersectUnitBox(const Ray &ray, double tMin, double tMax);
glm::dvec3 boxNormal(const glm::dvec3 &p);

// Exact outward object-space normal of the torus (around Y) at surface point p.
glm::dvec3 torusNormal(const glm::dvec3 &p, double majorRadius);

} // namespace phonglab
