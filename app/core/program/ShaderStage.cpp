#include "ShaderStage.h"

#include <QFileInfo>

namespace phonglab {

QString stageName(ShaderStage stage)
{
    return stage == ShaderStage::Vertex ? QStringLiteral("vertex") : QStringLiteral("fragment");
}

QString stageSuffix(ShaderStage stage)
{
    return stage == ShaderStage::Vertex ? QStringLiteral(".vert") : QStringLiteral(".frag");
}

namespace {

const QStringList kVertexSuffixes{QStringLiteral("vert"), QStringLiteral("vs"),
                                  QStringLiteral("vsh")};
const QStringList kFragmentSuffixes{QStringLiteral("frag"), QStringLiteral("fs"),
                                    QStringLiteral("fsh")};

} // namespace

std::optional<ShaderStage> stageOfSuffix(const QString &path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (kVertexSuffixes.contains(suffix))
        return ShaderStage::Vertex;
    if (kFragmentSuffixes.contains(suffix))
        return ShaderStage::Fragment;
    return std::nullopt;
}

const QStringList &shaderFileSuffixes()
{
    static const QStringList all{
        QStringLiteral("vert"), QStringLiteral("frag"), QStringLiteral("vs"),  QStringLiteral("fs"),
        QStringLiteral("vsh"),  QStringLiteral("fsh"),  QStringLiteral("glsl")};
    return all;
}

bool hasShaderFileSuffix(const QString &path)
{
    return shaderFileSuffixes().contains(QFileInfo(path).suffix().toLower());
}

QString shaderFilePatterns()
{
    QStringList patterns;
    for (const QString &suffix : shaderFileSuffixes())
        patterns << QStringLiteral("*.") + suffix;
    return patterns.join(QLatin1Char(' '));
}

} // namespace phonglab
