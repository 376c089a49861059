// The reference image with a classic shader mistake made: each mistake
// changes the image where it should and nowhere else, and one that cannot
// show in a scene (normal-matrix under uniform scale) changes nothing there.
#include "MistakeScenes.h"
#include "core/reference/MeshRaycaster.h"
#include "core/reference/ShaderMistake.h"

#include <QTest>

#include <cmath>

using namespace phonglab;
using phonglab::test::mistakeScene;

namespace {

constexpr int kSize = 64;

ReferenceImage render(const Scene &scene, const ReferenceShader &shader)
{
    const Result<ReferenceImage> image = raycastScene(scene, kSize, kSize, shader);
    return image ? *image : ReferenceImage();
}

// Covered pixels whose intensity differs by more than `tolerance` in any channel.
int differingPixels(const ReferenceImage &a, const ReferenceImage &b, double tolerance = 1e-9)
{
    int count = 0;
    for (std::size_t i = 0; i < a.color.size(); ++i) {
        if (!a.coverage[i])
            continue;
        const glm::dvec3 d = glm::abs(a.color[i] - b.color[i]);
        if (std::max({d.x, d.y, d.z}) > tolerance)
            ++count;
    }
    return count;
}

} // namespace

class TestMistakenReference : public QObject
{
    Q_OBJECT

private slots:
    // gouraud and per-face need the mesh's triangles (gouraudShadesExactlyHere).
    void everyPointMistakeShowsOnTheEllipsoid_data()
    {
        QTest::addColumn<QString>("key");
        for (const QString &key : shaderMistakeKeys())
            if (key != QLatin1String("gouraud") && key != QLatin1String("per-face"))
                QTest::newRow(qPrintable(key)) << key;
    }

    void everyPointMistakeShowsOnTheEllipsoid()
    {
        QFETCH(QString, key);
        const Scene scene = mistakeScene();
        const ReferenceImage exact = render(scene, ReferenceShading::Phong);
        const ReferenceImage mistaken =
            render(scene, {ReferenceShading::Phong, shaderMistakeFromKey(key)});
        QVERIFY(!exact.isNull() && !mistaken.isNull());
        // A mistake changes the colour, never which pixels the object covers.
        QVERIFY(exact.coverage == mistaken.coverage);
        QVERIFY(exact.depth == mistaken.depth);
        const int differing = differingPixels(exact, mistaken);
        qInfo("%s: %d of %lld covered pixels differ", qPrintable(key), differing,
              exact.coveredCount());
        QVERIFY2(differing > 0, qPrintable(key));
    }

    void normalMatrixCannotShowUnderUniformScale()
    {
        // MV·n and its inverse transpose differ by a factor of s² along
        // every direction under a uniform scale s: the same unit normal.
        const Scene uniform = mistakeScene(glm::dvec3(0.8));
        const ReferenceImage exact = render(uniform, ReferenceShading::Phong);
        const ReferenceImage mistaken =
            render(uniform, {ReferenceShading::Phong, ShaderMistake::NormalMatrix});
        QCOMPARE(differingPixels(exact, mistaken), 0);
        // The same shader mistake is plain under a non-uniform scale.
        const Scene stretched = mistakeScene();
        QVERIFY(differingPixels(
                    render(stretched, ReferenceShading::Phong),
                    render(stretched, {ReferenceShading::Phong, ShaderMistake::NormalMatrix}))
                > kSize);
    }

    void gouraudShadesExactlyHere()
    {
        // Per-vertex and per-face evaluation need the mesh's vertices, which
        // the ray caster does not have.
        const Scene scene = mistakeScene();
        for (const ShaderMistake m : {ShaderMistake::Gouraud, ShaderMistake::PerFace})
            QCOMPARE(differingPixels(render(scene, ReferenceShading::Phong),
                                     render(scene, {ReferenceShading::Phong, m})),
                     0);
    }

    void exactShaderIsTheDefault()
    {
        const Scene scene = mistakeScene();
        const Result<ReferenceImage> byDefault = raycastScene(scene, kSize, kSize);
        QVERIFY2(byDefault, qPrintable(byDefault.error()));
        QCOMPARE(differingPixels(*byDefault, render(scene, ReferenceShader{}), 0.0), 0);
    }
};

QTEST_GUILESS_MAIN(TestMistakenReference)
#include "tst_mistakenreference.moc"
