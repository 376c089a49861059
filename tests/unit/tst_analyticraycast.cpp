// The analytic ray caster: geometry checked against projections worked out by
// hand, shading checked against phongIntensity() at hand-known points.

#include "core/reference/MeshRaycaster.h"
#include "core/reference/PhongReference.h"

#include <QtTest>
#include <cmath>
#include <cstdint>
#include <numbers>

using namespace phonglab;

namespace {

SceneObject object(const QString &mesh, glm::dvec3 scale = glm::dvec3(1.0))
{
    SceneObject o;
    o.mesh = mesh;
    o.transform.scale = scale;
    o.material.ka = {0.2, 0.3, 0.4};
    o.material.kd = {0.6, 0.5, 0.4};
    o.material.ks = {0.5, 0.5, 0.5};
    o.material.shininess = 20.0;
    return o;
}

// One sphere at the origin, camera on +Z at distance 4 (the Camera default),
// one light up and to the right.
Scene sphereScene()
{
    Scene scene;
    scene.objects.push_back(object(QStringLiteral("builtin:sphere")));
    PointLight light;
    light.position = {3.0, 4.0, 5.0};
    scene.lights.push_back(light);
    return scene;
}

std::vector<CameraSpaceLight> cameraLights(const Scene &scene)
{
    std::vector<CameraSpaceLight> lights;
    for (const PointLight &light : scene.lights)
        lights.push_back(toCameraSpace(light, scene.camera.viewMatrix()));
    return lights;
}

bool near(const glm::dvec3 &a, const glm::dvec3 &b, double tol)
{
    return glm::all(glm::lessThanEqual(glm::abs(a - b), glm::dvec3(tol)));
}

ReferenceImage render(const Scene &scene, int w, int h)
{
    const Result<ReferenceImage> image = raycastScene(scene, w, h);
    if (!image)
        qFatal("raycastScene failed: %s", qPrintable(image.error()));
    return *image;
}

// Three builtins turned, scaled and overlapping, two attenuated lights: every
// analytic surface, the nearest-hit rule and every term of the equation.
Scene mixedScene()
{
    Scene scene;
    SceneObject sphere = object(QStringLiteral("builtin:sphere"), glm::dvec3(0.8));
    sphere.transform.translate = {-1.1, 0.3, 0.0};
    SceneObject torus = object(QStringLiteral("builtin:torus"));
    torus.transform.rotateDeg = {60.0, 20.0, 0.0};
    torus.transform.translate = {0.9, -0.2, -0.5};
    SceneObject cube = object(QStringLiteral("builtin:cube"), glm::dvec3(0.5, 0.7, 0.4));
    cube.transform.rotateDeg = {25.0, 40.0, 10.0};
    cube.transform.translate = {0.2, 0.9, 0.6};
    scene.objects = {sphere, torus, cube};
    PointLight key;
    key.position = {3.0, 4.0, 5.0};
    key.attenuation = {1.0, 0.05, 0.01};
    PointLight fill;
    fill.position = {-4.0, -1.0, 2.0};
    fill.diffuse = {0.3, 0.3, 0.5};
    fill.specular = {0.2, 0.2, 0.2};
    scene.lights = {key, fill};
    return scene;
}

// FNV-1a over the 8-bit image and the coverage: what the reference shows.
quint64 imageHash(const ReferenceImage &image)
{
    quint64 h = 1469598103934665603ull;
    const auto add = [&h](std::uint8_t byte) { h = (h ^ byte) * 1099511628211ull; };
    for (std::uint8_t byte : image.toImage({0.1, 0.2, 0.3}).bytes)
        add(byte);
    for (std::uint8_t covered : image.coverage)
        add(covered);
    return h;
}

int coveredInRow(const ReferenceImage &image, int y)
{
    int n = 0;
    for (int x = 0; x < image.width; ++x)
        n += image.covered(x, y);
    return n;
}

} // namespace

