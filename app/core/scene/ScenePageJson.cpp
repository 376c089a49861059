#include "ScenePageJson.h"

#include "SceneJsonText.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonObject>

#include <cmath>

namespace phonglab::scenejson {

struct ScenePageJsonWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::ScenePageJson)
};

namespace {

Result<QStringList> readStrings(const QJsonValue &value, const QString &path)
{
    if (value.isUndefined())
        return QStringList{};
    if (!value.isArray())
        return fail(path
                    + ScenePageJsonWords::tr(": expected an array of strings (got %1)")
                          .arg(describeType(value)));
    QStringList out;
    const QJsonArray array = value.toArray();
    for (qsizetype i = 0; i < array.size(); ++i) {
        if (!array[i].isString() || array[i].toString().trimmed().isEmpty())
            return fail(QStringLiteral("%1[%2]").arg(path).arg(i)
                        + ScenePageJsonWords::tr(": expected a string (got %1)")
                              .arg(describeType(array[i])));
        out << array[i].toString();
    }
    return out;
}

} // namespace

Result<PageSettings> readPageSettings(const QJsonValue &value, const QString &path)
{
    if (value.isUndefined())
        return PageSettings{};
    if (!value.isObject())
        return fail(
            path
            + ScenePageJsonWords::tr(": expected an object (got %1)").arg(describeType(value)));
    const QJsonObject o = value.toObject();
    static const QStringList known{QStringLiteral("steps"), QStringLiteral("libraries"),
                                   QStringLiteral("meshes"), QStringLiteral("frame")};
    for (const QString &k : o.keys())
        if (!known.contains(k))
            return fail(path + QLatin1Char('.') + k
                        + ScenePageJsonWords::tr(": unknown key (known: %1)")
                              .arg(known.join(QStringLiteral(", "))));
    PageSettings out;
    Result<QStringList> steps =
        readStrings(o.value(QStringLiteral("steps")), path + QStringLiteral(".steps"));
    if (!steps)
        return fail(steps.error());
    out.steps = *steps;
    Result<QStringList> libraries =
        readStrings(o.value(QStringLiteral("libraries")), path + QStringLiteral(".libraries"));
    if (!libraries)
        return fail(libraries.error());
    out.libraries = *libraries;
    const QJsonValue meshes = o.value(QStringLiteral("meshes"));
    if (!meshes.isUndefined() && !meshes.isString())
        return fail(path + QStringLiteral(".meshes")
                    + ScenePageJsonWords::tr(": expected a folder's path (got %1)")
                          .arg(describeType(meshes)));
    out.meshes = meshes.toString();
    const QJsonValue frame = o.value(QStringLiteral("frame"));
    if (!frame.isUndefined()) {
        const double n = frame.toDouble(-1);
        if (!frame.isDouble() || n != std::floor(n) || n < 1 || n > 600)
            return fail(path + QStringLiteral(".frame")
                        + ScenePageJsonWords::tr(": expected a frame number 1..600 (got %1)")
                              .arg(frame.isDouble() ? QString::number(n) : describeType(frame)));
        out.frame = int(n);
    }
    return out;
}

QJsonValue pageSettingsJson(const PageSettings &settings)
{
    QJsonObject o;
    if (!settings.steps.isEmpty())
        o.insert(QStringLiteral("steps"), QJsonArray::fromStringList(settings.steps));
    if (!settings.libraries.isEmpty())
        o.insert(QStringLiteral("libraries"), QJsonArray::fromStringList(settings.libraries));
    if (!settings.meshes.isEmpty())
        o.insert(QStringLiteral("meshes"), settings.meshes);
    if (settings.frame > 0)
        o.insert(QStringLiteral("frame"), settings.frame);
    return o;
}

} // namespace phonglab::scenejson
