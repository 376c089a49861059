#include "BenchOptions.h"

namespace phonglab {

BenchOptions BenchOptions::quick()
{
    // Under a minute on two cores: a smaller frame and three detail levels.
    BenchOptions options;
    options.size = QSize(400, 300);
    options.details = {1.0, 1.0 / 8, 1.0 / 64};
    return options;
}

BenchOptions BenchOptions::full()
{
    BenchOptions options;
    options.size = QSize(800, 600);
    options.details = {1.0, 1.0 / 2, 1.0 / 4, 1.0 / 8, 1.0 / 16, 1.0 / 32, 1.0 / 64, 1.0 / 256};
    return options;
}

} // namespace phonglab
