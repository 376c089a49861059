// ambiguousReferencePixels: pixel centres within one sub-pixel step of an
// occluding edge are flagged (two overlapping spheres, checked against the
// analytic distance to the front sphere's outline), the smooth interior of a
// surface is not, and neither is a plane seen at a grazing angle, whose depth
// changes fast but continuously. Also: the geometry-only SceneDepthCaster
// gives raycastSceneMeshes()'s depths bit for bit, bad input, and the time
// the mask takes for the default scene at 800x600.
#include "core/reference/MeshRaycaster.h"
#include "core/reference/ReferenceEdges.h"
#include "core/scene/SceneJson.h"
#include "mesh/import/BuiltinMeshes.h"
#include "mesh/loading/SceneMeshes.h"

#include <QtTest>
#include <thread>

using namespace phonglab;

namespace {

using MeshPtr = std::shared_ptr<const MeshData>;

SceneObject sphereObject(const glm::dvec3 &centre, double radius)
{
    SceneObject o;
    o.mesh = QStringLiteral("builtin:sphere");
    o.transform.translate = centre;
    o.transform.scale = glm::dvec3(radius);
    return o;
}

// Sphere A (radius 1 at the origin) and, partly in front of it, sphere B.
Scene twoSpheres()
{
    Scene scene;
    scene.camera.eye = {0.0, 0.0, 6.0};
    scene.objects.push_back(sphereObject({0.0, 0.0, 0.0}, 1.0));
    scene.objects.push_back(sphereObject({0.8, 0.35, 1.5}, 0.6));
    return scene;
}

// The direction of the ray through image point (px, py), as cameraRay() and
// SceneDepthCaster::depthAt() compute it.
glm::dvec3 rayDirection(const Camera &camera, double px, double py, int width, int height)
{
    const double tanHalfFov = std::tan(glm::radians(camera.fovDeg) * 0.5);
    const double ndcX = 2.0 * px / width - 1.0, ndcY = 1.0 - 2.0 * py / height;
    return glm::normalize(
        glm::dvec3(ndcX * tanHalfFov * double(width) / height, ndcY * tanHalfFov, -1.0));
}

// Signed distance in pixels from image point (px, py) to the outline of an
// analytic sphere (negative inside): the angle between the ray and the
// direction to the centre minus the sphere's angular radius, divided by that
// angle's gradient in the image (to first order, which is plenty within a
// few pixels of the outline).
double outlineDistancePx(const Scene &scene, const SceneObject &sphere, double px, double py,
                         int width, int height)
{
    const glm::dvec3 centre(scene.camera.viewMatrix()
                            * glm::dvec4(sphere.transform.translate, 1.0));
    const double radius = sphere.transform.scale.x;
    const double angularRadius = std::asin(radius / glm::length(centre));
    const auto f = [&](double x, double y) {
        const double c =
            glm::dot(rayDirection(scene.camera, x, y, width, height), glm::normalize(centre));
        return std::acos(std::clamp(c, -1.0, 1.0)) - angularRadius;
    };
    const double h = 1e-3;
    const glm::dvec2 gradient((f(px + h, py) - f(px - h, py)) / (2 * h),
                              (f(px, py + h) - f(px, py - h)) / (2 * h));
    return f(px, py) / glm::length(gradient);
}

std::vector<std::uint8_t> mask(const Scene &scene, const std::vector<MeshPtr> &meshes, int w, int h,
                               int bits)
{
    Result<std::vector<std::uint8_t>> m = ambiguousReferencePixels(scene, meshes, w, h, bits);
    if (!m)
        qFatal("ambiguousReferencePixels failed: %s", qPrintable(m.error()));
    return std::move(*m);
}

ReferenceImage reference(const Scene &scene, const std::vector<MeshPtr> &meshes, int w, int h)
{
    Result<ReferenceImage> image = raycastSceneMeshes(scene, meshes, w, h, ReferenceShading::Phong);
    if (!image)
        qFatal("raycastSceneMeshes failed: %s", qPrintable(image.error()));
    return std::move(*image);
}

// Whether every pixel within `radius` of (x, y) (a square) is covered.
bool deepInside(const ReferenceImage &image, int x, int y, int radius)
{
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= image.width || ny >= image.height
                || !image.covered(nx, ny))
                return false;
        }
    return true;
}

} // namespace

