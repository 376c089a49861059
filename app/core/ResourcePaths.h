#pragma once
#include <QString>

namespace phonglab {

// Where PhongLab finds its shaders and assets at run time. Files on disk win,
// so editing shaders/ takes effect without a rebuild; the copies embedded in
// the binary (":/shaders/...", ":/assets/...") are the fallback.
// Search order: $PHONGLAB_SHADER_DIR / $PHONGLAB_ASSET_DIR, next to the
// executable, ../share/phonglab beside it, the source tree it was built from.
QString shaderPath(const QString &fileName);
QString assetPath(const QString &relativePath);
QString defaultScenePath();

} // namespace phonglab
