#include "NormalOptions.h"

#include <array>
#include <utility>

namespace phonglab {

namespace {
constexpr std::array kNames = {
    std::pair{NormalMethod::Auto, "auto"},
    std::pair{NormalMethod::Flat, "flat"},
    std::pair{NormalMethod::Average, "average"},
    std::pair{NormalMethod::AreaWeighted, "area"},
    std::pair{NormalMethod::AngleWeighted, "angle"},
};
} // namespace

QString normalMethodName(NormalMethod method)
{
    for (const auto &[m, name] : kNames)
        if (m == method)
            return QString::fromLatin1(name);
    return {};
}

std::optional<NormalMethod> normalMethodFromName(const QString &name)
{
    for (const auto &[m, n] : kNames)
        if (name == QLatin1String(n))
            return m;
    return std::nullopt;
}

QStringList normalMethodNames()
{
    QStringList names;
    for (const auto &entry : kNames)
        names << QString::fromLatin1(entry.second);
    return names;
}

} // namespace phonglab