class TestAnalyticRaycast : public QObject
{
    Q_OBJECT

private slots:
    // The images the analytic surfaces gave before their ray casting became
    // the triangle meshes' one path (MeshRaycaster): the same rays, hits
    // and shading must give them bit for bit in 8 bits.
    void imagesUnchangedByTheOnePath_data()
    {
        QTest::addColumn<int>("shader");
        QTest::addColumn<quint64>("expected");
        QTest::newRow("phong") << 0 << quint64(4392566288901443761ull);
        QTest::newRow("blinn-phong") << 1 << quint64(10322002333853613776ull);
        QTest::newRow("normals") << 2 << quint64(193999887573511982ull);
        QTest::newRow("normal-matrix + attenuation") << 3 << quint64(1718540188898440815ull);
    }
    void imagesUnchangedByTheOnePath()
    {
        QFETCH(int, shader);
        QFETCH(quint64, expected);
        const ReferenceShader shaders[] = {
            ReferenceShader(ReferenceShading::Phong), ReferenceShader(ReferenceShading::BlinnPhong),
            ReferenceShader(ReferenceShading::Normals),
            ReferenceShader(ReferenceShading::Phong,
                            std::vector<MistakeVariant>{{ShaderMistake::NormalMatrix, 0},
                                                        {ShaderMistake::Attenuation, 0}})};
        const Result<ReferenceImage> image = raycastScene(mixedScene(), 96, 72, shaders[shader]);
        QVERIFY2(image, qPrintable(image.error()));
        QCOMPARE(imageHash(*image), expected);
    }

    void sphereCentrePixel()
    {
        // 101×101: pixel (50, 50) is sampled at ndc (0, 0), straight down -Z.
        // It meets the sphere at world (0, 0, 1) = camera (0, 0, -3), depth 3,
        // where the normal is (0, 0, 1) in both spaces (the view only translates).
        const Scene scene = sphereScene();
        const ReferenceImage image = render(scene, 101, 101);
        QVERIFY(image.covered(50, 50));
        QVERIFY(std::abs(image.depthAt(50, 50) - 3.0) < 1e-12);
        const glm::dvec3 expected =
            phongIntensity({0.0, 0.0, -3.0}, {0.0, 0.0, 1.0}, scene.objects[0].material,
                           scene.ambient, cameraLights(scene));
        QVERIFY(near(image.colorAt(50, 50), expected, 1e-12));
        QVERIFY(!image.covered(0, 0));
    }

    void sphereCentrePixelLitFromTheEye()
    {
        // Light at the eye: L = V = N, so I = Ia·ka + kd + ks exactly:
        // (0.2·0.2 + 0.6 + 0.5, 0.2·0.3 + 0.5 + 0.5, 0.2·0.4 + 0.4 + 0.5) = (1.14, 1.06, 0.98).
        Scene scene = sphereScene();
        scene.lights[0].position = scene.camera.eye;
        const ReferenceImage image = render(scene, 101, 101);
        QVERIFY(near(image.colorAt(50, 50), glm::dvec3(1.14, 1.06, 0.98), 1e-12));
    }

    // A switched-off light lights nothing: the image is that of the others alone.
    void disabledLightIsSkipped()
    {
        Scene scene = sphereScene();
        const ReferenceImage enabledOnly = render(scene, 64, 64);
        PointLight off;
        off.position = {-3.0, 1.0, 4.0};
        off.diffuse = {2.0, 0.5, 0.5};
        off.enabled = false;
        scene.lights.push_back(off);
        QVERIFY(render(scene, 64, 64).color == enabledOnly.color);
        scene.lights.back().enabled = true;
        QVERIFY(render(scene, 64, 64).color != enabledOnly.color);
    }

