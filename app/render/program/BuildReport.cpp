#include "BuildReport.h"

#include <algorithm>

namespace phonglab {

bool BuildReport::hasErrors() const
{
    return std::any_of(diagnostics.begin(), diagnostics.end(),
                       [](const ShaderDiagnostic &d) { return d.isError(); });
}

QStringList BuildReport::formatted() const
{
    QStringList lines;
    for (const ShaderDiagnostic &d : diagnostics)
        lines << d.format();
    return lines;
}

QString BuildReport::errorSummary() const
{
    return formatted().join(QLatin1Char('\n'));
}

} // namespace phonglab
