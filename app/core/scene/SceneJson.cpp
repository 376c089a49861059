#include "SceneJson.h"

#include "SceneJsonReader.h"
#include "ScenePageJson.h"
#include "ScenePaths.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>

#include <algorithm>
#include <cmath>

namespace phonglab {

namespace scenejson {

using namespace Qt::Literals::StringLiterals;

bool SceneReader::readFormat(const QJsonValue &value, const QString &path)
{
    if (value.isUndefined())
        return true; // format 1: written before the field existed
    const QString expected = SceneWords::tr("expected a whole number from 1");
    if (const auto literal = overflowLiteral(value))
        return fail(path, expected + QStringLiteral(", got %1").arg(*literal));
    if (!value.isDouble())
        return fail(path, expected + QStringLiteral(", got %1").arg(describeType(value)));
    const double format = value.toDouble();
    if (!(format >= 1.0) || format != std::floor(format))
        return fail(path, expected + QStringLiteral(", got %1").arg(number(format)));
    if (format > kSceneFormat)
        m_warnings << path
                + SceneWords::tr(": %1 is newer than this PhongLab's %2; read as %2, fields it "
                                 "does not know are ignored")
                      .arg(number(format))
                      .arg(kSceneFormat);
    m_format = int(std::min(format, double(kSceneFormat)));
    return true;
}

bool SceneReader::readShading(const QJsonValue &value, const QString &path, ShadingMethod &out)
{
    if (value.isUndefined())
        return true;
    if (!value.isString())
        return fail(path, SceneWords::tr("expected a string (got %1)").arg(describeType(value)));
    // Before format 2, "flat" named the per-fragment shader now called
    // "faceted": an old scene keeps the look it was saved with.
    if (m_format < 2 && value.toString() == "flat"_L1) {
        m_warnings << path
                + SceneWords::tr(": \"flat\" in a scene without \"format\": 2 is the "
                                 "per-fragment shader now called \"faceted\"; loaded as "
                                 "\"faceted\" (saving writes that; write \"format\": 2 for "
                                 "flat shading once per face)");
        out = ShadingMethod::Faceted;
        return true;
    }
    const auto method = shadingFromName(value.toString());
    if (!method)
        return fail(path,
                    SceneWords::tr("unknown shading method \"%1\" (known: %2)")
                        .arg(value.toString(), shadingNames().join(QStringLiteral(", "))));
    out = *method;
    return true;
}

bool SceneReader::readShaderFiles(const QJsonValue &value, const QString &path, Scene &out)
{
    if (value.isUndefined())
        return true;
    QJsonObject object;
    if (!readObject(value, path, object))
        return false;
    warnUnknownKeys(object, path, {"vertex"_L1, "fragment"_L1});
    QString files[2];
    const QLatin1StringView keys[2] = {"vertex"_L1, "fragment"_L1};
    for (int i = 0; i < 2; ++i) {
        const QJsonValue file = object.value(keys[i]);
        if (file.isUndefined())
            continue;
        const QString filePath = childPath(path, keys[i]);
        if (!file.isString())
            return fail(filePath,
                        SceneWords::tr("expected a string (got %1)").arg(describeType(file)));
        if (file.toString().isEmpty())
            return fail(filePath,
                        SceneWords::tr(
                            "must not be empty (give a shader file path, or leave the key out)"));
        files[i] = file.toString();
    }
    out.vertexShader = files[0];
    out.fragmentShader = files[1];
    return true;
}

bool SceneReader::readObjectList(const QJsonValue &value, const QString &path,
                                 std::vector<SceneObject> &out)
{
    if (!value.isArray())
        return fail(path, SceneWords::tr("expected an array (got %1)").arg(describeType(value)));
    const QJsonArray array = value.toArray();
    if (array.isEmpty())
        return fail(path, SceneWords::tr("must list at least one object"));
    std::vector<SceneObject> objects(array.size());
    for (qsizetype i = 0; i < array.size(); ++i) {
        const QString objectPath = indexPath(path, i);
        QJsonObject object;
        if (!readObject(array.at(i), objectPath, object))
            return false;
        warnUnknownKeys(
            object, objectPath,
            {"mesh"_L1, "transform"_L1, "material"_L1, "normals"_L1, "detail"_L1, "shading"_L1});
        if (!readMesh(object.value("mesh"_L1), childPath(objectPath, "mesh"_L1), objects[i].mesh)
            || !readTransform(object.value("transform"_L1), childPath(objectPath, "transform"_L1),
                              objects[i].transform)
            || !readMaterial(object.value("material"_L1), childPath(objectPath, "material"_L1),
                             objects[i].material)
            || !readNormals(object.value("normals"_L1), childPath(objectPath, "normals"_L1),
                            objects[i].normals)
            || !readDetail(object.value("detail"_L1), childPath(objectPath, "detail"_L1),
                           objects[i])
            || !readObjectShading(object.value("shading"_L1), childPath(objectPath, "shading"_L1),
                                  objects[i]))
            return false;
    }
    out = std::move(objects);
    return true;
}

bool SceneReader::readSingleObject(const QJsonObject &root, SceneObject &out)
{
    return readMesh(root.value("mesh"_L1), QStringLiteral("mesh"), out.mesh)
        && readTransform(root.value("transform"_L1), QStringLiteral("transform"), out.transform)
        && readMaterial(root.value("material"_L1), QStringLiteral("material"), out.material)
        && readNormals(root.value("normals"_L1), QStringLiteral("normals"), out.normals)
        && readDetail(root.value("detail"_L1), QStringLiteral("detail"), out);
}

bool SceneReader::readNormals(const QJsonValue &value, const QString &path, NormalOptions &out)
{
    return take(scenejson::readNormalOptions(value, path, out), out);
}

bool SceneReader::readUniforms(const QJsonValue &value, const QString &path,
                               scenejson::UserUniforms &out)
{
    return take(scenejson::readUserUniforms(value, path), out);
}

// A fraction of the full triangle count: 0 would draw nothing, and more
// than the mesh has cannot be made. Or "auto": the view decides.
bool SceneReader::readDetail(const QJsonValue &value, const QString &path, SceneObject &out)
{
    if (value.isUndefined())
        return true;
    if (value.isString() && value.toString() == "auto"_L1) {
        out.autoDetail = true;
        return true;
    }
    const QString expected = SceneWords::tr("expected a number in (0, 1]");
    if (const auto literal = overflowLiteral(value))
        return fail(path, expected + QStringLiteral(", got %1").arg(*literal));
    if (!value.isDouble())
        return fail(path,
                    expected + QStringLiteral(" or \"auto\", got %1").arg(describeType(value)));
    const double detail = value.toDouble();
    if (!(detail > 0.0 && detail <= 1.0))
        return fail(path, expected + QStringLiteral(", got %1").arg(number(detail)));
    out.detail = detail;
    return true;
}

bool SceneReader::readObjectShading(const QJsonValue &value, const QString &path, SceneObject &out)
{
    if (value.isUndefined())
        return true;
    ShadingMethod method = ShadingMethod::Phong;
    if (!readShading(value, path, method))
        return false;
    out.shading = method;
    return true;
}

bool SceneReader::readObjects(const QJsonObject &root, std::vector<SceneObject> &out)
{
    const bool hasMesh = root.contains("mesh"_L1);
    const bool hasObjects = root.contains("objects"_L1);
    if (hasMesh && hasObjects)
        return fail(QStringLiteral("objects"),
                    SceneWords::tr("cannot be combined with \"mesh\" (use one form)"));
    if (!hasMesh && !hasObjects)
        return fail(QStringLiteral("mesh"),
                    SceneWords::tr("required field missing (or give \"objects\")"));
    if (hasObjects) {
        // Top-level transform/material belong to the single-object form only.
        for (const auto key : {"transform"_L1, "material"_L1, "normals"_L1, "detail"_L1})
            if (root.contains(key))
                m_warnings << QString(key)
                        + SceneWords::tr(": ignored with \"objects\" (give each object its own)");
        return readObjectList(root.value("objects"_L1), QStringLiteral("objects"), out);
    }
    SceneObject object;
    if (!readSingleObject(root, object))
        return false;
    out = {object};
    return true;
}

SceneLoadResult SceneReader::read(const QJsonDocument &doc, const QString &baseDir)
{
    SceneLoadResult result;
    if (!doc.isObject()) {
        result.error = SceneWords::tr("top level: expected a JSON object (got array)");
        return result;
    }
    const QJsonObject root = doc.object();
    warnUnknownKeys(root, {},
                    {"mesh"_L1, "objects"_L1, "transform"_L1, "material"_L1, "normals"_L1,
                     "detail"_L1, "camera"_L1, "ambient"_L1, "lights"_L1, "shading"_L1,
                     "background"_L1, "shaders"_L1, "uniforms"_L1, "bindings"_L1, "defines"_L1,
                     "precision"_L1, "page"_L1, "format"_L1, "generator"_L1});
    Scene scene;
    scene.baseDir = baseDir;
    const bool ok = readFormat(root.value("format"_L1), QStringLiteral("format"))
        && readObjects(root, scene.objects)
        && readCamera(root.value("camera"_L1), QStringLiteral("camera"), scene.camera)
        && readColor(root.value("ambient"_L1), QStringLiteral("ambient"), scene.ambient)
        && readLights(root.value("lights"_L1), QStringLiteral("lights"), scene.lights)
        && readShading(root.value("shading"_L1), QStringLiteral("shading"), scene.shading)
        && readColor(root.value("background"_L1), QStringLiteral("background"), scene.background)
        && readShaderFiles(root.value("shaders"_L1), QStringLiteral("shaders"), scene)
        && readUniforms(root.value("uniforms"_L1), QStringLiteral("uniforms"), scene.uniforms)
        && take(scenejson::readBindings(root.value("bindings"_L1), QStringLiteral("bindings")),
                scene.bindings)
        && take(scenejson::readDefines(root.value("defines"_L1), QStringLiteral("defines")),
                scene.course.defines)
        && take(scenejson::readPrecision(root.value("precision"_L1), QStringLiteral("precision")),
                scene.course.precision)
        && take(scenejson::readPageSettings(root.value("page"_L1), QStringLiteral("page")),
                scene.page);
    if (ok)
        result.scene = std::move(scene);
    else
        result.error = m_error;
    result.warnings = m_warnings;
    return result;
}

} // namespace scenejson

SceneLoadResult parseScene(const QByteArray &json, const QString &baseDir)
{
    SceneLoadResult result;
    const Result<QJsonDocument> doc = parseJsonText(json, &result.errorLine, &result.errorColumn);
    if (!doc) {
        result.error = doc.error();
        return result;
    }
    return scenejson::SceneReader().read(*doc, baseDir);
}

SceneLoadResult loadSceneFile(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        SceneLoadResult result;
        result.error = SceneWords::tr("cannot read scene file (%1)").arg(file.errorString());
        return result;
    }
    SceneLoadResult result = parseScene(file.readAll(), QFileInfo(path).absolutePath());
    // A mesh where a scene belongs (`phonglab render tree.obj`): say what to
    // give instead of a JSON syntax error at line 1.
    if (!result.ok() && result.errorLine > 0 && isMeshFile(path)) {
        result.error =
            SceneWords::tr("a mesh, not a scene: name it in one, "
                           "{\"mesh\": \"%1\", \"lights\": [{\"position\": [3, 4, 5]}]}, "
                           "saved as a .json file beside it")
                .arg(QFileInfo(path).fileName());
        result.errorLine = result.errorColumn = 0;
    }
    return result;
}

} // namespace phonglab
