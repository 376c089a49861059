#include "MeshData.h"

namespace phonglab {

bool MeshData::isValid() const
{
    if (positions.empty() || positions.size() != normals.size() || indices.size() % 3 != 0)
        return false;
    for (std::uint32_t i : indices)
        if (i >= positions.size())
            return false;
    return true;
}

} // namespace phonglab
