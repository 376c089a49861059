#pragma once
#include <cstdint>
#include <fstream>
#include <string>
#include <unistd.h>

// This process's memory as Linux reports it, for the memory benches.
namespace phonglab::bench {

// Resident set size now (/proc/self/statm), bytes.
inline std::int64_t residentBytes()
{
    std::ifstream statm("/proc/self/statm");
    std::int64_t size = 0, resident = 0;
    statm >> size >> resident;
    return resident * std::int64_t(sysconf(_SC_PAGESIZE));
}

// The peak resident set size since the process started or the last
// resetPeakResident() (VmHWM in /proc/self/status), bytes.
inline std::int64_t peakResidentBytes()
{
    std::ifstream status("/proc/self/status");
    std::string key;
    while (status >> key) {
        if (key == "VmHWM:") {
            std::int64_t kib = 0;
            status >> kib;
            return kib * 1024;
        }
        status.ignore(1 << 20, '\n');
    }
    return 0;
}

// Lowers the peak to the current resident size (Linux 4.0+: "5" to
// clear_refs), so a later peakResidentBytes() is the peak of what came
// after. False where the kernel refuses.
inline bool resetPeakResident()
{
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5";
    clear.flush();
    return bool(clear);
}

// The machine's RAM, bytes.
inline std::int64_t physicalMemoryBytes()
{
    return std::int64_t(sysconf(_SC_PHYS_PAGES)) * std::int64_t(sysconf(_SC_PAGESIZE));
}

} // namespace phonglab::bench
