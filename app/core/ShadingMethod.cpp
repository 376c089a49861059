#include "ShadingMethod.h"

#include <array>
#include <utility>

namespace phonglab {

namespace {
constexpr std::array kMethods = {
    std::pair{ShadingMethod::Phong, "phong"},
    std::pair{ShadingMethod::BlinnPhong, "blinn-phong"},
    std::pair{ShadingMethod::Gouraud, "gouraud"},
    std::pair{ShadingMethod::Flat, "flat"},
    std::pair{ShadingMethod::Normals, "normals"},
};
} // namespace

QString shadingName(ShadingMethod method)
{
    for (const auto &[m, name] : kMethods)
        if (m == method)
            return QString::fromLatin1(name);
    return {};
}

std::optional<ShadingMethod> shadingFromName(const QString &name)
{
    for (const auto &[m, n] : kMethods)
        if (name == QLatin1String(n))
            return m;
    return std::nullopt;
}

QStringList shadingNames()
{
    QStringList names;
    for (const auto &entry : kMethods)
        names << QString::fromLatin1(entry.second);
    return names;
}

} // namespace phonglab
