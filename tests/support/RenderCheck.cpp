#include "RenderCheck.h"

#include "core/AnalyticRaycaster.h"
#include "core/ResourcePaths.h"
#include "core/SceneJson.h"
#include "render/OffscreenRenderer.h"

#include <QDir>
#include <QTest>

namespace phonglab::test {

RenderCheck checkAgainstReference(const Scene &scene, const std::optional<ShaderSource> &vertex,
                                  const std::optional<ShaderSource> &fragment, const QHash<QString, QString> &standIns)
{
    RenderCheck check;
    OffscreenRenderer offscreen;
    if (!offscreen.create(&check.error))
        return check;
    Renderer &renderer = offscreen.renderer();
    if (!renderer.setScene(scene, &check.error))
        return check;
    if (vertex || fragment) {
        const ShaderSource vs = vertex.value_or(shippedShader(QStringLiteral("phong.vert")));
        const ShaderSource fs = fragment.value_or(shippedShader(QStringLiteral("phong.frag")));
        check.compile = renderer.setProgramSources(vs, fs);
    } else {
        check.compile = renderer.loadShading(scene.shading);
    }
    if (!check.compile.ok) {
        check.error = QStringLiteral("shaders did not build:\n") + check.compile.errorSummary();
        return check;
    }
    const QSize size(kTestImageSide, kTestImageSide);
    check.gpu = offscreen.renderImage(size);

    const auto reference = raycastScene(scene, size.width(), size.height(), &check.error, standIns);
    if (!reference)
        return check;
    check.reference = reference->toImage(scene.background);
    check.comparison = compareWithReference(check.gpu, *reference, kSilhouetteBandPx);
    return check;
}

QString saveArtifacts(const QString &name, const RenderCheck &check, const Scene &scene,
                      const QHash<QString, QString> &standIns)
{
    QString root = qEnvironmentVariable("PHONGLAB_TEST_ARTIFACTS");
    if (root.isEmpty())
        root = QDir::temp().filePath(QStringLiteral("phonglab-test-artifacts"));
    QDir dir(root);
    dir.mkpath(QStringLiteral("."));
    check.gpu.save(dir.filePath(name + QStringLiteral("-gpu.png")));
    check.reference.save(dir.filePath(name + QStringLiteral("-reference.png")));
    if (const auto reference = raycastScene(scene, check.gpu.width(), check.gpu.height(), nullptr, standIns))
        errorHeatmap(check.gpu, *reference, kSilhouetteBandPx).save(dir.filePath(name + QStringLiteral("-error.png")));
    return dir.absolutePath();
}

ShaderSource testShader(const QString &relative)
{
    QString error;
    ShaderSource source = ShaderSource::fromFile(QStringLiteral(PHONGLAB_TEST_DATA_DIR "/") + relative, &error);
    if (!error.isEmpty())
        qFatal("%s", qPrintable(error));
    return source;
}

ShaderSource shippedShader(const QString &fileName)
{
    QString error;
    ShaderSource source = ShaderSource::fromFile(shaderPath(fileName), &error);
    if (!error.isEmpty())
        qFatal("%s", qPrintable(error));
    return source;
}

Scene loadTestScene(const QString &name)
{
    const QString path = QStringLiteral(PHONGLAB_TEST_DATA_DIR "/scenes/") + name + QStringLiteral(".json");
    const SceneLoadResult loaded = loadSceneFile(path);
    if (!loaded.ok())
        qFatal("%s: %s", qPrintable(path), qPrintable(loaded.error));
    return *loaded.scene;
}

} // namespace phonglab::test
