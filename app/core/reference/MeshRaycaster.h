#pragma once
#include "core/reference/AnalyticRaycaster.h"
#include "core/reference/ReferenceImage.h"
#include "core/scene/MeshData.h"
#include "core/scene/Scene.h"

#include <QHash>
#include <QString>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace phonglab {

// The CPU ground truth for scenes of real meshes: every pixel centre is
// ray-cast against the full-resolution triangle mesh of each object (through
// a MeshBvh, so a 512² frame of a million-triangle mesh takes seconds), and
// the hit is shaded in double precision with the normal the GPU would
// compute there: the barycentric interpolation of the triangle's three
// object-space vertex normals, mapped by the normal matrix (inverse transpose
// of the model-view) and normalised per pixel. That is exactly what
// phong.vert/.frag compute (perspective-correct interpolation of a linearly
// mapped normal, normalised per fragment), so against a correct GPU render
// only float precision and rasterisation differ, never the tessellation.
//
// The conventions: cameraRay() pixel centres (AnalyticRaycaster.h), the
// near/far clip on camera depth, each object intersected in its own space
// with the camera ray mapped by inverse(modelView) (so t stays the camera
// depth), the nearest hit over all objects (an exact tie keeps the earlier
// object, like GL_LESS), no flip of normals towards the viewer, objects with
// a zero-determinant transform left out, and the same shading code
// (shadeReferenceSample), `specular` included.
//
// No back-face culling: both faces of every triangle are hit. The GPU culls
// back faces of closed meshes only, and along any ray the nearest hit on a
// closed mesh seen from outside is a front face, so culling would change
// nothing there, while open meshes are drawn two-sided on the GPU too.
//
// objectMeshes has one entry per scene object, in the same order: the
// triangle mesh to ray-cast, or null to use the analytic surface of the
// object's builtin ("builtin:sphere|torus|cube").
// A size mismatch, an invalid mesh, or a null entry for a non-builtin mesh
// gives nullopt and *error. Objects sharing one MeshData pointer share one
// BVH, built once per call.
//
// Rows run in parallel on all cores; each pixel depends on nothing but its
// own ray, so the image is identical whatever the thread count.
// progress(fraction done) is called now and then from the calling thread
// (the first tenth covers building the BVHs); returning false cancels: the
// result is the failure "cancelled".
Result<ReferenceImage> raycastSceneMeshes(
    const Scene &scene, const std::vector<std::shared_ptr<const MeshData>> &objectMeshes, int width,
    int height, const ReferenceShader &shader, const std::function<bool(double)> &progress = {});

// A scene of builtins alone, each ray-cast against its analytic surface
// (AnalyticRaycaster.h) by raycastSceneMeshes() with no triangle meshes:
// exact normals at exact hit points, so a correct GPU render differs from it
// only by tessellation, interpolation and float precision. An object with
// any other mesh makes it fail, naming the mesh. `standIns` maps a mesh as
// written in the scene (a Blender cube's file path) to the builtin whose
// surface stands in for it ("builtin:cube").
Result<ReferenceImage> raycastScene(const Scene &scene, int width, int height,
                                    const ReferenceShader &shader,
                                    const QHash<QString, QString> &standIns = {});
// The same with exact Phong.
Result<ReferenceImage> raycastScene(const Scene &scene, int width, int height,
                                    const QHash<QString, QString> &standIns = {});

// Geometry only: the camera depth of the nearest surface along the ray
// through any point of the image, with the objects, meshes, conventions and
// nearest-hit rule of raycastSceneMeshes() but no shading (no normal is even
// interpolated). For questions about where surfaces are rather than how they
// look, such as ambiguousReferencePixels() (ReferenceEdges.h), which casts
// each pixel several times at sub-pixel offsets.
//
// The BVHs are built once, in create() (per distinct mesh, as in
// raycastSceneMeshes()); depthAt() is const and may be called from any
// number of threads at once.
class SceneDepthCaster
{
public:
    // A failure for the inputs raycastSceneMeshes() rejects.
    static Result<std::unique_ptr<SceneDepthCaster>> create(
        const Scene &scene, const std::vector<std::shared_ptr<const MeshData>> &objectMeshes,
        int width, int height);
    ~SceneDepthCaster();

    // The depth (camera-space -z) of the nearest hit along the ray through
    // image point (px, py), in pixels from the top-left corner of the image:
    // (x + 0.5, y + 0.5) is the centre of pixel (x, y), whose ray and depth
    // are exactly raycastSceneMeshes()'s. +infinity where nothing is hit.
    double depthAt(double px, double py) const;

    int width() const { return m_width; }
    int height() const { return m_height; }

private:
    struct Objects;
    SceneDepthCaster();

    // Nothing refers to the scene or the meshes after create(): the BVHs
    // hold their own triangles.
    std::unique_ptr<Objects> m_objects;
    int m_width = 0;
    int m_height = 0;
    double m_tanHalfFov = 0.0;
    double m_nearPlane = 0.0;
    double m_farPlane = 0.0;
};

} // namespace phonglab
