// The reference image with a classic shader mistake made: each mistake
// changes the image where it should and nowhere else, and one that cannot
// show in a scene (normal-matrix under uniform scale) changes nothing there.
#include "core/AnalyticRaycaster.h"
#include "core/ShaderMistake.h"

#include <QTest>

#include <cmath>

using namespace phonglab;

namespace {

// A sphere scaled non-uniformly and moved off the origin, seen from the
// default camera (on +Z at distance 4), lit from the front with attenuation
// and from behind.
Scene ellipsoidScene(const glm::dvec3 &scale = {1.2, 0.7, 0.9})
{
    SceneObject o;
    o.mesh = QStringLiteral("builtin:sphere");
    o.transform.scale = scale;
    o.transform.translate = {0.2, -0.1, 0.0};
    o.material.ka = {0.2, 0.2, 0.2};
    o.material.kd = {0.6, 0.5, 0.4};
    o.material.ks = {0.5, 0.5, 0.5};
    o.material.shininess = 20.0;
    Scene scene;
    scene.objects.push_back(o);
    PointLight light;
    light.position = {3.0, 4.0, 5.0};
    light.attenuation = {1.0, 0.05, 0.0};
    scene.lights.push_back(light);
    // Behind the object, almost opposite the eye: near the rim the surface
    // faces away from it (N·L < 0) while R·V > 0, where backface-specular
    // shows.
    PointLight back;
    back.position = {-1.0, 1.5, -6.0};
    scene.lights.push_back(back);
    return scene;
}

constexpr int kSize = 64;

ReferenceImage render(const Scene &scene, const ReferenceShader &shader)
{
    QString error;
    const std::optional<ReferenceImage> image = raycastScene(scene, kSize, kSize, shader, &error);
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
    void everyMistakeButGouraudShowsOnTheEllipsoid_data()
    {
        QTest::addColumn<QString>("key");
        for (const QString &key : shaderMistakeKeys())
            if (key != QLatin1String("gouraud"))
                QTest::newRow(qPrintable(key)) << key;
    }

    void everyMistakeButGouraudShowsOnTheEllipsoid()
    {
        QFETCH(QString, key);
        const Scene scene = ellipsoidScene();
        const ReferenceImage exact = render(scene, ReferenceShading::Phong);
        const ReferenceImage mistaken = render(scene, {ReferenceShading::Phong, shaderMistakeFromKey(key)});
        QVERIFY(!exact.isNull() && !mistaken.isNull());
        // A mistake changes the colour, never which pixels the object covers.
        QVERIFY(exact.coverage == mistaken.coverage);
        QVERIFY(exact.depth == mistaken.depth);
        const int differing = differingPixels(exact, mistaken);
        qInfo("%s: %d of %lld covered pixels differ", qPrintable(key), differing, exact.coveredCount());
        QVERIFY2(differing > 0, qPrintable(key));
    }

    void normalMatrixCannotShowUnderUniformScale()
    {
        // MV·n and its inverse transpose differ by a factor of s² along
        // every direction under a uniform scale s: the same unit normal.
        const Scene uniform = ellipsoidScene(glm::dvec3(0.8));
        const ReferenceImage exact = render(uniform, ReferenceShading::Phong);
        const ReferenceImage mistaken = render(uniform, {ReferenceShading::Phong, ShaderMistake::NormalMatrix});
        QCOMPARE(differingPixels(exact, mistaken), 0);
        // The same shader mistake is plain under a non-uniform scale.
        const Scene stretched = ellipsoidScene();
        QVERIFY(differingPixels(render(stretched, ReferenceShading::Phong),
                                render(stretched, {ReferenceShading::Phong, ShaderMistake::NormalMatrix}))
                > kSize);
    }

    void gouraudShadesExactlyHere()
    {
        // Per-vertex evaluation needs the mesh's vertices, which the ray
        // caster does not have.
        const Scene scene = ellipsoidScene();
        QCOMPARE(differingPixels(render(scene, ReferenceShading::Phong),
                                 render(scene, {ReferenceShading::Phong, ShaderMistake::Gouraud})),
                 0);
    }

    void exactShaderIsTheDefault()
    {
        const Scene scene = ellipsoidScene();
        QString error;
        const std::optional<ReferenceImage> byDefault = raycastScene(scene, kSize, kSize, &error);
        QVERIFY2(byDefault, qPrintable(error));
        QCOMPARE(differingPixels(*byDefault, render(scene, ReferenceShader{}), 0.0), 0);
    }
};

QTEST_GUILESS_MAIN(TestMistakenReference)
#include "tst_mistakenreference.moc"