class TestReferenceEdges : public QObject
{
    Q_OBJECT

private slots:
    // Sphere B in front of sphere A: the centres within one step of B's
    // outline where A lies behind it (the occlusion edge) are flagged, and
    // nothing farther than a pixel from either outline is.
    void overlappingSpheres_data()
    {
        QTest::addColumn<bool>("mesh");
        QTest::addColumn<int>("bits");
        QTest::addColumn<int>("side");
        QTest::addColumn<int>("minEdgePixels");
        // UV-sphere meshes (the tessellation puts their outline within
        // 0.01 px of the analytic one) with a 1/16 px step: a band wide
        // enough to hold a dozen edge pixels.
        QTest::newRow("uv spheres, 4 bits, 256 px") << true << 4 << 256 << 3;
        // The analytic spheres, exact enough for 1/256 px: few pixel
        // centres are that close to the edge, but none may be missed.
        QTest::newRow("analytic spheres, 8 bits, 512 px") << false << 8 << 512 << 1;
    }

    void overlappingSpheres()
    {
        QFETCH(bool, mesh);
        QFETCH(int, bits);
        QFETCH(int, side);
        QFETCH(int, minEdgePixels);
        const Scene scene = twoSpheres();
        const MeshPtr sphere =
            mesh ? std::make_shared<const MeshData>(makeUvSphere(512, 256)) : nullptr;
        const std::vector<MeshPtr> meshes{sphere, sphere};
        const std::vector<std::uint8_t> ambiguous = mask(scene, meshes, side, side, bits);
        const ReferenceImage image = reference(scene, meshes, side, side);
        const double step = std::ldexp(1.0, -bits);
        // How far the outline may lie from the analytic one, in pixels: a
        // 512x256 UV sphere is inside it by at most ~4e-5 of the radius
        // (B is ~40 px at 256 px); the first-order distance is exact to
        // ~1e-6 px this close to the outline.
        const double slack = mesh ? 0.01 * side / 256.0 : 1e-4;

        qint64 edgePixels = 0, flagged = 0, interior = 0;
        double farthestFlag = 0.0;
        for (int y = 0; y < side; ++y) {
            for (int x = 0; x < side; ++x) {
                const bool flag = ambiguous[image.index(x, y)];
                flagged += flag;
                const double px = x + 0.5, py = y + 0.5;
                const double toA = outlineDistancePx(scene, scene.objects[0], px, py, side, side);
                const double toB = outlineDistancePx(scene, scene.objects[1], px, py, side, side);
                // The occlusion edge: B's outline with A behind it on both
                // sides, the centre within one step of it.
                if (std::abs(toB) < step - slack && toA < -2.0) {
                    ++edgePixels;
                    QVERIFY2(
                        flag,
                        qPrintable(QStringLiteral(
                                       "edge pixel (%1, %2), %3 px from B's outline, not flagged")
                                       .arg(x)
                                       .arg(y)
                                       .arg(toB)));
                }
                // The smooth interior of either sphere (and the background):
                // more than a pixel from both outlines.
                if (std::abs(toA) > 1.0 && std::abs(toB) > 1.0) {
                    interior += image.covered(x, y);
                    QVERIFY2(
                        !flag,
                        qPrintable(QStringLiteral("pixel (%1, %2) flagged, %3 px from A's outline, "
                                                  "%4 px from B's")
                                       .arg(x)
                                       .arg(y)
                                       .arg(toA)
                                       .arg(toB)));
                }
                if (flag)
                    farthestFlag = std::max(farthestFlag, std::min(std::abs(toA), std::abs(toB)));
            }
        }
        qInfo("%s, %d bits, %dx%d: %lld px flagged, the farthest %.4f px from an outline; %lld on "
              "the occlusion "
              "edge (all flagged); %lld covered interior px (none flagged)",
              mesh ? "uv spheres" : "analytic spheres", bits, side, side, flagged, farthestFlag,
              edgePixels, interior);
        QVERIFY2(edgePixels >= minEdgePixels,
                 "the test geometry put too few pixel centres on the occlusion edge");
        QVERIFY(interior > side * side / 10);
        // Only pixels at an outline are flagged; "at" is a little wider than
        // the step, as near its outline a sphere's depth is not smooth at
        // the scale of a step (it grows like the root of the distance).
        QVERIFY2(farthestFlag < 4 * step + slack, qPrintable(QString::number(farthestFlag)));
    }

