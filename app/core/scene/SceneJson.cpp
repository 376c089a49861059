#include "SceneJson.h"

#include "core/support/NearestSpelling.h"
#include "SceneJsonText.h"
#include "ScenePaths.h"
#include "core/reference/AnalyticShapes.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>

#include <algorithm>
#include <cmath>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct SceneWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::SceneJson)
};

namespace {

using namespace Qt::Literals::StringLiterals;

using scenejson::describeType;
using scenejson::overflowLiteral;

QString childPath(const QString &parent, const QString &key)
{
    return parent.isEmpty() ? QString(key) : parent + u'.' + key;
}

QString indexPath(const QString &parent, qsizetype index)
{
    return parent + u'[' + QString::number(index) + u']';
}

QString number(double value)
{
    return QString::number(value, 'g', 10);
}

// Walks the document once, stopping at the first error. Every read* treats an
// absent value (QJsonValue::Undefined) as "keep the default", so optional
// fields need no special casing; required fields are checked by the caller.
class SceneReader
{
public:
    SceneLoadResult read(const QJsonDocument &doc, const QString &baseDir);

private:
    bool fail(const QString &path, const QString &reason);
    void warnUnknownKeys(const QJsonObject &object, const QString &path,
                         std::initializer_list<QLatin1StringView> known);

    bool readObject(const QJsonValue &value, const QString &path, QJsonObject &out);
    bool readNumber(const QJsonValue &value, const QString &path, double &out);
    bool readVec3(const QJsonValue &value, const QString &path, glm::dvec3 &out);
    bool readColor(const QJsonValue &value, const QString &path, glm::dvec3 &out);
    bool readMesh(const QJsonValue &value, const QString &path, QString &out);

    bool readTransform(const QJsonValue &value, const QString &path, Transform &out);
    bool readMaterial(const QJsonValue &value, const QString &path, Material &out);
    bool readCamera(const QJsonValue &value, const QString &path, Camera &out);
    bool validateCamera(const Camera &camera, const QString &path);
    bool readLight(const QJsonValue &value, const QString &path, PointLight &out);
    bool readLights(const QJsonValue &value, const QString &path, std::vector<PointLight> &out);
    bool readFormat(const QJsonValue &value, const QString &path);
    bool readShading(const QJsonValue &value, const QString &path, ShadingMethod &out);
    bool readShaderFiles(const QJsonValue &value, const QString &path, Scene &out);
    bool readObjectList(const QJsonValue &value, const QString &path,
                        std::vector<SceneObject> &out);
    bool readSingleObject(const QJsonObject &root, SceneObject &out);
    bool readNormals(const QJsonValue &value, const QString &path, NormalOptions &out);
    bool readUniforms(const QJsonValue &value, const QString &path, scenejson::UserUniforms &out);
    // A field read by a scenejson helper: its value into `out`, or its
    // (already located) error.
    template <typename T> bool take(Result<T> read, T &out)
    {
        if (!read) {
            m_error = read.error();
            return false;
        }
        out = std::move(*read);
        return true;
    }
    bool readDetail(const QJsonValue &value, const QString &path, SceneObject &out);
    bool readObjectShading(const QJsonValue &value, const QString &path, SceneObject &out);
    bool readObjects(const QJsonObject &root, std::vector<SceneObject> &out);

