#include "DetailLevels.h"

#include "core/reference/MeshBvh.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>

namespace phonglab {

namespace {

struct Sample {
    glm::dvec3 point;
    glm::dvec3 normal; // unit
};

// Up to kNormalSamples points of the full mesh with the normal Phong shades
// them with: vertices, then triangle centres (interpolated normals), evenly
// strided when there are more.
std::vector<Sample> normalSamples(const MeshData &mesh)
{
    std::vector<Sample> all;
    const std::size_t total = mesh.positions.size() + mesh.triangleCount();
    const std::size_t stride = std::max<std::size_t>(1, total / kNormalSamples);
    for (std::size_t i = 0; i < total; i += stride) {
        Sample s;
        if (i < mesh.positions.size()) {
            s.point = glm::dvec3(mesh.positions[i]);
            s.normal = glm::dvec3(mesh.normals[i]);
        } else {
            const std::size_t t = i - mesh.positions.size();
            for (std::size_t k = 0; k < 3; ++k) {
                const std::uint32_t v = mesh.indices[3 * t + k];
                s.point += glm::dvec3(mesh.positions[v]) / 3.0;
                s.normal += glm::dvec3(mesh.normals[v]) / 3.0;
            }
        }
        if (glm::dot(s.normal, s.normal) <= 0.0)
            continue;
        s.normal = glm::normalize(s.normal);
        all.push_back(s);
    }
    return all;
}

glm::dvec3 shadedNormal(const MeshData &mesh, const std::vector<std::uint32_t> &indices,
                        const TriangleHit &hit)
{
    const std::size_t base = 3 * std::size_t(hit.triangle);
    return hit.interpolate(glm::dvec3(mesh.normals[indices[base]]),
                           glm::dvec3(mesh.normals[indices[base + 1]]),
                           glm::dvec3(mesh.normals[indices[base + 2]]));
}

double angleBetween(const glm::dvec3 &a, const glm::dvec3 &b)
{
    if (glm::dot(a, a) <= 0.0 || glm::dot(b, b) <= 0.0)
        return M_PI / 2;
    return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0));
}

// The directions a pixel's ray may come from at a sample: along the normal
// and tilted kGrazingDeg away from it four ways (steeper pixels lie in the
// silhouette band).
std::vector<glm::dvec3> viewDirections(const glm::dvec3 &n)
{
    const glm::dvec3 helper = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(n, helper));
    const glm::dvec3 v = glm::cross(n, u);
    const double tilt = glm::radians(kGrazingDeg);
    std::vector<glm::dvec3> out{n};
    for (const glm::dvec3 &side : {u, -u, v, -v})
        out.push_back(std::cos(tilt) * n + std::sin(tilt) * side);
    return out;
}

// The largest angle between the normal the full mesh is shaded with and
// the one the level is shaded with, where the same view ray meets each:
// rays towards every sample from the directions above, starting `reach`
// in front of it. A ray that meets the level nowhere near counts as a
// right angle (a hole); one whose full-mesh hit is elsewhere (another part
// of the mesh in the way) is skipped.
//
// `scratch` holds the mesh's positions (all a MeshBvh reads besides the
// indices), so the vertices are copied once for the ladder, not per level.
double normalDeviation(const MeshData &mesh, const MeshBvh &fullBvh, MeshData &scratch,
                       const std::vector<std::uint32_t> &indices,
                       const std::vector<Sample> &samples, double reach)
{
    scratch.indices = indices;
    const MeshBvh bvh(scratch);
    double worst = 0.0;
    for (const Sample &s : samples)
        for (const glm::dvec3 &towardsEye : viewDirections(s.normal)) {
            const Ray ray{s.point + reach * towardsEye, -towardsEye};
            const auto full = fullBvh.closestHit(ray, 0.0, 3.0 * reach);
            if (!full || std::abs(full->t - reach) > 0.5 * reach)
                continue;
            const auto coarse = bvh.closestHit(ray, 0.0, 3.0 * reach);
            worst = std::max(worst,
                             coarse ? angleBetween(shadedNormal(mesh, mesh.indices, *full),
                                                   shadedNormal(mesh, indices, *coarse))
                                    : M_PI / 2);
        }
    return worst;
}

} // namespace

DetailLevels buildDetailLevels(const MeshData &mesh, const std::function<bool(double)> &progress)
{
    DetailLevels out;
    if (!mesh.isValid())
        return out;
    const float *positions = &mesh.positions.front().x;
    const std::size_t vertexCount = mesh.positions.size();
    // meshopt_simplify's error is relative to the mesh's extent.
    const double scale = meshopt_simplifyScale(positions, vertexCount, sizeof(glm::vec3));
    out.levels.push_back({mesh.indices, 0.0, 0.0});
    const std::vector<Sample> samples = normalSamples(mesh);
    const MeshBvh fullBvh(mesh);
    MeshData scratch;
    scratch.positions = mesh.positions;

    // Work done is about proportional to the triangles simplified; the
    // levels halve, so the whole ladder costs about twice the first step.
    const double total = 2.0 * double(mesh.triangleCount());
    double done = 0.0;
    while (out.levels.back().indices.size() / 3 >= 2 * kMinLevelTriangles) {
        const DetailLevel &previous = out.levels.back();
        const std::size_t target = (previous.indices.size() / 3 / 2) * 3;
        std::vector<std::uint32_t> simplified(previous.indices.size());
        float stepError = 0.0f;
        // No error limit (1 = the whole extent): the triangle target rules,
        // and the error is reported for the view to check.
        simplified.resize(meshopt_simplify(simplified.data(), previous.indices.data(),
                                           previous.indices.size(), positions, vertexCount,
                                           sizeof(glm::vec3), target, 1.0f, 0, &stepError));
        done += double(previous.indices.size() / 3);
        if (progress && !progress(std::min(done / total, 1.0)))
            return {};
        if (simplified.empty() || simplified.size() * 10 > previous.indices.size() * 9)
            break; // stuck: locked borders, or nothing left to collapse
        simplified.shrink_to_fit();
        const double error = previous.error + double(stepError) * scale;
        // Far enough to find the level from any sample, near enough not to
        // reach across the mesh: a few times the level's own error.
        const double reach = std::max(4.0 * error, 0.01 * scale);
        const double deviation =
            std::max(previous.normalDeviation,
                     normalDeviation(mesh, fullBvh, scratch, simplified, samples, reach));
        out.levels.push_back({std::move(simplified), error, deviation});
    }
    return out;
}

} // namespace phonglab
