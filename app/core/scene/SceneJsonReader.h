#pragma once
// Internal to SceneJson*.cpp: the reader that walks a parsed scene document,
// declared here because it is defined in two files. SceneJson.cpp reads the
// document (its format, objects, shading, shaders and course fields);
// SceneJsonValues.cpp the values inside it (numbers, vectors, colours, a
// mesh name) and the objects a scene is made of (transform, material,
// camera, lights).
#include "SceneJson.h"
#include "SceneJsonText.h"

#include <QCoreApplication>
#include <QJsonObject>
#include <QJsonValue>
#include <QLatin1StringView>

#include <initializer_list>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct SceneWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::SceneJson)
};

namespace scenejson {

// JSON paths in messages: "lights[1].attenuation".
QString childPath(const QString &parent, const QString &key);
QString indexPath(const QString &parent, qsizetype index);
QString number(double value);

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

} // namespace scenejson
} // namespace phonglab
