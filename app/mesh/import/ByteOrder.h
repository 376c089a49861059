#pragma once
#include <cstdint>
#include <string_view>

namespace phonglab {

// The unsigned little-endian integer of `size` bytes (1 to 4) at `at`, as
// binary mesh formats store their counts. The caller has checked that the
// bytes are there.
inline std::uint32_t littleEndian(std::string_view bytes, std::size_t at, int size = 4)
{
    std::uint32_t v = 0;
    for (int i = size - 1; i >= 0; --i)
        v = (v << 8) | static_cast<unsigned char>(bytes[at + std::size_t(i)]);
    return v;
}

} // namespace phonglab
