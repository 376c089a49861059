// Imported meshes on the GPU against analytic references: a flat-shaded
// Blender cube must render with exactly one normal per face, which a
// per-vertex (OpenMesh-style) normal import would smear.
#include "RenderCheck.h"
#include "render/gl/GlFormat.h"

#include <QTest>

using namespace phonglab;
using namespace phonglab::test;

class TestMeshRender : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void flatBlenderCubeMatchesAnalyticBox();
    void smearedNormalsFailTheSameComparison_data();
    void smearedNormalsFailTheSameComparison();

private:
    static QHash<QString, QString> cubeStandIn(const Scene &scene);
};

void TestMeshRender::initTestCase()
{
    QSurfaceFormat::setDefaultFormat(phonglabSurfaceFormat(0));
}

QHash<QString, QString> TestMeshRender::cubeStandIn(const Scene &scene)
{
    return {{scene.objects.front().mesh, QStringLiteral("builtin:cube")}};
}

void TestMeshRender::flatBlenderCubeMatchesAnalyticBox()
{
    const Scene scene = loadTestScene(QStringLiteral("gl_blender_cube_flat"));
    const RenderCheck check =
        checkAgainstReference(scene, std::nullopt, std::nullopt, cubeStandIn(scene));
    QVERIFY2(check.error.isEmpty(), qPrintable(check.error));
    qInfo("Blender flat cube vs analytic box: %s", qPrintable(check.comparison.summary()));
    QVERIFY(check.comparison.pixelsCompared > kTestImageSide * kTestImageSide / 10);
    if (!check.matches())
        QFAIL(qPrintable(
            check.comparison.summary() + QStringLiteral(" (images in ")
            + saveArtifacts(QStringLiteral("blender-cube"), check, scene, cubeStandIn(scene))
            + ')'));
}

void TestMeshRender::smearedNormalsFailTheSameComparison_data()
{
    QTest::addColumn<QString>("method");
    // One normal per vertex, averaged over its faces: what OpenMesh's OBJ
    // reader makes of a flat export.
    QTest::newRow("average") << "average";
    QTest::newRow("angle") << "angle";
}

void TestMeshRender::smearedNormalsFailTheSameComparison()
{
    QFETCH(QString, method);
    Scene scene = loadTestScene(QStringLiteral("gl_blender_cube_flat"));
    scene.objects.front().normals.method = *normalMethodFromName(method);
    const RenderCheck check =
        checkAgainstReference(scene, std::nullopt, std::nullopt, cubeStandIn(scene));
    QVERIFY2(check.error.isEmpty(), qPrintable(check.error));
    qInfo("cube with %s normals: %s", qPrintable(method), qPrintable(check.comparison.summary()));
    QVERIFY2(!check.matches(), qPrintable(check.comparison.summary()));
}

QTEST_MAIN(TestMeshRender)
#include "tst_meshrender.moc"