    void sphereCoverageArea()
    {
        // Sphere of radius 1 seen from distance 4: the tangent cone has
        // sin α = 1/4, tan α = 1/√15. On the image plane at distance 1 the
        // silhouette is a circle of radius 1/√15; in pixels that is
        // (1/√15) / tan(22.5°) · 128 = 79.79 px for 256×256 and a 45° fov,
        // area π·79.79² ≈ 20000 px.
        const ReferenceImage image = render(sphereScene(), 256, 256);
        const double radiusPx = (1.0 / std::sqrt(15.0)) / std::tan(glm::radians(22.5)) * 128.0;
        const double area = std::numbers::pi * radiusPx * radiusPx;
        const double covered = double(image.coveredCount());
        QVERIFY2(std::abs(covered - area) < 0.01 * area,
                 qPrintable(QStringLiteral("covered %1 px, expected %2").arg(covered).arg(area)));
    }

    void torusHoleFromAbove()
    {
        // Camera on +Y at height 4.42 looking down (up = -Z, so camera x = world x
        // and camera y = -world z), 90° fov, 201×201. The top of the tube at
        // world (1, 0.4, 0) is 4.02 below the eye and 1 to the right: ndc.x =
        // 1/4.02 = 50/201, which is the centre of pixel 125 (2·125.5/201 - 1).
        // Its normal is world +Y, i.e. camera +Z (towards the eye).
        Scene scene;
        scene.objects.push_back(object(QStringLiteral("builtin:torus")));
        scene.camera.eye = {0.0, 4.42, 0.0};
        scene.camera.up = {0.0, 0.0, -1.0};
        scene.camera.fovDeg = 90.0;
        PointLight light;
        light.position = {2.0, 3.0, 1.0};
        scene.lights.push_back(light);
        const ReferenceImage image = render(scene, 201, 201);

        // The ray down the axis passes through the hole (radius R - r = 0.6).
        QVERIFY(!image.covered(100, 100));
        QVERIFY(
            !image.covered(110, 100)); // ndc.x = 20/201: x ≤ 0.48 for |y| ≤ 0.4, inside the hole
        // Ring hit, both sides.
        QVERIFY(image.covered(125, 100));
        QVERIFY(image.covered(75, 100));
        QVERIFY(image.covered(100, 125));
        QVERIFY2(std::abs(image.depthAt(125, 100) - 4.02) < 1e-9,
                 qPrintable(QString::number(image.depthAt(125, 100), 'g', 17)));
        const glm::dvec3 expected =
            phongIntensity({1.0, 0.0, -4.02}, {0.0, 0.0, 1.0}, scene.objects[0].material,
                           scene.ambient, cameraLights(scene));
        QVERIFY(near(image.colorAt(125, 100), expected, 1e-9));
    }

    void torusIntersection()
    {
        // Down the Y axis at x = 1: first meets the tube top at y = 0.4 (t = 4.6).
        const double R = 1.0, r = 0.4;
        QCOMPARE_LE(
            std::abs(*intersectTorus({{1.0, 5.0, 0.0}, {0.0, -1.0, 0.0}}, 0.0, 100.0, R, r) - 4.6),
            1e-12);
        // Along +X through the centre: outer wall at x = -1.4 (t = 3.6); starting
        // past it (tMin = 4) the next wall is the hole's at x = -0.6 (t = 4.4).
        const Ray alongX{{-5.0, 0.0, 0.0}, {1.0, 0.0, 0.0}};
        QCOMPARE_LE(std::abs(*intersectTorus(alongX, 0.0, 100.0, R, r) - 3.6), 1e-12);
        QCOMPARE_LE(std::abs(*intersectTorus(alongX, 4.0, 100.0, R, r) - 4.4), 1e-12);
        // A non-unit direction scales t: same ray, twice as fast.
        QCOMPARE_LE(
            std::abs(*intersectTorus({{-5.0, 0.0, 0.0}, {2.0, 0.0, 0.0}}, 0.0, 100.0, R, r) - 1.8),
            1e-12);
        // Down the axis: through the hole.
        QVERIFY(!intersectTorus({{0.0, 5.0, 0.0}, {0.0, -1.0, 0.0}}, 0.0, 100.0, R, r));
        // Normal at the outer equator and at the tube top.
        QVERIFY(near(torusNormal({1.4, 0.0, 0.0}, R), {1.0, 0.0, 0.0}, 1e-15));
        QVERIFY(near(torusNormal({0.0, 0.4, -1.0}, R), {0.0, 1.0, 0.0}, 1e-15));
    }

