#pragma once
// Internal to ObjReader.cpp: the numbers of an OBJ line read in place, with
// a fast path for the short decimals exporters write. Apart so the reader
// stays about lines and faces; inline, as they were, since they run for
// every number of the file.
#include <charconv>
#include <cstdint>
#include <limits>
#include <system_error>

namespace phonglab::objtext {

inline bool isBlank(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

inline const char *skipBlanks(const char *p, const char *e)
{
    while (p < e && isBlank(*p))
        ++p;
    return p;
}

// std::from_chars for what the fast path leaves: long mantissas, large
// exponents, nan, inf. Values beyond float's range become ±inf or 0, which
// repair then handles like any other non-finite coordinate.
inline const char *parseFloatSlow(const char *p, const char *e, float &out)
{
    if (p < e && *p == '+')
        ++p;
    auto [q, ec] = std::from_chars(p, e, out);
    if (ec == std::errc::result_out_of_range) {
        double d = 0.0;
        auto [q2, ec2] = std::from_chars(p, e, d);
        if (ec2 == std::errc::result_out_of_range)
            d = (*p == '-' ? -1.0 : 1.0) * std::numeric_limits<double>::infinity();
        out = float(d);
        q = q2;
    } else if (ec != std::errc()) {
        return nullptr;
    }
    return (q == e || isBlank(*q)) ? q : nullptr;
}

// One number up to the next blank; nullptr when the token is not a number.
// Exporters write short decimals ("-0.123456"): those are read as an integer
// mantissa times an exact power of ten, which double computes correctly
// rounded (Clinger's fast path), at a fraction of from_chars' cost. The
// final float is then within half an ulp, bar double rounding in ties.
inline const char *parseFloat(const char *p, const char *e, float &out)
{
    static constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                        1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                        1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    const char *start = p;
    const bool negative = p < e && *p == '-';
    if (p < e && (*p == '-' || *p == '+'))
        ++p;
    std::uint64_t mantissa = 0;
    int digits = 0; // significant ones, leading zeros not counted
    int exponent = 0;
    bool any = false;
    for (; p < e && unsigned(*p - '0') < 10u; ++p, any = true) {
        if (digits < 19) {
            mantissa = mantissa * 10 + unsigned(*p - '0');
            digits += mantissa != 0;
        } else {
            ++exponent;
        }
    }
    if (p < e && *p == '.') {
        for (++p; p < e && unsigned(*p - '0') < 10u; ++p, any = true) {
            if (digits < 19) {
                mantissa = mantissa * 10 + unsigned(*p - '0');
                digits += mantissa != 0;
                --exponent;
            }
        }
    }
    if (!any)
        return parseFloatSlow(start, e, out);
    if (p < e && (*p == 'e' || *p == 'E')) {
        const char *q = p + 1;
        const bool negativeExponent = q < e && *q == '-';
        if (q < e && (*q == '-' || *q == '+'))
            ++q;
        int value = 0;
        const char *digitsStart = q;
        for (; q < e && unsigned(*q - '0') < 10u; ++q)
            value = value < 10000 ? value * 10 + (*q - '0') : value;
        if (q == digitsStart)
            return nullptr;
        exponent += negativeExponent ? -value : value;
        p = q;
    }
    if (p < e && !isBlank(*p))
        return nullptr;
    if (mantissa > (std::uint64_t(1) << 53) || exponent < -22 || exponent > 22)
        return parseFloatSlow(start, e, out);
    double value = double(mantissa);
    value = exponent < 0 ? value / kPow10[-exponent] : value * kPow10[exponent];
    out = float(negative ? -value : value);
    return p;
}

// A signed integer; saturates far beyond any valid index.
inline const char *parseInt(const char *p, const char *e, std::int64_t &out)
{
    bool negative = false;
    if (p < e && (*p == '-' || *p == '+'))
        negative = *p++ == '-';
    const char *start = p;
    std::int64_t v = 0;
    while (p < e && unsigned(*p - '0') < 10u) {
        v = v < (std::int64_t(1) << 40) ? v * 10 + (*p - '0') : v;
        ++p;
    }
    if (p == start)
        return nullptr;
    out = negative ? -v : v;
    return p;
}

} // namespace phonglab::objtext