    QString m_error;
    QStringList m_warnings;
    int m_format = 1; // "format"; 1 where the file has none
};

bool SceneReader::fail(const QString &path, const QString &reason)
{
    m_error = path + QStringLiteral(": ") + reason;
    return false;
}

// Unknown keys are usually typos ("fovy" for "fov_deg"); a warning points at
// them without making hand-edited or newer files unloadable.
void SceneReader::warnUnknownKeys(const QJsonObject &object, const QString &path,
                                  std::initializer_list<QLatin1StringView> known)
{
    for (auto it = object.begin(); it != object.end(); ++it) {
        if (std::find(known.begin(), known.end(), it.key()) == known.end())
            m_warnings << childPath(path, it.key()) + SceneWords::tr(": unknown key, ignored");
    }
}

bool SceneReader::readObject(const QJsonValue &value, const QString &path, QJsonObject &out)
{
    if (!value.isObject() || overflowLiteral(value))
        return fail(path, SceneWords::tr("expected an object (got %1)").arg(describeType(value)));
    out = value.toObject();
    return true;
}

bool SceneReader::readNumber(const QJsonValue &value, const QString &path, double &out)
{
    if (value.isUndefined())
        return true;
    if (const auto literal = overflowLiteral(value))
        return fail(path,
                    SceneWords::tr("must be a finite number (got %1, out of range)").arg(*literal));
    if (!value.isDouble())
        return fail(path, SceneWords::tr("expected a number (got %1)").arg(describeType(value)));
    // Qt versions differ on whether 1e999 is a syntax error or inf; refuse inf here too.
    if (!std::isfinite(value.toDouble()))
        return fail(path, SceneWords::tr("must be a finite number (got %1)").arg(value.toDouble()));
    out = value.toDouble();
    return true;
}

bool SceneReader::readVec3(const QJsonValue &value, const QString &path, glm::dvec3 &out)
{
    if (value.isUndefined())
        return true;
    const QString expected = SceneWords::tr("expected an array of 3 numbers");
    if (!value.isArray())
        return fail(path, expected + QStringLiteral(" (got %1)").arg(describeType(value)));
    const QJsonArray array = value.toArray();
    if (array.size() != 3)
        return fail(path, expected + QStringLiteral(" (got %1 elements)").arg(array.size()));
    glm::dvec3 result;
    for (int i = 0; i < 3; ++i) {
        if (!readNumber(array.at(i), indexPath(path, i), result[i]))
            return false;
    }
    out = result;
    return true;
}

// Colours and reflection coefficients: any finite value >= 0 (HDR is fine).
bool SceneReader::readColor(const QJsonValue &value, const QString &path, glm::dvec3 &out)
{
    glm::dvec3 color = out;
    if (!readVec3(value, path, color))
        return false;
    for (int i = 0; i < 3; ++i)
        if (color[i] < 0.0)
            return fail(indexPath(path, i),
                        SceneWords::tr("must be >= 0 (got %1)").arg(number(color[i])));
    out = color;
    return true;
}

bool SceneReader::readMesh(const QJsonValue &value, const QString &path, QString &out)
{
    if (value.isUndefined())
        return fail(path, SceneWords::tr("required field missing"));
    if (!value.isString())
        return fail(path, SceneWords::tr("expected a string (got %1)").arg(describeType(value)));
    if (value.toString().isEmpty())
        return fail(path,
                    SceneWords::tr("must not be empty (give a file path or \"builtin:sphere\")"));
    // A misspelt builtin is the scene's error, at its field, not the mesh loader's.
    if (const QString spec = value.toString();
        spec.startsWith("builtin:"_L1) && !analyticShapeFor(spec))
        return fail(path,
                    SceneWords::tr("unknown builtin mesh '%1'%2; known: %3")
                        .arg(spec, didYouMean(spec, builtinMeshSpecs()),
                             builtinMeshSpecs().join(QStringLiteral(", "))));
    out = value.toString();
    return true;
}

bool SceneReader::readTransform(const QJsonValue &value, const QString &path, Transform &out)
{
    if (value.isUndefined())
        return true;
    QJsonObject object;
    if (!readObject(value, path, object))
        return false;
    warnUnknownKeys(object, path, {"translate"_L1, "rotate_deg"_L1, "scale"_L1});
    Transform transform;
    if (!readVec3(object.value("translate"_L1), childPath(path, "translate"_L1),
                  transform.translate)
        || !readVec3(object.value("rotate_deg"_L1), childPath(path, "rotate_deg"_L1),
                     transform.rotateDeg)
        || !readVec3(object.value("scale"_L1), childPath(path, "scale"_L1), transform.scale))
        return false;
    // A zero scale collapses the mesh and makes the normal matrix singular.
    for (int i = 0; i < 3; ++i)
        if (transform.scale[i] == 0.0)
            return fail(indexPath(childPath(path, "scale"_L1), i), SceneWords::tr("must not be 0"));
    out = transform;
    return true;
}

bool SceneReader::readMaterial(const QJsonValue &value, const QString &path, Material &out)
{
    if (value.isUndefined())
        return true;
    QJsonObject object;
    if (!readObject(value, path, object))
        return false;
    warnUnknownKeys(object, path, {"ka"_L1, "kd"_L1, "ks"_L1, "shininess"_L1});
    Material material;
    if (!readColor(object.value("ka"_L1), childPath(path, "ka"_L1), material.ka)
        || !readColor(object.value("kd"_L1), childPath(path, "kd"_L1), material.kd)
        || !readColor(object.value("ks"_L1), childPath(path, "ks"_L1), material.ks)
        || !readNumber(object.value("shininess"_L1), childPath(path, "shininess"_L1),
                       material.shininess))
        return false;
    // pow(cos, n) with n <= 0 is 1 (or inf) for surfaces facing away from the highlight.
    if (material.shininess <= 0.0)
        return fail(childPath(path, "shininess"_L1),
                    SceneWords::tr("must be > 0 (got %1)").arg(number(material.shininess)));
    out = material;
    return true;
}

bool SceneReader::readCamera(const QJsonValue &value, const QString &path, Camera &out)
{
    if (value.isUndefined())
        return true;
    QJsonObject object;
    if (!readObject(value, path, object))
        return false;
    warnUnknownKeys(
        object, path,
        {"eye"_L1, "target"_L1, "up"_L1, "fov_deg"_L1, "near"_L1, "far"_L1, "frame_objects"_L1});
    Camera camera;
    if (!readVec3(object.value("eye"_L1), childPath(path, "eye"_L1), camera.eye)
        || !readVec3(object.value("target"_L1), childPath(path, "target"_L1), camera.target)
        || !readVec3(object.value("up"_L1), childPath(path, "up"_L1), camera.up)
        || !readNumber(object.value("fov_deg"_L1), childPath(path, "fov_deg"_L1), camera.fovDeg)
        || !readNumber(object.value("near"_L1), childPath(path, "near"_L1), camera.nearPlane)
        || !readNumber(object.value("far"_L1), childPath(path, "far"_L1), camera.farPlane)
        || !validateCamera(camera, path))
        return false;
    if (const QJsonValue frame = object.value("frame_objects"_L1); !frame.isUndefined()) {
        if (!frame.isBool())
            return fail(childPath(path, "frame_objects"_L1),
                        SceneWords::tr("expected true or false (got %1)").arg(describeType(frame)));
        camera.frameObjects = frame.toBool();
    }
    out = camera;
    return true;
}

// Each of these makes the view or projection matrix singular or flipped.
bool SceneReader::validateCamera(const Camera &camera, const QString &path)
{
    if (!(camera.fovDeg > 0.0 && camera.fovDeg < 180.0))
        return fail(
            childPath(path, "fov_deg"_L1),
            SceneWords::tr("must be in (0, 180) degrees (got %1)").arg(number(camera.fovDeg)));
    if (camera.nearPlane <= 0.0)
        return fail(childPath(path, "near"_L1),
                    SceneWords::tr("must be > 0 (got %1)").arg(number(camera.nearPlane)));
    if (camera.farPlane <= camera.nearPlane)
        return fail(childPath(path, "far"_L1),
                    SceneWords::tr("must be greater than near (%1) (got %2)")
                        .arg(number(camera.nearPlane), number(camera.farPlane)));
    if (camera.eye == camera.target)
        return fail(childPath(path, "target"_L1), SceneWords::tr("must differ from eye"));
    const double upLength = glm::length(camera.up);
    if (upLength == 0.0)
        return fail(childPath(path, "up"_L1), SceneWords::tr("must not be the zero vector"));
    const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
    if (glm::length(glm::cross(forward, camera.up / upLength)) < 1e-9)
        return fail(childPath(path, "up"_L1),
                    SceneWords::tr("must not be parallel to the view direction (target - eye)"));
    return true;
}

bool SceneReader::readLight(const QJsonValue &value, const QString &path, PointLight &out)
{
    QJsonObject object;
    if (!readObject(value, path, object))
        return false;
    warnUnknownKeys(
        object, path,
        {"position"_L1, "diffuse"_L1, "specular"_L1, "attenuation"_L1, "name"_L1, "enabled"_L1});
    // A light with no position would silently sit at the origin, inside the object.
    if (!object.contains("position"_L1))
        return fail(childPath(path, "position"_L1), SceneWords::tr("required field missing"));
    PointLight light;
    const QString attenuationPath = childPath(path, "attenuation"_L1);
    if (!readVec3(object.value("position"_L1), childPath(path, "position"_L1), light.position)
        || !readColor(object.value("diffuse"_L1), childPath(path, "diffuse"_L1), light.diffuse)
        || !readColor(object.value("specular"_L1), childPath(path, "specular"_L1), light.specular)
        || !readColor(object.value("attenuation"_L1), attenuationPath, light.attenuation))
        return false;
    // f_att = 1 / (c1 + c2·d + c3·d²) must not divide by zero at any distance.
    const double sum = light.attenuation.x + light.attenuation.y + light.attenuation.z;
    if (sum <= 0.0)
        return fail(attenuationPath,
                    SceneWords::tr("c1 + c2 + c3 must be positive (got %1)").arg(number(sum)));
    if (const QJsonValue name = object.value("name"_L1); !name.isUndefined()) {
        if (!name.isString())
            return fail(childPath(path, "name"_L1),
                        SceneWords::tr("expected a string (got %1)").arg(describeType(name)));
        light.name = name.toString().toStdString();
    }
    if (const QJsonValue enabled = object.value("enabled"_L1); !enabled.isUndefined()) {
        if (!enabled.isBool())
            return fail(
                childPath(path, "enabled"_L1),
                SceneWords::tr("expected true or false (got %1)").arg(describeType(enabled)));
        light.enabled = enabled.toBool();
    }
    out = light;
    return true;
}

bool SceneReader::readLights(const QJsonValue &value, const QString &path,
                             std::vector<PointLight> &out)
{
    if (value.isUndefined())
        return true;
    if (!value.isArray())
        return fail(path, SceneWords::tr("expected an array (got %1)").arg(describeType(value)));
    const QJsonArray array = value.toArray();
    // The shaders have fixed-size light arrays.
    if (array.size() > kMaxLights)
        return fail(path,
                    SceneWords::tr("at most %1 lights are supported (got %2)")
                        .arg(kMaxLights)
                        .arg(array.size()));
    std::vector<PointLight> lights(array.size());
    for (qsizetype i = 0; i < array.size(); ++i)
        if (!readLight(array.at(i), indexPath(path, i), lights[i]))
            return false;
    out = std::move(lights);
    return true;
}

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
                     "precision"_L1, "format"_L1, "generator"_L1});
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
                scene.course.precision);
    if (ok)
        result.scene = std::move(scene);
    else
        result.error = m_error;
    result.warnings = m_warnings;
    return result;
}

} // namespace

SceneLoadResult parseScene(const QByteArray &json, const QString &baseDir)
{
    SceneLoadResult result;
    const Result<QJsonDocument> doc =
        scenejson::parseJsonText(json, &result.errorLine, &result.errorColumn);
    if (!doc) {
        result.error = doc.error();
        return result;
    }
    return SceneReader().read(*doc, baseDir);
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
