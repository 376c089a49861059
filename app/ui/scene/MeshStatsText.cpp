#include "MeshStatsText.h"
#include "core/support/Language.h"

#include <QLocale>
#include <QObject>

namespace phonglab {

namespace {

constexpr int kBoundsDigits = 4; // significant digits: enough to see the shape's proportions

QString pointText(const glm::vec3 &p)
{
    return QStringLiteral("(%1, %2, %3)")
        .arg(sentenceNumber(double(p.x), 'g', kBoundsDigits))
        .arg(sentenceNumber(double(p.y), 'g', kBoundsDigits))
        .arg(sentenceNumber(double(p.z), 'g', kBoundsDigits));
}

} // namespace

QString normalsDescription(const MeshStats &stats, bool builtin)
{
    if (builtin)
        return QObject::tr("analytic (exact)");
    if (stats.normalsFromFile)
        return QObject::tr("from file");
    QString how = normalMethodName(stats.normalMethod);
    if (stats.creaseAngleDeg)
        how += QObject::tr(", crease %1°").arg(sentenceNumber(*stats.creaseAngleDeg, 'g', 6));
    return QObject::tr("computed (%1)").arg(how);
}

QString boundsDescription(const MeshStats &stats)
{
    return QObject::tr("%1 to %2").arg(pointText(stats.boundsMin), pointText(stats.boundsMax));
}

QString surfaceDescription(const MeshStats &stats)
{
    return stats.closed ? QObject::tr("closed") : QObject::tr("open (back faces drawn)");
}

QString countText(qint64 count)
{
    return QLocale().toString(count);
}

QString detailDescription(const MeshStats &stats)
{
    if (stats.detail == 1.0)
        return {};
    return QObject::tr("%1 %: %2 of %3 triangles")
        .arg(QLocale().toString(stats.detail * 100.0, 'g', 4), countText(stats.triangles),
             countText(stats.fullTriangles));
}

} // namespace phonglab