    // A thin slab (builtin:cube scaled flat) seen from just above its top
    // face, whose depth grows quickly but smoothly towards the far edge: no
    // pixel away from the outline may be flagged. First grazing.json's slab
    // and camera; then a ground plane reaching 500 units away, seen as far
    // as 0.06° from edge-on, where the depth changes by more than 0.1 % over
    // one step in the rows just below the horizon (checked, so that a
    // criterion on the depth itself, rather than on its continuity, would
    // fail here: such rows exist within 0.001/step px of the horizon of any
    // plane large enough).
    void grazingPlane_data()
    {
        QTest::addColumn<bool>("mesh");
        QTest::addColumn<int>("bits");
        QTest::addColumn<double>("halfSize");
        QTest::addColumn<double>("eyeHeight");
        QTest::newRow("grazing.json, analytic box, 8 bits") << false << 8 << 2.5 << 0.55;
        QTest::newRow("grazing.json, cube mesh, 8 bits") << true << 8 << 2.5 << 0.55;
        QTest::newRow("ground plane, analytic box, 8 bits") << false << 8 << 500.0 << 0.55;
        QTest::newRow("ground plane, cube mesh, 8 bits") << true << 8 << 500.0 << 0.55;
        QTest::newRow("ground plane, cube mesh, 4 bits") << true << 4 << 500.0 << 0.55;
    }

