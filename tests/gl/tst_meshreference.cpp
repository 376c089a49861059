// GPU renders of real meshes (the default scene: Blender tree and cloud)
// against the CPU mesh reference, which ray-casts the same full-resolution
// triangles with interpolated normals in double precision. Same bound as the
// analytic references (RenderCheck.h); deliberately wrong variants must fail
// the very same comparison.
#include "RenderCheck.h"
#include "core/reference/MeshRaycaster.h"
#include "core/reference/ReferenceEdges.h"
#include "core/scene/SceneJson.h"
#include "mesh/loading/SceneMeshes.h"
#include "render/draw/OffscreenRenderer.h"
#include "render/gl/GlFormat.h"
#include "render/gl/QtImages.h"

#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QTest>

using namespace phonglab;
using namespace phonglab::test;

namespace {

using MeshPtr = std::shared_ptr<const MeshData>;

Scene defaultScene()
{
    const QString path = QStringLiteral(PHONGLAB_SOURCE_DIR "/assets/scenes/default.json");
    const SceneLoadResult loaded = loadSceneFile(path);
    if (!loaded.ok())
        qFatal("%s: %s", qPrintable(path), qPrintable(loaded.error));
    return *loaded.scene;
}

// The same triangles, each with its own three vertices carrying the
// geometric face normal: what the reference would see if it ignored the
// vertex normals (the "wrong" reference).
MeshPtr withFaceNormals(const MeshData &mesh)
{
    auto flat = std::make_shared<MeshData>();
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const glm::vec3 a = mesh.positions[mesh.indices[i]],
                        b = mesh.positions[mesh.indices[i + 1]],
                        c = mesh.positions[mesh.indices[i + 2]];
        const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
        for (const glm::vec3 &p : {a, b, c}) {
            flat->indices.push_back(std::uint32_t(flat->positions.size()));
            flat->positions.push_back(p);
            flat->normals.push_back(n);
        }
    }
    return flat;
}

struct Variant {
    std::optional<ShadingMethod> gpuShading; // scene.shading when unset
    ReferenceShading reference = ReferenceShading::Phong;
    bool referenceWithFaceNormals = false;
    int side = kTestImageSide;
};

// Renders `scene` offscreen with the meshes loadSceneMeshes gives and
// ray-casts the very same MeshData (kept here before the renderer frees its
// copies after upload) with raycastSceneMeshes.
RenderCheck checkMeshScene(const Scene &scene, const Variant &variant)
{
    RenderCheck check;
    SceneMeshes meshes = loadSceneMeshes(scene);
    if (!meshes.ok()) {
        check.error = meshes.error;
        return check;
    }
    std::vector<MeshPtr> perObject;
    for (const SceneObject &object : scene.objects) {
        const MeshPtr mesh = meshes.entries.value(meshKey(scene, object)).mesh;
        perObject.push_back(variant.referenceWithFaceNormals ? withFaceNormals(*mesh) : mesh);
    }

    OffscreenRenderer offscreen;
    if (const Result<> done = offscreen.create(); !done) {
        check.error = done.error();
        return check;
    }
    Renderer &renderer = offscreen.renderer();
    if (const Result<> done = renderer.setScene(scene, std::move(meshes)); !done) {
        check.error = done.error();
        return check;
    }
    check.compile = renderer.loadShading(variant.gpuShading.value_or(scene.shading));
    if (!check.compile.ok) {
        check.error = QStringLiteral("shaders did not build:\n") + check.compile.errorSummary();
        return check;
    }
    check.gpu = toRgbImage(offscreen.renderImage(QSize(variant.side, variant.side)));
    GLint subpixelBits = 0;
    offscreen.makeCurrent();
    QOpenGLContext::currentContext()->functions()->glGetIntegerv(GL_SUBPIXEL_BITS, &subpixelBits);
    // OpenGL requires at least 4 bits (ambiguousReferencePixels counts
    // fewer as 4 too); snapping moves an edge by at most half a step, so one
    // whole step is a margin of two.
    const double step = std::ldexp(1.0, -std::max(subpixelBits, 4));

    Result<ReferenceImage> reference =
        raycastSceneMeshes(scene, perObject, variant.side, variant.side, variant.reference);
    if (!reference) {
        check.error = reference.error();
        return check;
    }
    // Pixels a rasteriser may legitimately give either surface (a centre
    // within one sub-pixel step of an occluding edge: the outline, or one
    // part of a mesh in front of another, like the tree's tiers) count as
    // uncovered, so the comparison leaves out the same silhouette band
    // around them as around the outer outline.
    const Result<std::vector<std::uint8_t>> ambiguousMask =
        ambiguousReferencePixels(scene, perObject, variant.side, variant.side, subpixelBits);
    if (!ambiguousMask) {
        check.error = ambiguousMask.error();
        return check;
    }
    const std::vector<std::uint8_t> &ambiguous = *ambiguousMask;
    qint64 ambiguousCount = 0;
    for (std::size_t i = 0; i < ambiguous.size(); ++i) {
        if (!ambiguous[i] || !reference->coverage[i])
            continue;
        ++ambiguousCount;
        reference->coverage[i] = 0;
        reference->color[i] = reference->specular[i] = glm::dvec3(0.0);
        reference->depth[i] = std::numeric_limits<double>::infinity();
    }
    qInfo("%d subpixel bits: %lld covered pixels within 1/%g px of an occluding edge", subpixelBits,
          ambiguousCount, 1.0 / step);
    check.referenceData = std::move(*reference);
    check.reference = check.referenceData.toImage(scene.background);
    check.comparison = compareWithReference(check.gpu, check.referenceData, kSilhouetteBandPx);
    return check;
}

} // namespace

