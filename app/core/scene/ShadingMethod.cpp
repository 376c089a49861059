#include "ShadingMethod.h"

#include "core/support/EnumNames.h"

#include <array>
#include <utility>

namespace phonglab {

namespace {
constexpr std::array kMethods = {
    std::pair{ShadingMethod::Phong, "phong"},
    std::pair{ShadingMethod::BlinnPhong, "blinn-phong"},
    std::pair{ShadingMethod::Gouraud, "gouraud"},
    std::pair{ShadingMethod::Flat, "flat"},
    std::pair{ShadingMethod::Faceted, "faceted"},
    std::pair{ShadingMethod::Normals, "normals"},
};
} // namespace

QString shadingName(ShadingMethod method)
{
    return enumName(kMethods, method);
}

std::optional<ShadingMethod> shadingFromName(const QString &name)
{
    return enumFromName(kMethods, name);
}

QStringList shadingNames()
{
    return enumNames(kMethods);
}

} // namespace phonglab
