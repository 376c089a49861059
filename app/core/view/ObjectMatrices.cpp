#include "ObjectMatrices.h"

namespace phonglab {

ObjectMatrices ObjectMatrices::make(const glm::dmat4 &model, const glm::dmat4 &view,
                                    const glm::dmat4 &projection)
{
    ObjectMatrices m;
    m.model = model;
    m.view = view;
    m.modelView = view * model;
    m.normalMatrix = glm::transpose(glm::inverse(glm::dmat3(m.modelView)));
    m.projection = projection;
    return m;
}

} // namespace phonglab
