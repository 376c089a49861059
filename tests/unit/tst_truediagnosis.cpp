// A diagnosis that is true: a set of mistakes is the answer only where it
// explains as much as a single mistake must (else it is the closest, partial
// one), and a program that lights per vertex is `gouraud` first, read from
// its code (core/program/VertexLighting, core/check/MistakeDiagnosis).
#include "core/check/MistakeDiagnosis.h"
#include "core/check/MistakeSets.h"
#include "core/program/VertexLighting.h"

#include <QTest>

using namespace phonglab;

class TestTrueDiagnosis : public QObject
{
    Q_OBJECT

private slots:
    void aWeakSetIsNoAnswer()
    {
        MistakeDiagnosis d;
        d.differingPixels = 1000;
        d.together = {{{ShaderMistake::HalfwayVector, 0}}, 0.02};
        QVERIFY(!d.togetherExplains());
        QVERIFY(d.unexplained());
        d.together.explains = kExplainedConfidence;
        QVERIFY(d.togetherExplains());
        QVERIFY(!d.unexplained());
    }

    void lightingPerVertexIsRead_data()
    {
        QTest::addColumn<QByteArray>("vertex");
        QTest::addColumn<QByteArray>("fragment");
        QTest::addColumn<bool>("perVertex");
        const QByteArray gouraudVertex =
            "attribute vec4 vPosition;\nattribute vec3 vNormal;\nvarying vec4 fColor;\n"
            "uniform vec4 ambientProduct, diffuseProduct, specularProduct;\n"
            "uniform float shininess;\nvoid main() {\n  vec3 N = normalize(vNormal);\n"
            "  float Kd = max(dot(L, N), 0.0);\n  float Ks = pow(max(dot(N, H), 0.0), shininess);\n"
            "  fColor = ambientProduct + Kd * diffuseProduct + Ks * specularProduct;\n"
            "  gl_Position = vPosition;\n}\n";
        const QByteArray passThrough = "precision mediump float;\nvarying vec4 fColor;\nvoid "
                                       "main() { gl_FragColor = fColor; }\n";
        const QByteArray phongFragment =
            "precision mediump float;\nvarying vec3 n;\nvoid main() { gl_FragColor = "
            "vec4(max(dot(n, vec3(0.0, 0.0, 1.0)), 0.0)); }\n";
        const QByteArray plainVertex =
            "attribute vec4 p;\nvarying vec3 n;\nvoid main() { n = p.xyz; gl_Position = p; }\n";
        QTest::newRow("Angel's shadedCube: per vertex") << gouraudVertex << passThrough << true;
        QTest::newRow("per fragment") << plainVertex << phongFragment << false;
        QTest::newRow("both light: per fragment") << gouraudVertex << phongFragment << false;
        QTest::newRow("a macro hides the call")
            << QByteArray("#define LAMBERT max(dot(N, L), 0.0)\n") + plainVertex << passThrough
            << true;
        QTest::newRow("unlit") << plainVertex << passThrough << false;
    }

    void lightingPerVertexIsRead()
    {
        QFETCH(QByteArray, vertex);
        QFETCH(QByteArray, fragment);
        QFETCH(bool, perVertex);
        QCOMPARE(lightsPerVertex(vertex, fragment), perVertex);
    }

    void gouraudComesFirstWhateverElse()
    {
        MistakeDiagnosis d;
        d.differingPixels = 500;
        d.findings = {{ShaderMistake::HomogeneousW, 0, {}, 1.0},
                      {ShaderMistake::Gouraud, 0, {}, 0.3}};
        d.together = {{{ShaderMistake::HomogeneousW, 0}, {ShaderMistake::Ambient, 0}}, 0.9};
        nameGouraudFromCode(d);
        QCOMPARE(d.findings.size(), std::size_t(2));
        QCOMPARE(d.findings.front().key, ShaderMistake::Gouraud);
        QVERIFY(d.findings.front().fromCode);
        QCOMPARE(d.findings.front().confidence, 0.3);
        QVERIFY(d.together.variants.empty());
        QVERIFY(!d.unexplained());

        MistakeDiagnosis none; // no image of gouraud matched: it is named all the same
        none.differingPixels = 500;
        nameGouraudFromCode(none);
        QCOMPARE(none.findings.size(), std::size_t(1));
        QCOMPARE(none.findings.front().key, ShaderMistake::Gouraud);
        QVERIFY(!none.unexplained());
    }
};

QTEST_GUILESS_MAIN(TestTrueDiagnosis)
#include "tst_truediagnosis.moc"
