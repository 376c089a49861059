#include "ParetoFront.h"

#include <algorithm>
#include <cmath>

namespace phonglab {

std::vector<int> paretoFront(const std::vector<BenchRow> &rows)
{
    // Rows without a measured time or error (NaN) cannot be compared and
    // are never on the front.
    auto measured = [&](int i) {
        return !std::isnan(rows[i].frameMs) && !std::isnan(rows[i].rmse);
    };

    std::vector<int> order;
    for (int i = 0; i < int(rows.size()); ++i)
        if (measured(i))
            order.push_back(i);
    // By time, then error, then index: whatever can dominate a row comes before it.
    std::sort(order.begin(), order.end(), [&](int a, int b) {
        if (rows[a].frameMs != rows[b].frameMs)
            return rows[a].frameMs < rows[b].frameMs;
        if (rows[a].rmse != rows[b].rmse)
            return rows[a].rmse < rows[b].rmse;
        return a < b;
    });

    // Sweep: a row is dominated exactly when an earlier row has a strictly
    // smaller error, or an equal error at a strictly smaller time. Exact
    // duplicates (same time and error) do not dominate each other.
    std::vector<int> front;
    bool haveBest = false;
    double bestError = 0;     // least error seen so far
    double bestErrorTime = 0; // the least time at which bestError was seen
    for (int i : order) {
        const BenchRow &row = rows[i];
        bool dominated = false;
        if (haveBest) {
            if (bestError < row.rmse)
                dominated = true;
            else if (bestError == row.rmse && bestErrorTime < row.frameMs)
                dominated = true;
        }
        if (!dominated)
            front.push_back(i);
        if (!haveBest || row.rmse < bestError) {
            haveBest = true;
            bestError = row.rmse;
            bestErrorTime = row.frameMs;
        }
    }
    return front;
}

} // namespace phonglab
