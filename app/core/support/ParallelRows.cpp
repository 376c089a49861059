#include "ParallelRows.h"

#include <algorithm>
#include <atomic>
#include <system_error>
#include <thread>
#include <vector>

namespace phonglab {

bool forEachRowInParallel(int height, const std::function<void(int)> &rowFunction,
                          const std::function<bool(double)> &progress)
{
    // Rows are handed out one at a time from a shared counter (rows differ
    // a lot in cost: empty sky against dense foliage). The calling thread
    // works too and is the only one that calls progress().
    std::atomic<int> nextRow{0};
    std::atomic<int> rowsDone{0};
    std::atomic<bool> cancelled{false};
    const auto work = [&](bool reports) {
        for (;;) {
            if (cancelled.load(std::memory_order_relaxed))
                return;
            const int y = nextRow.fetch_add(1, std::memory_order_relaxed);
            if (y >= height)
                return;
            rowFunction(y);
            const int done = rowsDone.fetch_add(1, std::memory_order_relaxed) + 1;
            if (reports && progress && !progress(double(done) / double(height)))
                cancelled = true;
        }
    };
    const int threadCount = int(std::max(1u, std::thread::hardware_concurrency()));
    std::vector<std::thread> helpers;
    for (int i = 1; i < std::min(threadCount, height); ++i) {
        try {
            helpers.emplace_back(work, false);
        } catch (const std::system_error &) {
            break; // no more threads to be had: fewer helpers, same image
        }
    }
    work(true);
    for (std::thread &helper : helpers)
        helper.join();
    return !cancelled;
}

} // namespace phonglab
