#include "TinyObjLoad.h"

#include <tiny_obj_loader.h>
#include <vector>

namespace phonglab::bench {

long long tinyObjCorners(const std::string &path)
{
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warn, err;
    tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, path.c_str(), nullptr, true);
    long long corners = 0;
    for (const auto &s : shapes)
        corners += static_cast<long long>(s.mesh.indices.size());
    return corners;
}

} // namespace phonglab::bench
