#include "CameraPath.h"

#include "core/support/JsonText.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>

#include <algorithm>
#include <cmath>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct CameraPathWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::CameraPath)
};

namespace {

// Rotates v about the unit axis by `angle` (Rodrigues).
glm::dvec3 rotate(const glm::dvec3 &v, const glm::dvec3 &axis, double angle)
{
    return v * std::cos(angle) + glm::cross(axis, v) * std::sin(angle)
        + axis * glm::dot(axis, v) * (1.0 - std::cos(angle));
}

// A camera a view matrix can be made from.
bool viewable(const Camera &c)
{
    const glm::dvec3 view = c.eye - c.target;
    return glm::length(view) > 0.0 && glm::length(glm::cross(view, c.up)) > 0.0;
}

Camera lerp(const Camera &a, const Camera &b, double t)
{
    Camera c = a;
    c.eye = glm::mix(a.eye, b.eye, t);
    c.target = glm::mix(a.target, b.target, t);
    c.up = glm::mix(a.up, b.up, t);
    c.fovDeg = a.fovDeg + (b.fovDeg - a.fovDeg) * t;
    return c;
}

} // namespace

CameraPath orbitPath(const Camera &start, int frames)
{
    CameraPath path{QStringLiteral("orbit"), {}};
    const glm::dvec3 axis = glm::normalize(start.up);
    const glm::dvec3 offset = start.eye - start.target;
    for (int i = 0; i < frames; ++i) {
        const double t = frames > 1 ? double(i) / double(frames - 1) : 0.0;
        Camera c = start;
        c.eye = start.target + (1.0 + 1.5 * t) * rotate(offset, axis, 2.0 * M_PI * t);
        path.cameras.push_back(c);
    }
    return path;
}

CameraPath dollyPath(const Camera &start, const BoundingSphere &scene, int frames)
{
    CameraPath path{QStringLiteral("dolly"), {}};
    const glm::dvec3 offset = start.eye - start.target;
    const double distance = glm::length(offset);
    const glm::dvec3 direction = distance > 0.0 ? offset / distance : glm::dvec3(0, 0, 1);
    const double outside = glm::length(scene.center - start.target) + 1.25 * scene.radius;
    const double nearest = std::max(std::min(outside, distance), 0.1 * distance);
    const double farthest = 32.0 * distance;
    for (int i = 0; i < frames; ++i) {
        const double t = frames > 1 ? double(i) / double(frames - 1) : 0.0;
        Camera c = start;
        const double d = nearest * std::pow(farthest / nearest, t);
        c.eye = start.target + direction * d;
        c.farPlane = std::max(start.farPlane,
                              d + 2.0 * (glm::length(scene.center - start.target) + scene.radius));
        path.cameras.push_back(c);
    }
    return path;
}

namespace {

class PathReader
{
public:
    Result<CameraPath> read(const QByteArray &json, const Camera &start, const QString &name)
    {
        const Result<QJsonDocument> doc = parseJsonText(json);
        if (!doc)
            return fail(doc.error());
        if (!doc->isObject())
            return fail(CameraPathWords::tr("top level: expected a JSON object"));
        const QJsonObject root = doc->object();
        int frames = kDefaultPathFrames;
        if (const QJsonValue f = root.value(QStringLiteral("frames")); !f.isUndefined()) {
            if (!f.isDouble() || f.toDouble() != std::floor(f.toDouble()) || f.toDouble() < 2
                || f.toDouble() > 10000)
                return fail(CameraPathWords::tr("frames: expected a whole number from 2 to 10000"));
            frames = f.toInt();
        }
        const QJsonValue list = root.value(QStringLiteral("keyframes"));
        if (!list.isArray() || list.toArray().size() < 2)
            return fail(
                CameraPathWords::tr("keyframes: expected an array of at least 2 keyframes"));
        std::vector<Camera> keys;
        Camera previous = start;
        const QJsonArray array = list.toArray();
        for (qsizetype i = 0; i < array.size(); ++i) {
            const QString path = QStringLiteral("keyframes[%1]").arg(i);
            if (!array.at(i).isObject())
                return fail(path + CameraPathWords::tr(": expected an object"));
            const QJsonObject key = array.at(i).toObject();
            if (!key.contains(QStringLiteral("eye")))
                return fail(path + CameraPathWords::tr(".eye: required field missing"));
            Camera c = previous;
            if (!vec3(key, QStringLiteral("eye"), path, c.eye)
                || !vec3(key, QStringLiteral("target"), path, c.target)
                || !vec3(key, QStringLiteral("up"), path, c.up))
                return fail(m_error);
            if (const QJsonValue fov = key.value(QStringLiteral("fov_deg")); !fov.isUndefined()) {
                if (!fov.isDouble() || !(fov.toDouble() > 0.0 && fov.toDouble() < 180.0))
                    return fail(path
                                + CameraPathWords::tr(".fov_deg: expected degrees in (0, 180)"));
                c.fovDeg = fov.toDouble();
            }
            if (!viewable(c))
                return fail(
                    path
                    + CameraPathWords::tr(": eye and target coincide, or up is along the view"));
            keys.push_back(c);
            previous = c;
        }
        CameraPath out{name, {}};
        const double segments = double(keys.size() - 1);
        for (int i = 0; i < frames; ++i) {
            const double u = segments * double(i) / double(frames - 1);
            const std::size_t k = std::min(std::size_t(u), keys.size() - 2);
            out.cameras.push_back(lerp(keys[k], keys[k + 1], u - double(k)));
            // Two good keyframes can still pass through a bad camera (eye
            // and target swapping places, up turning over).
            if (!viewable(out.cameras.back()))
                return fail(CameraPathWords::tr("frame %1, between keyframes[%2] and [%3]: eye and "
                                                "target coincide, or up is along the view")
                                .arg(i)
                                .arg(k)
                                .arg(k + 1));
        }
        return out;
    }

private:
    bool vec3(const QJsonObject &key, const QString &field, const QString &path, glm::dvec3 &out)
    {
        const QJsonValue value = key.value(field);
        if (value.isUndefined())
            return true;
        const QJsonArray a = value.toArray();
        // Far beyond any scene, and small enough that differences and
        // squares of them stay finite.
        constexpr double kLargest = 1e150;
        bool ok = value.isArray() && a.size() == 3;
        for (const QJsonValue &v : a)
            ok = ok && v.isDouble() && std::abs(v.toDouble()) <= kLargest;
        if (!ok) {
            m_error = CameraPathWords::tr("%1.%2: expected 3 numbers, each at most 1e150 in size")
                          .arg(path, field);
            return false;
        }
        out = {a.at(0).toDouble(), a.at(1).toDouble(), a.at(2).toDouble()};
        return true;
    }

    QString m_error;
};

} // namespace

Result<CameraPath> parseCameraPath(const QByteArray &json, const Camera &start, const QString &name)
{
    return PathReader().read(json, start, name);
}

Result<CameraPath> loadCameraPath(const QString &file, const Camera &start)
{
    QFile in(file);
    if (!in.open(QIODevice::ReadOnly))
        return fail(
            CameraPathWords::tr("%1: cannot read camera path (%2)").arg(file, in.errorString()));
    // A keyframe file is a few lines; refuse anything huge before reading it.
    if (in.size() > 16 * 1024 * 1024)
        return fail(CameraPathWords::tr("%1: too large for a camera path").arg(file));
    Result<CameraPath> path =
        parseCameraPath(in.readAll(), start, QFileInfo(file).completeBaseName());
    if (!path)
        return fail(QStringLiteral("%1: %2").arg(file, path.error()));
    return path;
}

} // namespace phonglab
