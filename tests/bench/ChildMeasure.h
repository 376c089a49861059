#pragma once
#include <functional>

namespace phonglab::bench {

// What a piece of work cost in a process of its own, so that its peak
// memory is its own and nothing of an earlier run is warm.
struct ChildSample {
    double ms = -1;          // wall time of `work`; -1: the child gave no answer
    double peakMiB = 0;      // the child's peak resident memory
    double childPeakMiB = 0; // the largest process it waited for (PhongLab's import child)
    long long result = 0;    // what `work` returned, so the work cannot be optimised away
};

// Runs `work` in a forked child and waits for it.
ChildSample measureInChild(const std::function<long long()> &work);

} // namespace phonglab::bench
