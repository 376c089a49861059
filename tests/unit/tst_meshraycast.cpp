// The mesh reference: the BVH against a brute-force loop over every triangle,
// the mesh ray caster against the analytic one on a finely tessellated sphere,
// the specular channel, bad input, and the time a default-scene frame takes.
#include "core/reference/AnalyticRaycaster.h"
#include "core/reference/ImageMetrics.h"
#include "core/reference/MeshBvh.h"
#include "core/reference/MeshRaycaster.h"
#include "core/scene/SceneJson.h"
#include "mesh/import/BuiltinMeshes.h"
#include "mesh/loading/MeshLoader.h"
#include "mesh/loading/SceneMeshes.h"

#include <QtTest>
#include <random>

using namespace phonglab;

namespace {

using MeshPtr = std::shared_ptr<const MeshData>;

MeshPtr assetMesh(const QString &name)
{
    const MeshLoadResult loaded =
        importMeshFile(QStringLiteral(PHONGLAB_SOURCE_DIR "/assets/meshes/") + name);
    if (!loaded.ok())
        qFatal("%s: %s", qPrintable(name), qPrintable(loaded.error));
    return std::make_shared<const MeshData>(*loaded.mesh);
}

struct Bounds {
    glm::dvec3 lo{std::numeric_limits<double>::infinity()};
    glm::dvec3 hi{-std::numeric_limits<double>::infinity()};
};

Bounds boundsOf(const MeshData &mesh)
{
    Bounds b;
    for (const glm::vec3 &p : mesh.positions) {
        b.lo = glm::min(b.lo, glm::dvec3(p));
        b.hi = glm::max(b.hi, glm::dvec3(p));
    }
    return b;
}

// Rays of three kinds, all reproducible: from outside the mesh's box at a
// point inside it (mostly hits, many grazing), from inside the box in any
// direction, and axis-parallel rays straight at a vertex (zero direction
// components, and hits exactly on shared vertices and edges).
std::vector<Ray> testRays(const MeshData &mesh, int count)
{
    std::mt19937 random(1234);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const Bounds b = boundsOf(mesh);
    const glm::dvec3 centre = 0.5 * (b.lo + b.hi), size = b.hi - b.lo;
    const double radius = glm::length(size);
    const auto inBox = [&] {
        return b.lo + size * glm::dvec3(unit(random), unit(random), unit(random));
    };
    const auto direction = [&] {
        const double z = 2.0 * unit(random) - 1.0, phi = 6.283185307179586 * unit(random);
        const double r = std::sqrt(1.0 - z * z);
        return glm::dvec3(r * std::cos(phi), r * std::sin(phi), z);
    };
    std::vector<Ray> rays;
    for (int i = 0; i < count; ++i) {
        switch (i % 3) {
        case 0: {
            const glm::dvec3 origin = centre + radius * direction();
            rays.push_back(Ray{origin, (inBox() - origin) * (0.5 + unit(random))});
            break;
        }
        case 1: rays.push_back(Ray{inBox(), direction()}); break;
        default: {
            const glm::dvec3 vertex(mesh.positions[random() % mesh.positions.size()]);
            const int axis = int(random() % 3);
            glm::dvec3 d(0.0);
            d[axis] = (random() % 2) ? 1.0 : -1.0;
            rays.push_back(Ray{vertex - 2.0 * radius * d, d});
            break;
        }
        }
    }
    return rays;
}

Scene sphereScene()
{
    Scene scene;
    SceneObject o;
    o.mesh = QStringLiteral("builtin:sphere");
    o.material.ka = {0.2, 0.3, 0.4};
    o.material.kd = {0.6, 0.5, 0.4};
    o.material.ks = {0.5, 0.5, 0.5};
    o.material.shininess = 20.0;
    scene.objects.push_back(o);
    PointLight light;
    light.position = {3.0, 4.0, 5.0};
    scene.lights.push_back(light);
    return scene;
}

ReferenceImage meshReference(const Scene &scene, const std::vector<MeshPtr> &meshes, int w, int h,
                             ReferenceShading shading = ReferenceShading::Phong)
{
    Result<ReferenceImage> image = raycastSceneMeshes(scene, meshes, w, h, shading);
    if (!image)
        qFatal("raycastSceneMeshes failed: %s", qPrintable(image.error()));
    return std::move(*image);
}

ReferenceImage analyticReference(const Scene &scene, int w, int h,
                                 ReferenceShading shading = ReferenceShading::Phong)
{
    Result<ReferenceImage> image = raycastScene(scene, w, h, shading);
    if (!image)
        qFatal("raycastScene failed: %s", qPrintable(image.error()));
    return std::move(*image);
}

// The default scene with its meshes as loadSceneMeshes loads them, one per object.
std::pair<Scene, std::vector<MeshPtr>> defaultScene()
{
    const QString path = QStringLiteral(PHONGLAB_SOURCE_DIR "/assets/scenes/default.json");
    const SceneLoadResult loaded = loadSceneFile(path);
    if (!loaded.ok())
        qFatal("%s: %s", qPrintable(path), qPrintable(loaded.error));
    const SceneMeshes meshes = loadSceneMeshes(*loaded.scene);
    if (!meshes.ok())
        qFatal("%s", qPrintable(meshes.error));
    std::vector<MeshPtr> perObject;
    for (const SceneObject &object : loaded.scene->objects)
        perObject.push_back(meshes.entries.value(meshKey(*loaded.scene, object)).mesh);
    return {*loaded.scene, perObject};
}

} // namespace