    void ellipsoidSilhouetteWidth()
    {
        // Sphere scaled (2, 1, 1): in the plane y = 0 the ellipse x²/4 + z² = 1
        // seen from (0, 4). Lines x = k(4 - z) touch it when the quadratic
        // (k²/4 + 1)z² - 2k²z + 4k² - 1 = 0 has a double root:
        // k⁴ - (k²/4 + 1)(4k² - 1) = 0 -> k² = 4/15. So the half-width on the
        // image plane is 2/√15, twice the sphere's 1/√15, while the height
        // stays 1/√15. With a 60° fov on 257×257 pixels: ndc half-width
        // (2/√15)/tan 30° = 0.894, i.e. 0.894·128.5 = 114.9 px either side.
        Scene scene = sphereScene();
        scene.objects[0].transform.scale = {2.0, 1.0, 1.0};
        scene.camera.fovDeg = 60.0;
        const ReferenceImage image = render(scene, 257, 257);
        const double tanHalf = std::tan(glm::radians(30.0));
        const double halfWidthPx = (2.0 / std::sqrt(15.0)) / tanHalf * 128.5;
        const double halfHeightPx = (1.0 / std::sqrt(15.0)) / tanHalf * 128.5;
        QVERIFY(std::abs(coveredInRow(image, 128) - 2.0 * halfWidthPx) <= 2.0);
        int column = 0;
        for (int y = 0; y < image.height; ++y)
            column += image.covered(128, y);
        QVERIFY(std::abs(column - 2.0 * halfHeightPx) <= 2.0);
    }

    void ellipsoidShadingUsesTheNormalMatrix()
    {
        // Same ellipsoid, camera at (0, 0, 4). The object point (1/√2, 0, 1/√2)
        // lands on world/camera-relative point q = (√2, 0, 1/√2), camera
        // (√2, 0, 1/√2 - 4). Its true normal is the gradient (x/4, y, z) =
        // (√2/4, 0, 1/√2); transforming the object normal with the model-view
        // matrix would give (√2, 0, 1/√2) instead.
        // The fov is chosen so q lies on a pixel centre: on 198×199 pixel
        // (148, 99) has ndc (0.5, 0), so tan(fov/2)·aspect must be
        // 2·√2/(4 - 1/√2).
        Scene scene = sphereScene();
        scene.objects[0].transform.scale = {2.0, 1.0, 1.0};
        // Light roughly along the true normal: N·L ≈ 1 with the right normal,
        // ≈ 0.83 with the skewed one, a diffuse difference of about 0.1.
        scene.lights[0].position = {3.0, 0.0, 3.5};
        const double s = 1.0 / std::sqrt(2.0);
        const double xOverDepth = std::sqrt(2.0) / (4.0 - s);
        const double aspect = 198.0 / 199.0;
        scene.camera.fovDeg = glm::degrees(2.0 * std::atan(2.0 * xOverDepth / aspect));
        const ReferenceImage image = render(scene, 198, 199);

        const glm::dvec3 position(std::sqrt(2.0), 0.0, s - 4.0);
        QVERIFY(std::abs(image.depthAt(148, 99) - (4.0 - s)) < 1e-9);
        const Material &m = scene.objects[0].material;
        const auto lights = cameraLights(scene);
        const glm::dvec3 right =
            phongIntensity(position, {std::sqrt(2.0) / 4.0, 0.0, s}, m, scene.ambient, lights);
        const glm::dvec3 wrong =
            phongIntensity(position, {std::sqrt(2.0), 0.0, s}, m, scene.ambient, lights);
        QVERIFY(near(image.colorAt(148, 99), right, 1e-9));
        QVERIFY(!near(right, wrong, 0.05)); // the case would catch a wrong normal transform
    }

