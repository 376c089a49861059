// True flat shading (shaders/flat.*: the equation once per face, at its
// centroid with its face normal) against the CPU's per-face evaluation
// (shadeSceneFaces), pixel by pixel, with RenderCheck's bound; and the
// deliberately wrong variants that must fail the same comparison: the
// per-fragment faceted shader on the GPU, per-pixel Phong as the reference.
// Also the face layout behind it (FaceLayout.h), which needs no context.
#include "RenderCheck.h"
#include "TestPaths.h"
#include "core/reference/FaceGeometry.h"
#include "core/reference/ReferenceEdges.h"
#include "core/reference/SceneHits.h"
#include "core/scene/SceneJson.h"
#include "mesh/import/BuiltinMeshes.h"
#include "mesh/loading/SceneMeshes.h"
#include "mesh/normals/FaceLayout.h"
#include "render/draw/OffscreenRenderer.h"
#include "render/gl/GlFormat.h"
#include "render/gl/QtImages.h"

#include <QTest>
#include <set>

using namespace phonglab;
using namespace phonglab::test;

namespace {

using MeshPtr = std::shared_ptr<const MeshData>;

// Where a pixel centre lies closer than this (pixels) to an edge of the
// triangle the ray hit, the rasteriser may give the pixel to the neighbour
// across that edge, whose face has another colour: vertices snap to the
// sub-pixel grid (1/256 px here) and edge functions run in float. A
// sixteenth of a pixel is sixteen grid steps.
constexpr double kEdgeMarginPx = 1.0 / 16.0;

// The builtin sphere at a sixteenth of its triangles: faces of several
// pixels, where evaluating once per face and once per pixel differ clearly.
Scene coarseSphere()
{
    Scene s = loadTestScene(QStringLiteral("gl_sphere_one_light"));
    s.objects.front().detail = 1.0 / 16;
    return s;
}

enum class Reference {
    PerFace, // correct: shadeSceneFaces
    Phong,   // wrong: the exact per-pixel equation
};

struct FlatCheck {
    RenderCheck check;
    qint64 edgePixels = 0; // left out beside an edge of their own triangle
};

glm::dvec2 toPixels(const glm::dvec4 &clip, int side)
{
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    return {(ndc.x * 0.5 + 0.5) * side, (0.5 - ndc.y * 0.5) * side};
}

double distanceToSegment(const glm::dvec2 &p, const glm::dvec2 &a, const glm::dvec2 &b)
{
    const glm::dvec2 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

// Whether pixel (x, y)'s centre is within kEdgeMarginPx of an edge of the
// triangle it hit, on screen (the projection's x and y do not depend on the
// depth range, so the camera's own planes serve).
bool besideOwnEdge(const SceneHits &hits, const Scene &scene, int x, int y)
{
    const ReferenceHit &hit = hits.at(x, y);
    const SceneHits::Object &object = hits.objects[std::size_t(hit.object)];
    if (!object.mesh || hit.triangle < 0)
        return false;
    const glm::dmat4 projection = scene.camera.projectionMatrix(1.0);
    glm::dvec2 corner[3];
    for (std::size_t k = 0; k < 3; ++k) {
        const std::uint32_t v = object.mesh->indices[3 * std::size_t(hit.triangle) + k];
        const glm::dvec4 p =
            object.modelView * glm::dvec4(glm::dvec3(object.mesh->positions[v]), 1.0);
        corner[k] = toPixels(projection * p, hits.width);
    }
    const glm::dvec2 centre(x + 0.5, y + 0.5);
    for (int k = 0; k < 3; ++k)
        if (distanceToSegment(centre, corner[k], corner[(k + 1) % 3]) < kEdgeMarginPx)
            return true;
    return false;
}

FlatCheck checkFlat(const Scene &scene, ShadingMethod gpuShading, Reference reference)
{
    const int side = kTestImageSide;
    FlatCheck out;
    RenderCheck &check = out.check;
    SceneMeshes meshes = loadSceneMeshes(scene);
    if (!meshes.ok()) {
        check.error = meshes.error;
        return out;
    }
    std::vector<MeshPtr> perObject;
    for (const SceneObject &object : scene.objects)
        perObject.push_back(meshes.entries.value(meshKey(scene, object)).mesh);

    OffscreenRenderer offscreen;
    if (const Result<> done = offscreen.create(); !done) {
        check.error = done.error();
        return out;
    }
    Renderer &renderer = offscreen.renderer();
    if (const Result<> done = renderer.setScene(scene, std::move(meshes)); !done) {
        check.error = done.error();
        return out;
    }
    check.compile = renderer.loadShading(gpuShading);
    if (!check.compile.ok) {
        check.error = check.compile.errorSummary();
        return out;
    }
    check.gpu = toRgbImage(offscreen.renderImage(QSize(side, side)));
    if (!renderer.drawError().isEmpty()) {
        check.error = renderer.drawError();
        return out;
    }

    const Result<SceneHits> hits = castSceneHits(scene, perObject, side, side);
    const Result<std::vector<std::uint8_t>> ambiguous =
        ambiguousReferencePixels(scene, perObject, side, side, 8);
    if (!hits || !ambiguous) {
        check.error = !hits ? hits.error() : ambiguous.error();
        return out;
    }
    check.referenceData = reference == Reference::PerFace ? shadeSceneFaces(*hits, scene)
                                                          : shadeSceneHits(*hits, scene, {});
    // Occluding edges go into the silhouette band, as in tst_meshreference;
    // a pixel beside an edge of its own triangle is only left out itself
    // (banding it would swallow the whole surface of a fine mesh).
    ReferenceImage &data = check.referenceData;
    std::vector<std::uint8_t> compared(data.color.size(), 1);
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            const std::size_t i = data.index(x, y);
            if (!data.coverage[i])
                continue;
            if ((*ambiguous)[i]) {
                data.coverage[i] = 0;
                data.color[i] = data.specular[i] = glm::dvec3(0.0);
                data.depth[i] = std::numeric_limits<double>::infinity();
            } else if (besideOwnEdge(*hits, scene, x, y)) {
                compared[i] = 0;
                ++out.edgePixels;
            }
        }
    check.reference = data.toImage(scene.background);
    check.comparison =
        compareOutsideBand(check.gpu, data, scene.background, kSilhouetteBandPx, &compared).error;
    return out;
}

Scene defaultScene()
{
    const SceneLoadResult loaded =
        loadSceneFile(sourcePath(QStringLiteral("assets/scenes/default.json")));
    if (!loaded.ok())
        qFatal("default.json: %s", qPrintable(loaded.error));
    return *loaded.scene;
}

} // namespace

