#pragma once
#include "core/reference/AnalyticRaycaster.h"
#include "core/reference/ReferenceImage.h"
#include "core/scene/MeshData.h"
#include "core/scene/Scene.h"

#include <QString>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace phonglab {

// What the reference's rays found, before any shading: per pixel the nearest
// hit's object, its object-space point and normal and, on a triangle mesh,
// the triangle and the barycentric coordinates of the hit. Casting is the
// expensive half of the reference; shading the same hits again with another
// ReferenceShader (each classic mistake, say) costs a fraction of it, and
// the pixel inspector reads one hit to explain one pixel.

struct ReferenceHit {
    int object = -1;             // index into Scene::objects; -1 where nothing was hit
    std::int32_t triangle = -1;  // on a triangle mesh; -1 on an analytic surface
    double depth = 0.0;          // camera-space -z
    glm::dvec3 point{0.0};       // object space
    glm::dvec3 normal{0.0};      // object space, not normalised (the normal matrix comes first)
    glm::dvec3 barycentric{0.0}; // on a triangle: the weights of its three vertices
};

struct SceneHits {
    // Per scene object: its matrices and the mesh its triangles index.
    struct Object {
        glm::dmat4 modelView{1.0};
        glm::dmat3 normalMatrix{1.0};
        glm::dmat4 model{1.0};
        std::shared_ptr<const MeshData> mesh; // null for an analytic surface
    };
    int width = 0;
    int height = 0;
    std::vector<Object> objects;    // one per scene object
    std::vector<ReferenceHit> hits; // row-major, row 0 at the top

    const ReferenceHit &at(int x, int y) const
    {
        return hits[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    }
};

// raycastSceneMeshes()'s rays (MeshRaycaster.h: same inputs, conventions,
// errors, progress and cancelling), keeping the hits instead of shading them.
Result<SceneHits> castSceneHits(const Scene &scene,
                                const std::vector<std::shared_ptr<const MeshData>> &objectMeshes,
                                int width, int height,
                                const std::function<bool(double)> &progress = {});

// The reference image of `hits` shaded with `shader` (rows in parallel). The
// gouraud mistake shades the three vertices of the hit triangle and
// interpolates their colours with the hit's barycentric weights (which is
// what a perspective-correct varying does); on an analytic surface, which
// has no vertices, it shades exactly.
ReferenceImage shadeSceneHits(const SceneHits &hits, const Scene &scene,
                              const ReferenceShader &shader);

// Flat shading as shaders/flat.vert computes it: the exact equation once per
// triangle, at its centroid with its face normal (FaceGeometry.h), for every
// pixel the triangle covers. An analytic surface, which has no faces, is
// shaded exactly.
ReferenceImage shadeSceneFaces(const SceneHits &hits, const Scene &scene);

// The illumination equation's inputs at one hit, as the exact vertex stage
// computes them: camera-space point and (normalised) normal.
struct CameraSpaceHit {
    glm::dvec3 position{0.0};
    glm::dvec3 normal{0.0, 0.0, 1.0};
};
CameraSpaceHit cameraSpaceHit(const SceneHits &hits, const ReferenceHit &hit);

} // namespace phonglab
