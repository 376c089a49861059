#include "NormalMethodStudy.h"

#include "NormalComputation.h"
#include "mesh/detail/MeshDecimation.h"
#include "mesh/import/BuiltinMeshes.h"

#include <QElapsedTimer>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <map>
#include <random>
#include <unordered_map>

namespace phonglab {

namespace {

// Positions shared by the triangles around them: what computeNormals
// averages over. A MeshData splits seams and poles into copies, which would
// make a seam look like a border; welded by exact position here, with
// triangles left without area (a UV sphere's pole caps) dropped.
struct Surface {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> triangles;
};

Surface weld(const MeshData &mesh)
{
    Surface s;
    std::map<std::array<float, 3>, std::uint32_t> idOf; // ordered: deterministic ids
    std::vector<std::uint32_t> remap(mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::vec3 p = mesh.positions[i] + glm::vec3(0.0f); // -0 -> +0
        const auto [it, added] =
            idOf.try_emplace({p.x, p.y, p.z}, std::uint32_t(s.positions.size()));
        if (added)
            s.positions.push_back(p);
        remap[i] = it->second;
    }
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t a = remap[mesh.indices[t]], b = remap[mesh.indices[t + 1]],
                            c = remap[mesh.indices[t + 2]];
        if (a != b && b != c && c != a)
            s.triangles.insert(s.triangles.end(), {a, b, c});
    }
    return s;
}

// Uniform in [0, 1) from the standard mt19937 sequence (the std
// distributions may differ between libraries; this does not).
double uniform(std::mt19937 &random)
{
    return double(random() >> 8) / double(1u << 24);
}

// An icosahedron subdivided `levels` times onto the unit sphere, then each
// vertex pushed along the sphere by up to `jitter` × the edge length in a
// random direction and re-projected: triangles of every shape and size, no
// two vertices alike. 30 % keeps every triangle the right way round (a
// vertex and the opposite edge together move at most 0.6 edge, less than
// the 0.87 edge between them).
Surface jitteredIcosphere(int levels, double jitter, std::uint32_t seed)
{
    const double g = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<glm::dvec3> p = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0},
                                 {0, -1, g}, {0, 1, g}, {0, -1, -g}, {0, 1, -g},
                                 {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
    for (glm::dvec3 &v : p)
        v = glm::normalize(v);
    std::vector<std::uint32_t> t = {0, 11, 5, 0, 5,  1,  0,  1,  7,  0,  7, 10, 0, 10, 11,
                                    1, 5,  9, 5, 11, 4,  11, 10, 2,  10, 7, 6,  7, 1,  8,
                                    3, 9,  4, 3, 4,  2,  3,  2,  6,  3,  6, 8,  3, 8,  9,
                                    4, 9,  5, 2, 4,  11, 6,  2,  10, 8,  6, 7,  9, 8,  1};
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoint;
        const auto mid = [&](std::uint32_t a, std::uint32_t b) {
            const auto key = std::minmax(a, b);
            const auto [it, added] =
                midpoint.try_emplace({key.first, key.second}, std::uint32_t(p.size()));
            if (added)
                p.push_back(glm::normalize(p[a] + p[b]));
            return it->second;
        };
        std::vector<std::uint32_t> finer;
        finer.reserve(t.size() * 4);
        for (std::size_t i = 0; i < t.size(); i += 3) {
            const std::uint32_t a = t[i], b = t[i + 1], c = t[i + 2];
            const std::uint32_t ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
            finer.insert(finer.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
        }
        t = std::move(finer);
    }
    const double edge = glm::length(p[t[0]] - p[t[1]]);
    std::mt19937 random(seed);
    Surface s;
    for (const glm::dvec3 &v : p) {
        // A random direction in the tangent plane, a random distance.
        const glm::dvec3 helper = std::abs(v.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
        const glm::dvec3 u = glm::normalize(glm::cross(v, helper)), w = glm::cross(v, u);
        const double angle = 2.0 * M_PI * uniform(random),
                     distance = jitter * edge * uniform(random);
        s.positions.emplace_back(
            glm::normalize(v + distance * (std::cos(angle) * u + std::sin(angle) * w)));
    }
    s.triangles = std::move(t);
    return s;
}

double angleDeg(const glm::vec3 &a, const glm::vec3 &b)
{
    const double c = glm::dot(glm::normalize(glm::dvec3(a)), glm::normalize(glm::dvec3(b)));
    return glm::degrees(std::acos(std::clamp(c, -1.0, 1.0)));
}

NormalStudyRow measure(const QString &tessellation, const Surface &s, NormalMethod method,
                       int repeats)
{
    NormalStudyRow row;
    row.tessellation = tessellation;
    row.method = normalMethodName(method);
    row.triangles = qint64(s.triangles.size() / 3);
    std::vector<double> times;
    CornerNormals normals;
    for (int i = 0; i < std::max(1, repeats); ++i) {
        QElapsedTimer timer;
        timer.start();
        normals = computeNormals(s.positions, s.triangles, method);
        times.push_back(timer.nsecsElapsed() / 1e6);
    }
    std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
    row.ms = times[times.size() / 2];
    const std::vector<glm::vec3> corner = expandCornerNormals(normals, s.triangles);
    double sum = 0.0;
    for (std::size_t c = 0; c < corner.size(); ++c) {
        const double a =
            angleDeg(corner[c], s.positions[s.triangles[c]]); // exact: the point's radius
        row.maxAngleDeg = std::max(row.maxAngleDeg, a);
        sum += a;
    }
    row.meanAngleDeg = corner.empty() ? 0.0 : sum / double(corner.size());
    return row;
}

} // namespace

std::vector<NormalStudyRow> runNormalStudy(int repeats)
{
    const std::vector<std::pair<QString, Surface>> tessellations = {
        {QStringLiteral("UV sphere 64\u00d732"), weld(makeUvSphere(64, 32))},
        {QStringLiteral("icosphere 5, jittered 30 %"), jitteredIcosphere(5, 0.3, 20240601u)},
        {QStringLiteral("UV sphere 128\u00d764 decimated to 1/4"),
         weld(decimateMesh(makeUvSphere(128, 64), 0.25).mesh)},
    };
    std::vector<NormalStudyRow> rows;
    for (const auto &[name, surface] : tessellations)
        for (const NormalMethod method : {NormalMethod::Flat, NormalMethod::Average,
                                          NormalMethod::AreaWeighted, NormalMethod::AngleWeighted})
            rows.push_back(measure(name, surface, method, repeats));
    return rows;
}

} // namespace phonglab