class TestFlatShading : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QSurfaceFormat::setDefaultFormat(phonglabSurfaceFormat(0));
        qInfo("bounds: PSNR >= %.1f dB, max error <= %d/255, outside a %d px silhouette band and "
              "%g px of the pixel's own triangle's edges",
              kMinPsnrDb, kMaxErrorSteps, kSilhouetteBandPx, kEdgeMarginPx);
    }

    void faceLayoutGivesEveryTriangleItsOwnProvokingVertex()
    {
        const MeshData mesh = makeUvSphere(24, 12);
        const FaceLayout layout = buildFaceLayout(mesh);
        QCOMPARE(layout.indices.size(), mesh.indices.size());
        QVERIFY(layout.vertexCount() >= mesh.positions.size());
        QVERIFY(layout.vertexCount() < mesh.positions.size() + mesh.triangleCount());
        std::set<std::uint32_t> provoking;
        for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
            const std::uint32_t last = layout.indices[3 * t + 2];
            QVERIFY2(provoking.insert(last).second, "a vertex provokes two triangles");
            // The same triangle, rotated: same positions in the same cyclic order.
            auto position = [&](std::uint32_t v) {
                const float *f =
                    layout.vertices.data() + std::size_t(v) * FaceLayout::kFloatsPerVertex;
                return glm::vec3(f[0], f[1], f[2]);
            };
            std::array<glm::vec3, 3> before, after;
            for (std::size_t k = 0; k < 3; ++k) {
                before[k] = mesh.positions[mesh.indices[3 * t + k]];
                after[k] = position(layout.indices[3 * t + k]);
            }
            const bool rotated = after == before
                || after == std::array{before[1], before[2], before[0]}
                || after == std::array{before[2], before[0], before[1]};
            QVERIFY2(rotated, "a triangle's corners changed or its winding flipped");
            const float *f =
                layout.vertices.data() + std::size_t(last) * FaceLayout::kFloatsPerVertex;
            const FaceGeometry face = faceGeometry(mesh, t);
            QCOMPARE(glm::vec3(f[3], f[4], f[5]), glm::vec3(face.normal));
            QCOMPARE(glm::vec3(f[6], f[7], f[8]), glm::vec3(face.centroid));
        }
    }

    void faceNormalFollowsWinding()
    {
        MeshData mesh;
        mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        mesh.normals = {{0, 0, -1}, {0, 0, -1}, {0, 0, -1}};
        mesh.indices = {0, 1, 2, 0, 2, 1, 0, 0, 1};
        QCOMPARE(glm::normalize(faceGeometry(mesh, 0).normal), glm::dvec3(0, 0, 1));
        QCOMPARE(glm::normalize(faceGeometry(mesh, 1).normal), glm::dvec3(0, 0, -1));
        // Degenerate: no plane, the vertex normals stand in.
        QCOMPARE(glm::normalize(faceGeometry(mesh, 2).normal), glm::dvec3(0, 0, -1));
        QCOMPARE(faceGeometry(mesh, 0).centroid, glm::dvec3(1.0 / 3, 1.0 / 3, 0));
    }

    void gpuMatchesPerFaceReference_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::newRow("sphere") << QStringLiteral("gl_sphere_one_light");
        QTest::newRow("coarse sphere") << QStringLiteral("coarse");
        QTest::newRow("tree + cloud") << QString();
    }

    void gpuMatchesPerFaceReference()
    {
        QFETCH(QString, scene);
        const Scene s = scene.isEmpty()        ? defaultScene()
            : scene == QLatin1String("coarse") ? coarseSphere()
                                               : loadTestScene(scene);
        const FlatCheck flat = checkFlat(s, ShadingMethod::Flat, Reference::PerFace);
        QVERIFY2(flat.check.error.isEmpty(), qPrintable(flat.check.error));
        qInfo("flat vs per-face reference: %s; %lld pixels beside their triangle's edges left out",
              qPrintable(flat.check.comparison.summary()), flat.edgePixels);
        QVERIFY2(flat.check.comparison.pixelsCompared > kTestImageSide * kTestImageSide / 25,
                 qPrintable(flat.check.comparison.summary()));
        if (!flat.check.matches())
            QFAIL(qPrintable(
                QStringLiteral("%1 (images in %2)")
                    .arg(flat.check.comparison.summary(),
                         saveArtifacts(QStringLiteral("flat-%1").arg(QTest::currentDataTag()),
                                       flat.check, s))));
    }

    void wrongVariantsFail_data()
    {
        QTest::addColumn<int>("gpu");
        QTest::addColumn<int>("reference");
        QTest::newRow("faceted GPU, per-face reference")
            << int(ShadingMethod::Faceted) << int(Reference::PerFace);
        QTest::newRow("flat GPU, per-pixel Phong reference")
            << int(ShadingMethod::Flat) << int(Reference::Phong);
    }

    void wrongVariantsFail()
    {
        QFETCH(int, gpu);
        QFETCH(int, reference);
        const FlatCheck flat = checkFlat(coarseSphere(), ShadingMethod(gpu), Reference(reference));
        QVERIFY2(flat.check.error.isEmpty(), qPrintable(flat.check.error));
        qInfo("WRONG %-36s %s", QTest::currentDataTag(),
              qPrintable(flat.check.comparison.summary()));
        QVERIFY(flat.check.comparison.pixelsCompared > 0);
        QVERIFY2(!flat.check.matches(), qPrintable(flat.check.comparison.summary()));
    }
};

QTEST_MAIN(TestFlatShading)
#include "tst_flatshading.moc"
