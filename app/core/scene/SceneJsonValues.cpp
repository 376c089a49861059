// The scene reader's values and the objects a scene is made of: numbers,
// vectors, colours and mesh names, each refused with its JSON path, and the
// transform, material, camera and lights built from them. Apart from
// SceneJson.cpp, which walks the document these sit in.
#include "SceneJsonReader.h"

#include "AnalyticShapes.h"
#include "core/support/NearestSpelling.h"

#include <QJsonArray>

#include <algorithm>
#include <cmath>

namespace phonglab::scenejson {

using namespace Qt::Literals::StringLiterals;

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

} // namespace phonglab::scenejson
