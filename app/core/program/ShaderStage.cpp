#include "ShaderStage.h"

namespace phonglab {

QString stageName(ShaderStage stage)
{
    return stage == ShaderStage::Vertex ? QStringLiteral("vertex") : QStringLiteral("fragment");
}

QString stageSuffix(ShaderStage stage)
{
    return stage == ShaderStage::Vertex ? QStringLiteral(".vert") : QStringLiteral(".frag");
}

} // namespace phonglab