class TestMeshRaycast : public QObject
{
    Q_OBJECT

private slots:
    void bvhMatchesBruteForce_data()
    {
        QTest::addColumn<QString>("mesh");
        QTest::newRow("uv sphere 64x32") << "sphere";
        QTest::newRow("torus 48x24") << "torus";
        QTest::newRow("tree.obj") << "tree.obj";
        QTest::newRow("cloud.obj") << "cloud.obj";
    }

    void bvhMatchesBruteForce()
    {
        QFETCH(QString, mesh);
        const MeshPtr data = mesh == QLatin1String("sphere")
            ? std::make_shared<const MeshData>(makeUvSphere(64, 32))
            : mesh == QLatin1String("torus") ? std::make_shared<const MeshData>(makeTorus(48, 24))
                                             : assetMesh(mesh);
        const MeshBvh bvh(*data);
        QCOMPARE(bvh.triangleCount(), data->triangleCount());
        int hits = 0;
        for (const Ray &ray : testRays(*data, 3000)) {
            const std::optional<TriangleHit> expected = closestHitBruteForce(*data, ray, 0.0, 1e30);
            const std::optional<TriangleHit> actual = bvh.closestHit(ray, 0.0, 1e30);
            QCOMPARE(actual.has_value(), expected.has_value());
            if (!expected)
                continue;
            ++hits;
            // Same arithmetic on the same vertices and the same tie rule:
            // bit for bit the same answer.
            QCOMPARE(actual->t, expected->t);
            QCOMPARE(actual->triangle, expected->triangle);
            QVERIFY(actual->barycentric == expected->barycentric);
            QVERIFY(std::abs(actual->barycentric.x + actual->barycentric.y + actual->barycentric.z
                             - 1.0)
                    < 1e-12);
        }
        qInfo("%s: %zu triangles, %zu nodes, depth %d, %d of 3000 rays hit", qPrintable(mesh),
              data->triangleCount(), bvh.nodeCount(), bvh.depth(), hits);
        QVERIFY(hits > 1000);
    }

