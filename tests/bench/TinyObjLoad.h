#pragma once
#include <string>

namespace phonglab::bench {

// The peer the importer is measured against: tinyobjloader's LoadObj of
// `path`, triangulated; the number of triangle corners it read, so the
// work cannot be optimised away.
long long tinyObjCorners(const std::string &path);

} // namespace phonglab::bench
