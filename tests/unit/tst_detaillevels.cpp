// Levels of detail for "detail": "auto" (DetailLevels.h) and the choice
// among them (DetailSelection.h): what the ladder holds on the shipped
// meshes, and the hysteresis that keeps a level from flickering without
// ever letting the projected error exceed the target.

#include "TestPaths.h"
#include "core/view/DetailSelection.h"
#include "mesh/detail/DetailLevels.h"
#include "mesh/import/BuiltinMeshes.h"
#include "mesh/loading/MeshLoader.h"

#include <QRandomGenerator>
#include <QtTest>

using namespace phonglab;
using namespace phonglab::test;

class TestDetailLevels : public QObject
{
    Q_OBJECT

private slots:
    void ladderHalvesAndStatesItsError_data()
    {
        QTest::addColumn<QString>("spec");
        QTest::newRow("sphere") << QStringLiteral("builtin:sphere");
        QTest::newRow("tree") << sourcePath(QStringLiteral("assets/meshes/tree.obj"));
        QTest::newRow("cloud") << sourcePath(QStringLiteral("assets/meshes/cloud.obj"));
        // Any other mesh's ladder, printed (e.g. the 1.3M-triangle icosphere
        // of scripts/make-bench-mesh.sh): PHONGLAB_LEVELS_MESH=FILE.
        if (const QString extra = qEnvironmentVariable("PHONGLAB_LEVELS_MESH"); !extra.isEmpty())
            QTest::newRow("PHONGLAB_LEVELS_MESH") << extra;
    }

    void ladderHalvesAndStatesItsError()
    {
        QFETCH(QString, spec);
        const MeshLoadResult loaded = loadMesh(spec);
        QVERIFY2(loaded.mesh, qPrintable(loaded.error));
        const MeshData &mesh = *loaded.mesh;
        const DetailLevels ladder = buildDetailLevels(mesh);
        QVERIFY(ladder.levels.size() >= 4);
        QCOMPARE(ladder.levels.front().indices, mesh.indices);
        QCOMPARE(ladder.levels.front().error, 0.0);
        QString line;
        for (std::size_t i = 0; i < ladder.levels.size(); ++i) {
            const DetailLevel &level = ladder.levels[i];
            line += QStringLiteral(" %1△/%2/%3°")
                        .arg(ladder.triangles(i))
                        .arg(level.error, 0, 'g', 3)
                        .arg(glm::degrees(level.normalDeviation), 0, 'g', 3);
            QCOMPARE(level.indices.size() % 3, std::size_t(0));
            for (std::uint32_t v : level.indices)
                QVERIFY(v < mesh.positions.size());
            if (i == 0)
                continue;
            QVERIFY(ladder.triangles(i) <= ladder.triangles(i - 1) * 9 / 10);
            QVERIFY(ladder.triangles(i) >= ladder.triangles(i - 1) / 3);
            QVERIFY(level.error >= ladder.levels[i - 1].error);
            QVERIFY2(level.error > 0.0, "a coarser level of a curved mesh claims no error");
        }
        qInfo("%s:%s", QTest::currentDataTag(), qPrintable(line));
        // It stops near kMinLevelTriangles, or where seams and borders lock
        // the rest (the UV sphere's poles and seam), far below the full mesh.
        QVERIFY(ladder.triangles(ladder.levels.size() - 1) * 32 < mesh.triangleCount());
    }

    void cancelledLadderIsEmpty()
    {
        const DetailLevels ladder =
            buildDetailLevels(makeUvSphere(64, 32), [](double) { return false; });
        QVERIFY(ladder.empty());
    }

    void projectedErrorShrinksWithDistance()
    {
        Camera camera;
        camera.eye = {0, 0, 10};
        camera.fovDeg = 90.0; // half height = distance
        const BoundingSphere bounds{{0, 0, 0}, 1.0};
        // Distance 9 to the nearest point: 0.09 units span 0.09 / 18 of 600 px.
        QCOMPARE(projectedErrorPx(0.09, bounds, camera, 600), 3.0);
        camera.eye = {0, 0, 19};
        QCOMPARE(projectedErrorPx(0.09, bounds, camera, 600), 1.5);
        camera.eye = {0, 0, 0.5}; // inside the bounds: the near plane
        QVERIFY(projectedErrorPx(0.09, bounds, camera, 600) > 100.0);
    }

    void chooseTakesTheCoarsestWithinTheTarget()
    {
        const std::vector<double> errors{0.0, 0.1, 0.3, 0.6, 1.2};
        QCOMPARE(chooseDetailLevel(errors, -1, 0.5), 2);
        QCOMPARE(chooseDetailLevel(errors, -1, 0.05), 0);
        QCOMPARE(chooseDetailLevel(errors, -1, 5.0), 4);
        QCOMPARE(chooseDetailLevel({}, -1, 0.5), 0);
    }

    void hysteresisHoldsALevelButNeverExceedsTheTarget()
    {
        // Level 2 at 0.45 px with a 0.5 px target: within, but not below
        // 0.7 x 0.5 = 0.35, so from level 1 it is not taken...
        QCOMPARE(chooseDetailLevel(std::vector<double>{0.0, 0.2, 0.45}, 1, 0.5), 1);
        // ... from level 2 it is kept ...
        QCOMPARE(chooseDetailLevel(std::vector<double>{0.0, 0.2, 0.45}, 2, 0.5), 2);
        // ... and once it is over the target it is left at once.
        QCOMPARE(chooseDetailLevel(std::vector<double>{0.0, 0.2, 0.55}, 2, 0.5), 1);
        // Comfortably within: coarser is taken.
        QCOMPARE(chooseDetailLevel(std::vector<double>{0.0, 0.2, 0.3}, 1, 0.5), 2);
    }

    void hysteresisOnACameraThatJitters()
    {
        // Levels of error 0.001·2^k units; the camera creeps back and forth
        // around a distance: the level must switch far less often than a
        // choice without hysteresis, and never show more than the target.
        std::vector<double> worldErrors;
        for (int k = 0; k < 10; ++k)
            worldErrors.push_back(k == 0 ? 0.0 : 0.001 * std::pow(2.0, k));
        Camera camera;
        camera.fovDeg = 45.0;
        const BoundingSphere bounds{{0, 0, 0}, 1.0};
        QRandomGenerator random(99);
        int current = -1, switches = 0, naiveSwitches = 0, naive = -1;
        double z = 24.2; // where level 4 reaches 0.5 px
        for (int frame = 0; frame < 2000; ++frame) {
            z = std::clamp(z + (random.generateDouble() - 0.5) * 0.4, 5.0, 60.0);
            camera.eye = {0, 0, z};
            std::vector<double> px;
            for (double e : worldErrors)
                px.push_back(projectedErrorPx(e, bounds, camera, 600));
            const int next = chooseDetailLevel(px, current, kDefaultDetailPixels);
            const int naiveNext = chooseDetailLevel(px, -1, kDefaultDetailPixels);
            QVERIFY(px[std::size_t(next)] <= kDefaultDetailPixels);
            switches += frame > 0 && next != current ? 1 : 0;
            naiveSwitches += frame > 0 && naiveNext != naive ? 1 : 0;
            current = next;
            naive = naiveNext;
        }
        qInfo("level switches over 2000 jittering frames: %d with hysteresis, %d without", switches,
              naiveSwitches);
        QVERIFY(naiveSwitches > 20);
        QVERIFY(switches * 3 < naiveSwitches);
    }
};

QTEST_APPLESS_MAIN(TestDetailLevels)
#include "tst_detaillevels.moc"