    // A closed mesh seen from inside is hit in every direction, including
    // rays aimed exactly at its vertices, where a non-watertight test can let
    // a ray slip between the triangles that share the vertex.
    void closedMeshHasNoLeaks()
    {
        const MeshData sphere = makeUvSphere(96, 48);
        const MeshBvh bvh(sphere);
        std::mt19937 random(99);
        std::uniform_real_distribution<double> small(-1e-3, 1e-3);
        int rays = 0;
        for (const glm::vec3 &vertex : sphere.positions) {
            const glm::dvec3 origin(small(random), small(random), small(random));
            for (const glm::dvec3 &target : {glm::dvec3(vertex), glm::dvec3(vertex) * 0.999}) {
                const Ray ray{origin, target - origin};
                QVERIFY2(bvh.closestHit(ray, 0.0, 1e30).has_value(),
                         "a ray from inside escaped the sphere");
                ++rays;
            }
        }
        QVERIFY(rays > 9000);
    }

    // The same sphere once as a fine mesh and once analytic, under a
    // non-uniform scale and a rotation (the normal matrix at work), two
    // objects sharing one mesh pointer (one BVH).
    void fineSphereMatchesAnalytic_data()
    {
        QTest::addColumn<int>("shading");
        QTest::newRow("phong") << int(ReferenceShading::Phong);
        QTest::newRow("blinn-phong") << int(ReferenceShading::BlinnPhong);
        QTest::newRow("normals") << int(ReferenceShading::Normals);
    }

    void fineSphereMatchesAnalytic()
    {
        QFETCH(int, shading);
        const auto method = ReferenceShading(shading);
        Scene scene = sphereScene();
        scene.objects[0].transform.translate = {-0.9, 0.0, 0.0};
        scene.objects.push_back(scene.objects[0]);
        scene.objects[1].transform.translate = {0.9, 0.2, -0.5};
        scene.objects[1].transform.scale = {0.6, 1.1, 0.8};
        scene.objects[1].transform.rotateDeg = {20.0, 35.0, -10.0};
        const MeshPtr sphere = std::make_shared<const MeshData>(makeUvSphere(256, 128));
        const ReferenceImage mesh = meshReference(scene, {sphere, sphere}, 256, 256, method);
        const ReferenceImage analytic = analyticReference(scene, 256, 256, method);
        const ImageComparison c = compareWithReference(mesh.toImage(scene.background), analytic, 2);
        qInfo("UV sphere 256x128 vs analytic sphere: %s", qPrintable(c.summary()));
        // Bound: a 256×128 tessellation differs from the sphere by at most
        // 1 - cos(π/128) ≈ 3e-4 in position and ~1e-4 rad in the
        // interpolated normal; that moves an 8-bit value by at most one step.
        QVERIFY(c.pixelsCompared > 256 * 256 / 8);
        QVERIFY2(c.maxError <= 1, qPrintable(c.summary()));
        QVERIFY2(c.psnr >= 60.0, qPrintable(c.summary()));
    }

    // The specular channel is the highlight alone: ks = 0 zeroes it, it is
    // zero off the surface, and colour minus specular is the ks = 0 image.
    void specularChannel()
    {
        Scene scene = sphereScene();
        const MeshPtr sphere = std::make_shared<const MeshData>(makeUvSphere(128, 64));
        const ReferenceImage withKs = meshReference(scene, {sphere}, 128, 128);
        const ReferenceImage analyticWithKs = analyticReference(scene, 128, 128);
        scene.objects[0].material.ks = glm::dvec3(0.0);
        const ReferenceImage withoutKs = meshReference(scene, {sphere}, 128, 128);
        const ReferenceImage analyticWithoutKs = analyticReference(scene, 128, 128);

        for (const ReferenceImage *image : {&withoutKs, &analyticWithoutKs})
            for (const glm::dvec3 &s : image->specular)
                QCOMPARE(s, glm::dvec3(0.0));
        for (const auto &[lit, unlit] :
             {std::pair{&withKs, &withoutKs}, std::pair{&analyticWithKs, &analyticWithoutKs}}) {
            qint64 highlight = 0;
            double peak = 0.0;
            for (std::size_t i = 0; i < lit->specular.size(); ++i) {
                if (!lit->coverage[i]) {
                    QCOMPARE(lit->specular[i], glm::dvec3(0.0));
                    continue;
                }
                QVERIFY(glm::all(
                    glm::lessThan(glm::abs(lit->color[i] - lit->specular[i] - unlit->color[i]),
                                  glm::dvec3(1e-12))));
                peak = std::max(peak, lit->specular[i].r);
                highlight += lit->specular[i].r > 1.0 / 255.0;
            }
            // n = 20: the highlight is a small spot, not the whole lit side.
            qInfo("specular: peak %.3f, %lld of %lld covered pixels above 1/255", peak, highlight,
                  lit->coveredCount());
            QVERIFY(peak > 0.3);
            QVERIFY(highlight > 0 && highlight < lit->coveredCount() / 4);
        }
        const ReferenceImage normals =
            meshReference(sphereScene(), {sphere}, 64, 64, ReferenceShading::Normals);
        for (const glm::dvec3 &s : normals.specular)
            QCOMPARE(s, glm::dvec3(0.0));
    }

