#pragma once
// Internal to NormalComputation*.cpp: the small float helpers the normal
// methods share (smooth, flat and creased).
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <span>

namespace phonglab::normals {

constexpr std::uint32_t kUnassigned = std::numeric_limits<std::uint32_t>::max();
constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kTiny = std::numeric_limits<float>::min();
constexpr float kHuge = std::numeric_limits<float>::max();
// A sum shorter than this fraction of its parts' total size has cancelled:
// its direction is rounding noise (two faces back to back, or within
// 0.01° of it), not a normal.
constexpr float kCancelled = 1e-4f;

// Unit vector along v, or zero when v has no usable direction. Dividing by
// the length (rather than multiplying by its inverse) keeps axis-aligned
// normals exact: sqrt(w²) is w in IEEE arithmetic, and w / w is 1.
inline glm::vec3 normalizedOrZero(const glm::vec3 &v)
{
    const float length = std::sqrt(glm::dot(v, v));
    return length > kTiny && length <= kHuge ? v / length : glm::vec3(0.0f);
}

inline bool isZero(const glm::vec3 &v)
{
    return v.x == 0.0f && v.y == 0.0f && v.z == 0.0f;
}

inline float sizeOf(const glm::vec3 &v)
{
    return std::abs(v.x) + std::abs(v.y) + std::abs(v.z);
}

// A weighted normal sum in xyz and, in w, the total size of what was added
// (the lengths, or for raw cross products their L1 norms: cheaper, and
// within √3), so that a sum that cancelled can be told from a small one.
using Accumulator = glm::vec4;

constexpr glm::vec3 kLastResort(0.0f, 0.0f, 1.0f);

// The unit normal a sum stands for. A sum of nothing (a position only
// degenerate triangles touch, which are invisible, or none) gets the last
// resort, +Z. A sum that cancelled gives zero: its corners need their
// triangles' normals instead.
inline glm::vec3 resolve(const Accumulator &sum)
{
    if (sum.w == 0.0f)
        return kLastResort;
    const glm::vec3 v(sum);
    const float length = std::sqrt(glm::dot(v, v));
    return length > kCancelled * sum.w && length > kTiny && length <= kHuge ? v / length
                                                                            : glm::vec3(0.0f);
}

// The angle atan2(y, x) for y ≥ 0, as between two edges with cross
// product length y and dot product x: accurate for tiny and near-straight
// angles, where acos of a normalised dot is not. atan on [0, 1] is a
// degree-15 odd polynomial (a Lawson-weighted least-squares fit within
// 6e-8), evaluated by Estrin's scheme for a short dependency chain; the
// octant folding uses selects, not branches, so loops of it vectorise.
// Within 4e-7 rad of the exact angle; the library's atan2f, in its place,
// took most of the angle-weighted loop's time.
inline float angleBetween(float y, float x)
{
    const float ax = std::abs(x);
    const float lo = std::min(ax, y), hi = std::max(ax, y);
    const float t = lo / std::max(hi, kTiny);
    const float z = t * t, z2 = z * z, z4 = z2 * z2;
    const float atanT = t
        * ((0.999999336f - 0.333298608f * z) + z2 * (0.199465661f - 0.139086307f * z)
           + z4
               * ((0.0964219876f - 0.0559123329f * z) + z2 * (0.0218629554f - 0.00405456518f * z)));
    const float steep = y > ax ? 1.0f : 0.0f, obtuse = x < 0.0f ? 1.0f : 0.0f;
    const float acute = steep * (kPi / 2) + (1.0f - 2.0f * steep) * atanT;
    return obtuse * kPi + (1.0f - 2.0f * obtuse) * acute;
}

// The normal for a corner whose own sum cancelled: its triangle's.
inline glm::vec3 fallbackNormal(std::span<const glm::vec3> positions,
                                std::span<const std::uint32_t> triangles, std::size_t corner)
{
    const std::size_t base = corner - corner % 3;
    const glm::vec3 &a = positions[triangles[base]];
    const glm::vec3 face = normalizedOrZero(
        glm::cross(positions[triangles[base + 1]] - a, positions[triangles[base + 2]] - a));
    return isZero(face) ? kLastResort : face;
}

} // namespace phonglab::normals
