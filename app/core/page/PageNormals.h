#pragma once
#include "JavaScriptFinding.h"
#include "PageCapture.h"
#include "core/scene/MeshData.h"

#include <vector>

namespace phonglab {

// The normals a page sent in its VBO against the meshes the course hands
// out (the Blender cloud and tree: phonglab check --meshes DIR). A drawn
// mesh is recognised by its positions (as the file has them); its normals
// are then, vertex by vertex, Blender's exactly, the faces' normals, the
// right directions at another length, the positions again, or something
// else. Each course mesh gets one finding, "missing" when the frame does
// not draw it with normals.
struct CourseMesh {
    QString name; // the file's name, as the finding says it
    MeshData mesh;
};

// Keys: normals-exact, normals-face, normals-not-normalised,
// normals-positions, normals-other, normals-missing.
std::vector<JavaScriptFinding> checkPageNormals(const PageCapture &capture,
                                                const std::vector<CourseMesh> &meshes);

} // namespace phonglab