    void badInputIsAnError()
    {
        const Scene scene = sphereScene();
        const MeshPtr sphere = std::make_shared<const MeshData>(makeUvSphere(16, 8));
        const auto expectError = [](const Result<ReferenceImage> &r, const QString &part) {
            QVERIFY(!r);
            QVERIFY2(r.error().contains(part), qPrintable(r.error()));
        };
        expectError(raycastSceneMeshes(scene, {}, 32, 32, ReferenceShading::Phong),
                    QStringLiteral("1 objects but 0 meshes"));
        expectError(raycastSceneMeshes(scene, {sphere, sphere}, 32, 32, ReferenceShading::Phong),
                    QStringLiteral("1 objects but 2 meshes"));
        expectError(raycastSceneMeshes(scene, {sphere}, 0, 32, ReferenceShading::Phong),
                    QStringLiteral("0x32"));

        Scene fileScene = scene;
        fileScene.objects[0].mesh = QStringLiteral("tree.obj");
        expectError(raycastSceneMeshes(fileScene, {nullptr}, 32, 32, ReferenceShading::Phong),
                    QStringLiteral("tree.obj"));
        // A null mesh for a builtin is its analytic surface.
        QVERIFY(raycastSceneMeshes(scene, {nullptr}, 32, 32, ReferenceShading::Phong));

        auto broken = std::make_shared<MeshData>(makeUvSphere(16, 8));
        broken->indices.push_back(0); // not a multiple of three
        expectError(raycastSceneMeshes(scene, {broken}, 32, 32, ReferenceShading::Phong),
                    QStringLiteral("not valid"));

        int calls = 0;
        const Result<ReferenceImage> cancelled = raycastSceneMeshes(
            scene, {sphere}, 64, 64, ReferenceShading::Phong, [&](double) { return ++calls < 3; });
        QVERIFY(!cancelled);
        QCOMPARE(cancelled.error(), QStringLiteral("cancelled"));
    }

    void defaultSceneIsTheSameOnAnyThreadCount()
    {
        const auto [scene, meshes] = defaultScene();
        qint64 triangles = 0;
        for (const MeshPtr &mesh : meshes)
            triangles += qint64(mesh->triangleCount());
        double lastFraction = -1.0;
        bool monotonic = true;
        const Result<ReferenceImage> image =
            raycastSceneMeshes(scene, meshes, 512, 512, ReferenceShading::Phong, [&](double f) {
                monotonic = monotonic && f >= lastFraction && f <= 1.0;
                lastFraction = f;
                return true;
            });
        QVERIFY(image);
        QVERIFY(monotonic);
        qInfo("default scene (tree + cloud, %lld triangles) at 512x512: %lld px covered", triangles,
              image->coveredCount());
        QVERIFY(image->coveredCount() > 512 * 512 / 20);
        // Each pixel depends only on its own ray: a second run, scheduled
        // differently across the threads, gives the same image.
        const ReferenceImage again = meshReference(scene, meshes, 512, 512);
        QVERIFY(again.color == image->color && again.depth == image->depth
                && again.specular == image->specular);
    }
};

QTEST_APPLESS_MAIN(TestMeshRaycast)
#include "tst_meshraycast.moc"
