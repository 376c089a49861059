#include "CompileResult.h"

#include <algorithm>

namespace phonglab {

bool CompileResult::hasErrors() const
{
    return std::any_of(diagnostics.begin(), diagnostics.end(), [](const ShaderDiagnostic &d) { return d.isError(); });
}

QStringList CompileResult::formatted() const
{
    QStringList lines;
    for (const ShaderDiagnostic &d : diagnostics)
        lines << d.format();
    return lines;
}

QString CompileResult::errorSummary() const
{
    return formatted().join(QLatin1Char('\n'));
}

} // namespace phonglab
