#include "SceneJson.h"
#include "SceneJsonText.h"
#include "ScenePageJson.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct SceneJsonWriteWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::SceneJsonWrite)
};

namespace {

// Every field is written, defaults included, so a saved file documents the
// whole scene and does not change meaning if a default ever changes.
// Qt writes doubles in shortest round-trip form, so values read back exactly.

QJsonArray vec3Json(const glm::dvec3 &v)
{
    return QJsonArray{v.x, v.y, v.z};
}

QJsonObject transformJson(const Transform &transform)
{
    return QJsonObject{
        {QStringLiteral("translate"), vec3Json(transform.translate)},
        {QStringLiteral("rotate_deg"), vec3Json(transform.rotateDeg)},
        {QStringLiteral("scale"), vec3Json(transform.scale)},
    };
}

QJsonObject materialJson(const Material &material)
{
    return QJsonObject{
        {QStringLiteral("ka"), vec3Json(material.ka)},
        {QStringLiteral("kd"), vec3Json(material.kd)},
        {QStringLiteral("ks"), vec3Json(material.ks)},
        {QStringLiteral("shininess"), material.shininess},
    };
}

QJsonObject cameraJson(const Camera &camera)
{
    QJsonObject json{
        {QStringLiteral("eye"), vec3Json(camera.eye)},
        {QStringLiteral("target"), vec3Json(camera.target)},
        {QStringLiteral("up"), vec3Json(camera.up)},
        {QStringLiteral("fov_deg"), camera.fovDeg},
        {QStringLiteral("near"), camera.nearPlane},
        {QStringLiteral("far"), camera.farPlane},
    };
    if (!camera.frameObjects)
        json.insert(QStringLiteral("frame_objects"), false);
    return json;
}

QJsonObject lightJson(const PointLight &light)
{
    QJsonObject json{
        {QStringLiteral("position"), vec3Json(light.position)},
        {QStringLiteral("diffuse"), vec3Json(light.diffuse)},
        {QStringLiteral("specular"), vec3Json(light.specular)},
        {QStringLiteral("attenuation"), vec3Json(light.attenuation)},
    };
    // Only when not the default, so files without them stay as they were.
    if (!light.name.empty())
        json.insert(QStringLiteral("name"), QString::fromStdString(light.name));
    if (!light.enabled)
        json.insert(QStringLiteral("enabled"), false);
    return json;
}

// The keys one object contributes: inside an "objects" entry, or at the top
// level in the single-object form.
void insertObject(QJsonObject &into, const SceneObject &object)
{
    into.insert(QStringLiteral("mesh"), object.mesh);
    into.insert(QStringLiteral("transform"), transformJson(object.transform));
    into.insert(QStringLiteral("material"), materialJson(object.material));
    if (object.normals != NormalOptions{})
        into.insert(QStringLiteral("normals"), scenejson::normalOptionsJson(object.normals));
    // Only when reduced, so files from before "detail" keep their shape.
    if (object.autoDetail)
        into.insert(QStringLiteral("detail"), QStringLiteral("auto"));
    else if (object.detail != 1.0)
        into.insert(QStringLiteral("detail"), object.detail);
    if (object.shading)
        into.insert(QStringLiteral("shading"), shadingName(*object.shading));
}

} // namespace

QByteArray sceneToJson(const Scene &scene)
{
    QJsonObject root;
    // An object with its own shading needs an "objects" entry: at the top level
    // "shading" is the scene's.
    if (scene.objects.size() == 1 && !scene.objects.front().shading) {
        insertObject(root, scene.objects.front());
    } else {
        QJsonArray objects;
        for (const SceneObject &object : scene.objects) {
            QJsonObject entry;
            insertObject(entry, object);
            objects.append(entry);
        }
        root.insert(QStringLiteral("objects"), objects);
    }
    root.insert(QStringLiteral("camera"), cameraJson(scene.camera));
    root.insert(QStringLiteral("ambient"), vec3Json(scene.ambient));
    QJsonArray lights;
    for (const PointLight &light : scene.lights)
        lights.append(lightJson(light));
    root.insert(QStringLiteral("lights"), lights);
    root.insert(QStringLiteral("format"), kSceneFormat);
    // What desktops recognise a PhongLab scene by (the shared-MIME magic of
    // packaging/org.phonglab.PhongLab.mime.xml), among other JSON files.
    root.insert(QStringLiteral("generator"), QStringLiteral("PhongLab " PHONGLAB_VERSION));
    root.insert(QStringLiteral("shading"), shadingName(scene.shading));
    root.insert(QStringLiteral("background"), vec3Json(scene.background));
    if (!scene.uniforms.empty())
        root.insert(QStringLiteral("uniforms"), scenejson::userUniformsJson(scene.uniforms));
    if (!scene.bindings.empty())
        root.insert(QStringLiteral("bindings"), scenejson::bindingsJson(scene.bindings));
    if (!scene.course.defines.empty())
        root.insert(QStringLiteral("defines"), scenejson::definesJson(scene.course.defines));
    if (scene.course.precision != PrecisionRule::Highp)
        root.insert(QStringLiteral("precision"), precisionRuleKey(scene.course.precision));
    if (!scene.page.empty())
        root.insert(QStringLiteral("page"), scenejson::pageSettingsJson(scene.page));
    if (!scene.vertexShader.isEmpty() || !scene.fragmentShader.isEmpty()) {
        QJsonObject shaders;
        if (!scene.vertexShader.isEmpty())
            shaders.insert(QStringLiteral("vertex"), scene.vertexShader);
        if (!scene.fragmentShader.isEmpty())
            shaders.insert(QStringLiteral("fragment"), scene.fragmentShader);
        root.insert(QStringLiteral("shaders"), shaders);
    }
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

Result<> saveSceneFile(const Scene &scene, const QString &path)
{
    const QByteArray json = sceneToJson(scene);
    // Saving is the one place an invalid in-memory scene could become a file
    // that no longer opens; check it by reading back what would be written.
    const SceneLoadResult check = parseScene(json);
    if (!check.ok())
        return fail(
            SceneJsonWriteWords::tr("refusing to save an invalid scene: %1").arg(check.error));

    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return fail(SceneJsonWriteWords::tr("%1: cannot write scene file (%2)")
                        .arg(path, file.errorString()));
    if (file.write(json) != json.size()) {
        file.cancelWriting();
        return fail(SceneJsonWriteWords::tr("%1: write failed (%2)").arg(path, file.errorString()));
    }
    if (!file.commit())
        return fail(SceneJsonWriteWords::tr("%1: cannot write scene file (%2)")
                        .arg(path, file.errorString()));
    return {};
}

} // namespace phonglab
