#pragma once
#include <glm/vec3.hpp>

#include <bit>
#include <compare>
#include <cstddef>
#include <cstdint>

namespace phonglab {

// A position or a normal as a key for welding, counting and sorting: its
// exact float bits, with -0 and +0 as one value. "The same vertex" is the
// same number; a file that writes a zero coordinate once as -0 and once as
// 0 (Blender does) has not made two vertices. Every place that asks "is
// this the same position or normal" (welding in MeshBuilder and
// MeshDecimation, the split count in SceneMeshes) uses this key, so they
// all agree on what one vertex is.
struct Vec3Key {
    std::uint32_t x = 0, y = 0, z = 0;

    auto operator<=>(const Vec3Key &) const = default;
};

inline std::uint32_t exactFloatKey(float f)
{
    return std::bit_cast<std::uint32_t>(f == 0.0f ? 0.0f : f);
}

inline Vec3Key vec3Key(const glm::vec3 &v)
{
    return {exactFloatKey(v.x), exactFloatKey(v.y), exactFloatKey(v.z)};
}

struct Vec3KeyHash {
    std::size_t operator()(const Vec3Key &k) const
    {
        std::uint64_t h = k.x * 0x9E3779B97F4A7C15ull;
        h ^= (h >> 29) + k.y * 0xBF58476D1CE4E5B9ull;
        h ^= (h >> 31) + k.z * 0x94D049BB133111EBull;
        return std::size_t(h ^ (h >> 32));
    }
};

} // namespace phonglab
