#include "core/reference/SceneHits.h"

#include "FaceGeometry.h"
#include "core/reference/ReferenceSample.h"
#include "core/support/ParallelRows.h"

namespace phonglab {

namespace {

// Gouraud: the exact equation at the triangle's three vertices, the colours
// interpolated like a perspective-correct varying.
ReferenceSample shadeVertices(const SceneHits::Object &object, const ReferenceHit &hit,
                              const Material &material, const glm::dvec3 &ambient,
                              std::span<const CameraSpaceLight> lights)
{
    const MeshData &mesh = *object.mesh;
    const std::size_t base = 3 * std::size_t(hit.triangle);
    ReferenceSample out;
    for (int k = 0; k < 3; ++k) {
        const std::uint32_t v = mesh.indices[base + std::size_t(k)];
        const ReferenceSample vertex =
            shadeReferenceHit({glm::dvec3(mesh.positions[v]), glm::dvec3(mesh.normals[v]),
                               object.modelView, object.normalMatrix, object.model},
                              material, ambient, lights, ReferenceShading::Phong);
        out.color += hit.barycentric[k] * vertex.color;
        out.specular += hit.barycentric[k] * vertex.specular;
    }
    return out;
}

// One sample per covered pixel, rows in parallel.
template <typename ShadeHit>
ReferenceImage shadeEachHit(const SceneHits &hits, const Scene &scene, const ShadeHit &shadeHit)
{
    ReferenceImage image(hits.width, hits.height);
    forEachRowInParallel(hits.height, [&](int y) {
        for (int x = 0; x < hits.width; ++x) {
            const ReferenceHit &hit = hits.at(x, y);
            if (hit.object < 0)
                continue;
            const SceneHits::Object &object = hits.objects[std::size_t(hit.object)];
            const Material &material = scene.objects[std::size_t(hit.object)].material;
            const ReferenceSample sample = shadeHit(object, hit, material);
            const std::size_t i = image.index(x, y);
            image.coverage[i] = 1;
            image.depth[i] = hit.depth;
            image.color[i] = sample.color;
            image.specular[i] = sample.specular;
        }
    });
    return image;
}

} // namespace

ReferenceImage shadeSceneHits(const SceneHits &hits, const Scene &scene,
                              const ReferenceShader &shader)
{
    const std::vector<CameraSpaceLight> lights = enabledCameraSpaceLights(scene, shader);
    return shadeEachHit(
        hits, scene,
        [&](const SceneHits::Object &object, const ReferenceHit &hit, const Material &material) {
            if (shader.makes(ShaderMistake::Gouraud) && object.mesh && hit.triangle >= 0)
                return shadeVertices(object, hit, material, scene.ambient, lights);
            if (const std::optional<int> form = shader.formOf(ShaderMistake::PerFace);
                form && object.mesh && hit.triangle >= 0) {
                // Flat: once at the face's centroid; faceted: at the hit, both
                // with the face's normal. The rest of the equation is exact.
                const FaceGeometry face = faceGeometry(*object.mesh, std::size_t(hit.triangle));
                const glm::dvec3 at =
                    *form == MistakeForm::FaceNormalPerFragment ? hit.point : face.centroid;
                return shadeReferenceHit(
                    {at, face.normal, object.modelView, object.normalMatrix, object.model},
                    material, scene.ambient, lights, ReferenceShader());
            }
            return shadeReferenceHit(
                {hit.point, hit.normal, object.modelView, object.normalMatrix, object.model},
                material, scene.ambient, lights, shader);
        });
}

ReferenceImage shadeSceneFaces(const SceneHits &hits, const Scene &scene)
{
    const std::vector<CameraSpaceLight> lights = enabledCameraSpaceLights(scene);
    return shadeEachHit(
        hits, scene,
        [&](const SceneHits::Object &object, const ReferenceHit &hit, const Material &material) {
            if (!object.mesh || hit.triangle < 0)
                return shadeReferenceHit(
                    {hit.point, hit.normal, object.modelView, object.normalMatrix, object.model},
                    material, scene.ambient, lights, ReferenceShader());
            const FaceGeometry face = faceGeometry(*object.mesh, std::size_t(hit.triangle));
            return shadeReferenceHit(
                {face.centroid, face.normal, object.modelView, object.normalMatrix, object.model},
                material, scene.ambient, lights, ReferenceShader());
        });
}

CameraSpaceHit cameraSpaceHit(const SceneHits &hits, const ReferenceHit &hit)
{
    const SceneHits::Object &object = hits.objects[std::size_t(hit.object)];
    return {glm::dvec3(object.modelView * glm::dvec4(hit.point, 1.0)),
            glm::normalize(object.normalMatrix * hit.normal)};
}

} // namespace phonglab
