#pragma once
#include <QtGlobal>

// Time bounds in tests catch a hang or a lost order of magnitude, not speed
// (the benchmarks measure that). Code built with AddressSanitizer runs
// several times slower (scripts/test.sh --sanitize), so bounds scale with it.
namespace phonglab::test {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr int kSanitizerSlowdown = 5;
#else
inline constexpr int kSanitizerSlowdown = 1;
#endif

// `ms` of this build's time: `ms` normally, more under sanitizers.
constexpr qint64 timeBudgetMs(qint64 ms)
{
    return ms * kSanitizerSlowdown;
}

} // namespace phonglab::test