    void grazingPlane()
    {
        QFETCH(bool, mesh);
        QFETCH(int, bits);
        QFETCH(double, halfSize);
        QFETCH(double, eyeHeight);
        Scene scene;
        SceneObject slab;
        slab.mesh = QStringLiteral("builtin:cube");
        slab.transform.translate = {0.0, -0.05, 0.0}; // top face at y = 0
        slab.transform.scale = {halfSize, 0.05, halfSize};
        scene.objects.push_back(slab);
        scene.camera.eye = {0.0, eyeHeight, 4.2};
        scene.camera.target = {0.0, 0.0, 0.0};
        scene.camera.farPlane = 2000.0;
        const int w = 320, h = 240;
        const std::vector<MeshPtr> meshes{mesh ? std::make_shared<const MeshData>(makeCube())
                                               : nullptr};
        const std::vector<std::uint8_t> ambiguous = mask(scene, meshes, w, h, bits);
        const ReferenceImage image = reference(scene, meshes, w, h);
        const auto created = SceneDepthCaster::create(scene, meshes, w, h);
        QVERIFY2(created, qPrintable(created.error()));
        const std::unique_ptr<SceneDepthCaster> &caster = *created;
        const double step = std::ldexp(1.0, -bits);

        qint64 inside = 0, flaggedInside = 0, steepInside = 0, flagged = 0;
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const bool flag = ambiguous[image.index(x, y)];
                flagged += flag;
                if (!deepInside(image, x, y, 1))
                    continue;
                ++inside;
                flaggedInside += flag;
                if (flag)
                    qWarning("flagged inside the outline: (%d, %d)", x, y);
                const double d = image.depthAt(x, y);
                steepInside += std::abs(caster->depthAt(x + 0.5, y + 0.5 - step) - d) > 1e-3 * d;
            }
        }
        qInfo(
            "%s, %dx%d: %lld px flagged; %lld px a pixel or more inside the outline, %lld of them "
            "with a depth change > 0.1 %% over one step, %lld flagged",
            QTest::currentDataTag(), w, h, flagged, inside, steepInside, flaggedInside);
        QVERIFY(inside > w * h / 20);
        if (halfSize > 100.0)
            QVERIFY2(steepInside > w, "not grazing enough to test anything");
        // (Flagged pixels on the outline there may well be none: its edges
        // are straight, and few or no pixel centres lie within a step.)
        QCOMPARE(flaggedInside, 0);
    }

    // The geometry-only caster is raycastSceneMeshes() without the shading:
    // the same depth and coverage at every pixel centre, analytic and mesh
    // objects mixed, non-square image.
    void depthCasterMatchesReference()
    {
        Scene scene = twoSpheres();
        scene.objects.push_back(sphereObject({-1.2, -0.6, 0.5}, 0.5));
        scene.objects[2].mesh = QStringLiteral("builtin:torus");
        const MeshPtr sphere = std::make_shared<const MeshData>(makeUvSphere(64, 32));
        const std::vector<MeshPtr> meshes{sphere, nullptr, nullptr};
        const int w = 160, h = 100;
        const ReferenceImage image = reference(scene, meshes, w, h);
        const auto created = SceneDepthCaster::create(scene, meshes, w, h);
        QVERIFY2(created, qPrintable(created.error()));
        const std::unique_ptr<SceneDepthCaster> &caster = *created;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                QCOMPARE(caster->depthAt(x + 0.5, y + 0.5), image.depthAt(x, y));
    }

    void badInputIsAnError()
    {
        const Scene scene = twoSpheres();
        const auto tooFewMeshes = ambiguousReferencePixels(scene, {nullptr}, 32, 32, 8);
        QVERIFY(!tooFewMeshes);
        QVERIFY2(tooFewMeshes.error().contains(QStringLiteral("2 objects but 1 meshes")),
                 qPrintable(tooFewMeshes.error()));
        QVERIFY(!ambiguousReferencePixels(scene, {nullptr, nullptr}, 0, 32, 8));
        QVERIFY(!SceneDepthCaster::create(scene, {nullptr, nullptr}, 32, -1));
        // Fewer bits than OpenGL's minimum count as 4: the same mask.
        QVERIFY(*ambiguousReferencePixels(scene, {nullptr, nullptr}, 64, 48, 0)
                == *ambiguousReferencePixels(scene, {nullptr, nullptr}, 64, 48, 4));
    }

    // What the bench pays per frame size: the default scene (tree + cloud
    // meshes) at 800x600 with the default precision.
    void defaultSceneFlagsFewPixels()
    {
        const QString path = QStringLiteral(PHONGLAB_SOURCE_DIR "/assets/scenes/default.json");
        const SceneLoadResult loaded = loadSceneFile(path);
        QVERIFY2(loaded.ok(), qPrintable(loaded.error));
        const SceneMeshes meshes = loadSceneMeshes(*loaded.scene);
        QVERIFY2(meshes.ok(), qPrintable(meshes.error));
        std::vector<MeshPtr> perObject;
        for (const SceneObject &object : loaded.scene->objects)
            perObject.push_back(meshes.entries.value(meshKey(*loaded.scene, object)).mesh);

        const std::vector<std::uint8_t> ambiguous =
            mask(*loaded.scene, perObject, 800, 600, kDefaultSubpixelBits);
        const ReferenceImage image = reference(*loaded.scene, perObject, 800, 600);
        qint64 flagged = 0, flaggedCovered = 0;
        for (std::size_t i = 0; i < ambiguous.size(); ++i) {
            flagged += ambiguous[i];
            flaggedCovered += ambiguous[i] && image.coverage[i];
        }
        qInfo("default scene 800x600, %d bits: %lld px flagged, %lld of them covered, of %lld "
              "covered",
              kDefaultSubpixelBits, flagged, flaggedCovered, image.coveredCount());
        QVERIFY(flagged > 0);
        QVERIFY(flagged < image.coveredCount() / 20);
    }
};

QTEST_APPLESS_MAIN(TestReferenceEdges)
#include "tst_referenceedges.moc"
