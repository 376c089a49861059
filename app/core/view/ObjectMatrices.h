#pragma once
#include <glm/glm.hpp>

namespace phonglab {

// The matrices one object is drawn with. Positions go to camera space with
// modelView; normals with normalMatrix, the inverse transpose of modelView's
// upper 3×3 (modelView itself would skew normals under non-uniform scale).
struct ObjectMatrices {
    glm::dmat4 model{1.0};
    glm::dmat4 view{1.0};
    glm::dmat4 modelView{1.0};
    glm::dmat3 normalMatrix{1.0};
    glm::dmat4 projection{1.0};

    // A mirroring transform (det < 0) turns counter-clockwise triangles
    // clockwise on screen: the front faces of this object wind the other way.
    bool mirrors() const { return glm::determinant(glm::dmat3(modelView)) < 0.0; }

    static ObjectMatrices make(const glm::dmat4 &model, const glm::dmat4 &view,
                               const glm::dmat4 &projection);
};

} // namespace phonglab
