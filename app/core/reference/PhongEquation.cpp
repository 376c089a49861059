#include "core/reference/PhongEquation.h"

namespace phonglab {

QString phongEquationKey(PhongEquation equation)
{
    return equation == PhongEquation::Slide ? QStringLiteral("slide") : QStringLiteral("guarded");
}

std::optional<PhongEquation> phongEquationFromKey(const QString &key)
{
    if (key == QLatin1StringView("slide"))
        return PhongEquation::Slide;
    if (key == QLatin1StringView("guarded"))
        return PhongEquation::Guarded;
    return std::nullopt;
}

} // namespace phonglab