class TestMeshReference : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QSurfaceFormat::setDefaultFormat(phonglabSurfaceFormat(0));
        qInfo("bounds: PSNR >= %.1f dB, max error <= %d/255, outside a %d px silhouette band",
              kMinPsnrDb, kMaxErrorSteps, kSilhouetteBandPx);
    }

    void gpuMatchesMeshReference_data()
    {
        QTest::addColumn<int>("method");
        QTest::addColumn<int>("side");
        QTest::newRow("phong 256") << int(ShadingMethod::Phong) << kTestImageSide;
        QTest::newRow("phong 512") << int(ShadingMethod::Phong) << 512;
        QTest::newRow("blinn-phong 256") << int(ShadingMethod::BlinnPhong) << kTestImageSide;
        QTest::newRow("normals 256") << int(ShadingMethod::Normals) << kTestImageSide;
    }

    void gpuMatchesMeshReference()
    {
        QFETCH(int, method);
        QFETCH(int, side);
        Scene scene = defaultScene();
        scene.shading = ShadingMethod(method);
        Variant variant;
        variant.reference = idealShadingFor(scene.shading);
        variant.side = side;
        const RenderCheck check = checkMeshScene(scene, variant);
        QVERIFY2(check.error.isEmpty(), qPrintable(check.error));
        qInfo("tree + cloud, %-12s %dx%d: %s", qPrintable(shadingName(scene.shading)), side, side,
              qPrintable(check.comparison.summary()));
        // A render that compared almost nothing proves nothing.
        QVERIFY2(check.comparison.pixelsCompared > side * side / 25,
                 qPrintable(check.comparison.summary()));
        if (!check.matches())
            QFAIL(qPrintable(QStringLiteral("%1 (images in %2)")
                                 .arg(check.comparison.summary(),
                                      saveArtifacts(QStringLiteral("mesh-reference-%1-%2")
                                                        .arg(shadingName(scene.shading))
                                                        .arg(side),
                                                    check, scene))));
    }

    void wrongVariantsFail_data()
    {
        QTest::addColumn<bool>("faceNormalReference");
        QTest::addColumn<bool>("facetedGpu");
        // The reference ignores the vertex normals (one normal per face),
        // the GPU renders correctly.
        QTest::newRow("reference with face normals") << true << false;
        // The GPU renders with faceted shading, the reference is correct Phong.
        QTest::newRow("GPU with the faceted shader") << false << true;
    }

    void wrongVariantsFail()
    {
        QFETCH(bool, faceNormalReference);
        QFETCH(bool, facetedGpu);
        const Scene scene = defaultScene();
        Variant variant;
        variant.referenceWithFaceNormals = faceNormalReference;
        if (facetedGpu)
            variant.gpuShading = ShadingMethod::Faceted;
        const RenderCheck check = checkMeshScene(scene, variant);
        QVERIFY2(check.error.isEmpty(), qPrintable(check.error));
        qInfo("WRONG %-28s %s", QTest::currentDataTag(), qPrintable(check.comparison.summary()));
        QVERIFY2(check.comparison.pixelsCompared > 0, "nothing compared");
        QVERIFY2(
            !check.matches(),
            qPrintable(QStringLiteral("a wrong variant passed: ") + check.comparison.summary()));
    }
};

QTEST_MAIN(TestMeshReference)
#include "tst_meshreference.moc"
