#include "NormalOptions.h"

#include "core/support/EnumNames.h"

#include <array>
#include <utility>

namespace phonglab {

namespace {
constexpr std::array kNames = {
    std::pair{NormalMethod::Auto, "auto"},           std::pair{NormalMethod::Flat, "flat"},
    std::pair{NormalMethod::Average, "average"},     std::pair{NormalMethod::AreaWeighted, "area"},
    std::pair{NormalMethod::AngleWeighted, "angle"},
};
} // namespace

QString normalMethodName(NormalMethod method)
{
    return enumName(kNames, method);
}

std::optional<NormalMethod> normalMethodFromName(const QString &name)
{
    return enumFromName(kNames, name);
}

QStringList normalMethodNames()
{
    return enumNames(kNames);
}

} // namespace phonglab
