#include "BuiltinMeshes.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace phonglab {

namespace {

// Indices for a (columns+1) × (rows+1) vertex grid, two triangles per cell,
// counter-clockwise when seen from outside.
void appendGridIndices(MeshData &mesh, int columns, int rows)
{
    const int stride = columns + 1;
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < columns; ++c) {
            const std::uint32_t a = r * stride + c;
            const std::uint32_t b = a + stride;
            mesh.indices.insert(mesh.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
        }
    }
}

} // namespace

MeshData makeUvSphere(int slices, int stacks)
{
    MeshData mesh;
    constexpr double pi = std::numbers::pi;
    for (int r = 0; r <= stacks; ++r) {
        const double theta = pi * r / stacks; // 0 at +Y pole
        // Exactly 0 at both poles and the seam column exactly the first one
        // (sin(pi) and sin(2 pi) are not 0 in floating point): the copies of
        // a point are then the same point, which welding (decimation) needs.
        const double ringRadius = (r == 0 || r == stacks) ? 0.0 : std::sin(theta);
        for (int c = 0; c <= slices; ++c) {
            const double phi = 2.0 * pi * (c % slices) / slices;
            const glm::dvec3 p(ringRadius * std::sin(phi), std::cos(theta),
                               ringRadius * std::cos(phi));
            mesh.positions.emplace_back(p);
            mesh.normals.emplace_back(p);
        }
    }
    appendGridIndices(mesh, slices, stacks);
    return mesh;
}

MeshData makeTorus(int ringSegments, int tubeSegments, double majorRadius, double minorRadius)
{
    MeshData mesh;
    constexpr double pi = std::numbers::pi;
    for (int t = 0; t <= tubeSegments; ++t) {
        // The last row and column repeat the first exactly (see makeUvSphere).
        const double v = 2.0 * pi * (t % tubeSegments) / tubeSegments; // around the tube
        for (int r = 0; r <= ringSegments; ++r) {
            const double u = 2.0 * pi * (r % ringSegments) / ringSegments; // around Y
            const glm::dvec3 ringDir(std::sin(u), 0.0, std::cos(u));
            const glm::dvec3 normal = std::cos(v) * ringDir + glm::dvec3(0.0, std::sin(v), 0.0);
            mesh.positions.emplace_back(majorRadius * ringDir + minorRadius * normal);
            mesh.normals.emplace_back(normal);
        }
    }
    // Rows advance along v (around the tube); columns along u. Flip the cell
    // order so triangles wind counter-clockwise seen from outside.
    const int stride = ringSegments + 1;
    for (int t = 0; t < tubeSegments; ++t) {
        for (int r = 0; r < ringSegments; ++r) {
            const std::uint32_t a = t * stride + r;
            const std::uint32_t b = a + stride;
            mesh.indices.insert(mesh.indices.end(), {a, a + 1, b, a + 1, b + 1, b});
        }
    }
    return mesh;
}

MeshData makeCube()
{
    MeshData mesh;
    for (int axis = 0; axis < 3; ++axis) {
        for (float sign : {1.0f, -1.0f}) {
            glm::vec3 n(0.0f);
            n[axis] = sign;
            // Two in-face directions with u × v = n, so corners run
            // counter-clockwise seen from outside.
            glm::vec3 u(0.0f), v(0.0f);
            u[(axis + 1) % 3] = 1.0f;
            v[(axis + 2) % 3] = sign;
            const auto base = std::uint32_t(mesh.positions.size());
            for (auto [a, b] :
                 {std::pair{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}}) {
                mesh.positions.push_back(n + a * u + b * v);
                mesh.normals.push_back(n);
            }
            mesh.indices.insert(mesh.indices.end(),
                                {base, base + 1, base + 2, base, base + 2, base + 3});
        }
    }
    return mesh;
}

bool isBuiltinMeshSpec(const QString &spec)
{
    return spec.startsWith(QLatin1String("builtin:"));
}

std::optional<MeshData> builtinMesh(const QString &spec)
{
    return builtinMesh(spec, 1.0);
}

std::optional<BuiltinTessellation> builtinTessellation(const QString &spec, double detail)
{
    const bool sphere = spec == QLatin1String("builtin:sphere");
    if (!sphere && spec != QLatin1String("builtin:torus"))
        return std::nullopt;
    // Both counts scale by sqrt(detail), so the triangle count scales by detail.
    const double scale = (detail > 0.0 && detail <= 1.0) ? std::sqrt(detail) : 1.0;
    const BuiltinTessellation full =
        sphere ? BuiltinTessellation{256, 128} : BuiltinTessellation{192, 96};
    return BuiltinTessellation{std::max(kMinBuiltinColumns, int(std::lround(full.columns * scale))),
                               std::max(kMinBuiltinRows, int(std::lround(full.rows * scale)))};
}

std::optional<MeshData> builtinMesh(const QString &spec, double detail)
{
    if (const auto grid = builtinTessellation(spec, detail)) {
        if (spec == QLatin1String("builtin:sphere"))
            return makeUvSphere(grid->columns, grid->rows);
        return makeTorus(grid->columns, grid->rows);
    }
    if (spec == QLatin1String("builtin:cube"))
        return makeCube();
    return std::nullopt;
}

QString builtinDetailLabel(const QString &spec, double detail)
{
    if (const auto grid = builtinTessellation(spec, detail))
        return QStringLiteral("%1\u00d7%2").arg(grid->columns).arg(grid->rows);
    return spec == QLatin1String("builtin:cube") ? QStringLiteral("6 faces") : QString();
}

} // namespace phonglab