    void nearAndFarClipping()
    {
        // The sphere spans depths 3..5 on the axis. With near = 3.5 the front
        // cap is clipped and, as on the GPU (no culling), the inside of the
        // back at depth 5 shows. With far = 2.9 nothing is left.
        Scene scene = sphereScene();
        scene.camera.nearPlane = 3.5;
        ReferenceImage image = render(scene, 101, 101);
        QVERIFY(image.covered(50, 50));
        QVERIFY(std::abs(image.depthAt(50, 50) - 5.0) < 1e-12);

        scene.camera.nearPlane = 0.1;
        scene.camera.farPlane = 2.9;
        image = render(scene, 101, 101);
        QCOMPARE(image.coveredCount(), qint64(0));

        // far = 3.5: the tip of the front cap (depth 3) survives; the rim, where
        // the tangent rays touch at depth √15·cos α = 15/4 = 3.75, does not.
        scene.camera.farPlane = 3.5;
        image = render(scene, 101, 101);
        QVERIFY(image.covered(50, 50));
        QVERIFY(std::abs(image.depthAt(50, 50) - 3.0) < 1e-12);
        QVERIFY(image.coveredCount() < render(sphereScene(), 101, 101).coveredCount());
    }

    void nearestObjectWins()
    {
        // A second, smaller sphere in front (centre z = 2, radius 0.5) hides
        // the first on the axis: hit at z = 2.5, depth 1.5.
        Scene scene = sphereScene();
        SceneObject front = object(QStringLiteral("builtin:sphere"), glm::dvec3(0.5));
        front.transform.translate = {0.0, 0.0, 2.0};
        scene.objects.push_back(front);
        const ReferenceImage image = render(scene, 101, 101);
        QVERIFY(std::abs(image.depthAt(50, 50) - 1.5) < 1e-12);
    }

    void unknownMesh()
    {
        Scene scene = sphereScene();
        scene.objects.push_back(object(QStringLiteral("models/bunny.obj")));
        const Result<ReferenceImage> unknown = raycastScene(scene, 32, 32);
        QVERIFY(!unknown);
        QVERIFY2(unknown.error().contains(QStringLiteral("models/bunny.obj")),
                 qPrintable(unknown.error()));
        const Result<ReferenceImage> empty = raycastScene(sphereScene(), 0, 32);
        QVERIFY(!empty);
        QVERIFY2(empty.error().contains(QStringLiteral("0x32")), qPrintable(empty.error()));
    }

    void toImageWritesBackground()
    {
        const Scene scene = sphereScene();
        const ReferenceImage reference = render(scene, 101, 101);
        const glm::dvec3 background(0.1, 0.5, 2.0);
        const RgbImage image = reference.toImage(background);
        QCOMPARE(image.width, 101);
        QCOMPARE(image.height, 101);
        const auto rgb = [&](int x, int y) {
            const std::uint8_t *p = image.pixel(x, y);
            return std::array<int, 3>{p[0], p[1], p[2]};
        };
        QCOMPARE(rgb(0, 0), (std::array<int, 3>{encodeChannel(0.1), 128, 255}));
        const glm::dvec3 &I = reference.colorAt(50, 50);
        QCOMPARE(rgb(50, 50),
                 (std::array<int, 3>{encodeChannel(I.r), encodeChannel(I.g), encodeChannel(I.b)}));
    }
};

QTEST_APPLESS_MAIN(TestAnalyticRaycast)
#include "tst_analyticraycast.moc"
