#include "RenderCheck.h"

#include "core/reference/MeshRaycaster.h"
#include "core/scene/ResourcePaths.h"
#include "core/scene/SceneJson.h"
#include "mesh/loading/SceneMeshes.h"
#include "render/draw/OffscreenRenderer.h"
#include "render/gl/QtImages.h"

#include <QDir>

#include <QTest>
#include <algorithm>
#include <cmath>

namespace phonglab::test {

namespace {

// The scene's meshes as the renderer would load them, with every mesh's
// vertices replaced by `mesh` when one is given (its stats, hence culling,
// stay those of the object's own mesh).
SceneMeshes meshesFor(const Scene &scene, const std::shared_ptr<const MeshData> &mesh)
{
    SceneMeshes meshes = loadSceneMeshes(scene);
    if (mesh && meshes.ok())
        for (SceneMeshes::Entry &entry : meshes.entries)
            entry.mesh = mesh;
    return meshes;
}

// What an 8-bit target stores for each float pixel; non-finite ones are
// counted and shown magenta.
RgbImage quantised(const std::vector<float> &rgba, const QSize &size, qint64 *nonFinite)
{
    RgbImage image(size.width(), size.height());
    *nonFinite = 0;
    for (std::size_t i = 0; i < image.pixelCount(); ++i) {
        const float *p = &rgba[i * 4];
        const bool finite = std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
        *nonFinite += !finite;
        for (int c = 0; c < 3; ++c)
            image.pixel(i)[c] = finite ? uchar(std::lround(std::clamp(p[c], 0.0f, 1.0f) * 255.0f))
                                       : (c == 1 ? 0 : 255);
    }
    return image;
}

} // namespace

RenderCheck checkAgainstReference(const Scene &scene, const CheckOptions &options)
{
    RenderCheck check;
    OffscreenRenderer offscreen;
    if (const Result<> done = offscreen.create(); !done) {
        check.error = done.error();
        return check;
    }
    Renderer &renderer = offscreen.renderer();
    if (const Result<> done = renderer.setScene(scene, meshesFor(scene, options.meshOverride));
        !done) {
        check.error = done.error();
        return check;
    }
    if (options.vertex || options.fragment) {
        const QString method = shadingName(scene.shading);
        const ShaderSource vs =
            options.vertex.value_or(shippedShader(method + QStringLiteral(".vert")));
        const ShaderSource fs =
            options.fragment.value_or(shippedShader(method + QStringLiteral(".frag")));
        check.compile = renderer.setProgramSources(vs, fs);
    } else {
        check.compile = renderer.loadShading(scene.shading);
    }
    if (!check.compile.ok) {
        check.error = QStringLiteral("shaders did not build:\n") + check.compile.errorSummary();
        return check;
    }
    const QSize size(kTestImageSide, kTestImageSide);
    if (options.floatTarget)
        check.gpu = quantised(offscreen.renderFloatPixels(size), size, &check.nonFinitePixels);
    else
        check.gpu = toRgbImage(offscreen.renderImage(size));

    const ReferenceShading shading = options.reference.value_or(idealShadingFor(scene.shading));
    auto reference = raycastScene(scene, size.width(), size.height(), shading, options.standIns);
    if (!reference) {
        check.error = reference.error();
        return check;
    }
    check.referenceData = std::move(*reference);
    check.reference = check.referenceData.toImage(scene.background);
    check.comparison = compareWithReference(check.gpu, check.referenceData, kSilhouetteBandPx);
    return check;
}

RenderCheck checkAgainstReference(const Scene &scene, const std::optional<ShaderSource> &vertex,
                                  const std::optional<ShaderSource> &fragment,
                                  const QHash<QString, QString> &standIns)
{
    CheckOptions options;
    options.vertex = vertex;
    options.fragment = fragment;
    options.standIns = standIns;
    return checkAgainstReference(scene, options);
}

QString saveArtifacts(const QString &name, const RenderCheck &check, const Scene &scene,
                      const QHash<QString, QString> &standIns)
{
    QString root = qEnvironmentVariable("PHONGLAB_TEST_ARTIFACTS");
    if (root.isEmpty())
        root = QDir::temp().filePath(QStringLiteral("phonglab-test-artifacts"));
    QDir dir(root);
    dir.mkpath(QStringLiteral("."));
    toQImage(check.gpu).save(dir.filePath(name + QStringLiteral("-gpu.png")));
    toQImage(check.reference).save(dir.filePath(name + QStringLiteral("-reference.png")));
    const QString heatmapPath = dir.filePath(name + QStringLiteral("-error.png"));
    if (!check.referenceData.isNull())
        toQImage(errorHeatmap(check.gpu, check.referenceData, kSilhouetteBandPx)).save(heatmapPath);
    else if (const auto reference =
                 raycastScene(scene, check.gpu.width, check.gpu.height, standIns))
        toQImage(errorHeatmap(check.gpu, *reference, kSilhouetteBandPx)).save(heatmapPath);
    return dir.absolutePath();
}

ShaderSource testShader(const QString &relative)
{
    Result<ShaderSource> source =
        ShaderSource::fromFile(QStringLiteral(PHONGLAB_TEST_DATA_DIR "/") + relative);
    if (!source)
        qFatal("%s", qPrintable(source.error()));
    return std::move(*source);
}

ShaderSource shippedShader(const QString &fileName)
{
    Result<ShaderSource> source = ShaderSource::fromFile(shaderPath(fileName));
    if (!source)
        qFatal("%s", qPrintable(source.error()));
    return std::move(*source);
}

Scene loadTestScene(const QString &name)
{
    const QString path =
        QStringLiteral(PHONGLAB_TEST_DATA_DIR "/scenes/") + name + QStringLiteral(".json");
    const SceneLoadResult loaded = loadSceneFile(path);
    if (!loaded.ok())
        qFatal("%s: %s", qPrintable(path), qPrintable(loaded.error));
    return *loaded.scene;
}

} // namespace phonglab::test
