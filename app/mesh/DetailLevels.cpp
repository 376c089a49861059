#include "DetailLevels.h"

#include <meshoptimizer.h>

#include <algorithm>

namespace phonglab {

DetailLevels buildDetailLevels(const MeshData &mesh, const std::function<bool(double)> &progress)
{
    DetailLevels out;
    if (!mesh.isValid())
        return out;
    const float *positions = &mesh.positions.front().x;
    const std::size_t vertexCount = mesh.positions.size();
    // meshopt_simplify's error is relative to the mesh's extent.
    const double scale = meshopt_simplifyScale(positions, vertexCount, sizeof(glm::vec3));
    out.levels.push_back({mesh.indices, 0.0});

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
        // and the error is reported for the view to judge.
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
        out.levels.push_back({std::move(simplified), error});
    }
    return out;
}

} // namespace phonglab
