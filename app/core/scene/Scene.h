#pragma once
#include "Material.h"
#include "NormalOptions.h"
#include "PageSettings.h"
#include "PointLight.h"
#include "ShadingMethod.h"
#include "Transform.h"
#include "core/program/CoursePrelude.h"
#include "core/program/ShaderBindings.h"
#include "core/view/Camera.h"

#include <QString>
#include <map>
#include <optional>
#include <vector>

namespace phonglab {

// One mesh placed in the world with its own material. `mesh` is kept exactly
// as written in the scene file: "builtin:sphere", "builtin:torus", or a path
// relative to the scene file's folder (see Scene::resolveMeshPath).
struct SceneObject {
    QString mesh;
    Transform transform;
    Material material;
    NormalOptions normals; // how the mesh gets normals (file's, or computed)
    // Fraction of the full triangle count to draw: 1 = the mesh as loaded;
    // < 1 = decimated (files, mesh/detail/MeshDecimation) or tessellated coarser
    // (builtins). In (0, 1]. Lets the bench store the level of detail a
    // scene needs.
    double detail = 1.0;
    // "detail": "auto": drawn at the level of detail its size on screen
    // allows (DetailSelection.h), from levels built for it (DetailLevels.h);
    // `detail` is then 1.
    bool autoDetail = false;
    // Its own shading method ("shading" in an "objects" entry); the scene's
    // when unset. Per-object fits to an error budget write it.
    std::optional<ShadingMethod> shading;

    bool operator==(const SceneObject &) const = default;
};

struct Scene {
    std::vector<SceneObject> objects;
    Camera camera;
    glm::dvec3 ambient{0.2, 0.2, 0.2}; // Ia
    std::vector<PointLight> lights;
    ShadingMethod shading = ShadingMethod::Phong;
    glm::dvec3 background{0.08, 0.08, 0.1};
    // Optional "shaders": files that replace the shading method's shipped
    // ones. Kept exactly as written (relative to the scene file, like meshes;
    // resolve with resolveShaderPath); empty = the shipped file.
    QString vertexShader;
    QString fragmentShader;

    // Values of the shader's own uniforms (those neither the renderer nor
    // the scene's material/lights set), by name as the program knows them
    // ("gain", "tint[1]"); applied to the program once it declares them.
    std::map<QString, std::vector<double>> uniforms;
    // "bindings": what the shader's own names mean, where the user said so
    // (core/ShaderBindings.h); every other name is bound automatically.
    ExplicitBindings bindings;
    // How the course's page compiles the shaders (core/program/CoursePrelude.h):
    // "precision" ("highp", as a desktop browser computes floats, or
    // "as-written") and "defines" ({"NUM_POINT_LIGHTS": "2"}: tokens the
    // page's JavaScript replaces).
    CourseOptions course;
    // "page": how the course's page is run with this scene (core/scene/PageSettings.h).
    PageSettings page;

    // Folder the scene was loaded from; relative mesh paths resolve against it.
    // Not part of the scene's content, so not compared.
    QString baseDir;

    QString resolveMeshPath(const QString &mesh) const;
    QString resolveShaderPath(const QString &shader) const;
    bool operator==(const Scene &other) const;
    // The lights switched on: what the shader and the reference see.
    int enabledLightCount() const;

    // What `object` is drawn with: its own method, else the scene's.
    ShadingMethod shadingOf(const SceneObject &object) const
    {
        return object.shading.value_or(shading);
    }
};

} // namespace phonglab
