#pragma once
#include "ShadingMethod.h"
#include "core/program/ShaderStage.h"

#include <QString>
#include <QStringList>

namespace phonglab {

// Where PhongLab finds its shaders and assets at run time. Files on disk win,
// so editing shaders/ takes effect without a rebuild; the copies embedded in
// the binary (":/shaders/...", ":/assets/...") are the fallback.
// Search order: $PHONGLAB_SHADER_DIR / $PHONGLAB_ASSET_DIR, next to the
// executable, ../share/phonglab beside it (an installed prefix, wherever it
// was moved), and, for executables of the build tree only, the source tree
// they were built from.
QString shaderPath(const QString &fileName);
// The shader a shading method ships for `stage` ("phong.frag", ...): the one
// place that names the shipped files.
QString shippedShaderPath(ShadingMethod method, ShaderStage stage);
// The folders shaderPath() searches, in its order (the embedded copies aside).
QStringList shaderSearchFolders();
QString assetPath(const QString &relativePath);
QString defaultScenePath();
// Whether `path` is one of the shipped example scenes (beside the default
// scene): saving over one would change the examples, so Save asks where.
bool isShippedScene(const QString &path);

} // namespace phonglab
