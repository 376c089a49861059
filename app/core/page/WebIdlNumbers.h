#pragma once
// The GL values WebGL makes of a JavaScript number, as WebIDL converts one
// for `unrestricted float`, `long` and `unsigned long`. A captured page's
// uniforms are doubles, and a replay hands them to GL as the browser did.
// A plain C++ cast would be undefined behaviour out of range (a float
// uniform's -3.2 made into an unsigned int, a crafted capture file's 1e300
// made into a float), where WebIDL's answer is defined.
#include <cmath>
#include <cstdint>
#include <limits>

namespace phonglab {

// Rounded to the nearest float; from 2^128 - 2^103 on (FLT_MAX and half its
// last place) the rounding reaches infinity, where a cast may do anything.
inline float webIdlFloat(double x)
{
    constexpr double overflow = 0x1.ffffffp+127;
    if (std::isnan(x))
        return std::numeric_limits<float>::quiet_NaN();
    if (std::abs(x) >= overflow)
        return x > 0 ? std::numeric_limits<float>::infinity()
                     : -std::numeric_limits<float>::infinity();
    return static_cast<float>(x);
}

// ECMAScript's ToUint32: NaN and the infinities are 0, the rest is truncated
// towards zero and taken modulo 2^32.
inline std::uint32_t webIdlUnsignedLong(double x)
{
    if (!std::isfinite(x))
        return 0;
    constexpr double range = 4294967296.0;
    double wrapped = std::fmod(std::trunc(x), range); // exact, in (-2^32, 2^32)
    if (wrapped < 0)
        wrapped += range;
    return static_cast<std::uint32_t>(wrapped);
}

// ECMAScript's ToInt32: ToUint32, read as two's complement.
inline std::int32_t webIdlLong(double x)
{
    return static_cast<std::int32_t>(webIdlUnsignedLong(x));
}

} // namespace phonglab
