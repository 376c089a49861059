// What a course's page adds to a shader before the browser compiles it
// (core/program/CoursePrelude): lower precisions checked at highp unless asked
// otherwise, three.js's declarations only where the source leaves them to
// three.js, a default float precision for a GLSL ES fragment shader without
// one, the page's defines, and what to do about a token nobody defines.
#include "core/program/CoursePrelude.h"

#include <QTest>

using namespace phonglab;

namespace {

const QByteArray kThreeVertex = R"(varying vec3 vNormal;
void main() {
    vNormal = normalMatrix * normal; // modelMatrix in a comment declares nothing
    gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}
)";

} // namespace

class TestCoursePrelude : public QObject
{
    Q_OBJECT

private slots:
    void lowerPrecisionIsCheckedAtHighp()
    {
        const QByteArray code = "precision mediump float;\nvoid main() { lowp vec3 c; }\n";
        const CoursePrelude highp = coursePreludeFor(code, ShaderStage::Fragment, {});
        QCOMPARE(highp.lowerPrecisions,
                 (QStringList{QStringLiteral("mediump"), QStringLiteral("lowp")}));
        QVERIFY(highp.text.contains("#define mediump highp\n"));
        QVERIFY(highp.text.contains("#define lowp highp\n"));
        QCOMPARE(highp.added.size(), 1);

        CourseOptions asWritten;
        asWritten.precision = PrecisionRule::AsWritten;
        const CoursePrelude kept = coursePreludeFor(code, ShaderStage::Fragment, asWritten);
        QVERIFY(!kept.text.contains("#define"));
        QCOMPARE(kept.lowerPrecisions.size(), 2); // still said
        // In a comment, a precision is no declaration.
        QVERIFY(coursePreludeFor("// mediump\nprecision highp float;\nvoid main(){}",
                                 ShaderStage::Fragment, {})
                    .lowerPrecisions.isEmpty());
    }

    void threeJsDeclaresWhatTheSourceLeavesToIt()
    {
        const CoursePrelude vertex = coursePreludeFor(kThreeVertex, ShaderStage::Vertex, {});
        QVERIFY(vertex.usesThreeJs);
        for (const char *line :
             {"uniform mat4 modelViewMatrix;", "uniform mat4 projectionMatrix;",
              "uniform mat3 normalMatrix;", "attribute vec3 position;", "attribute vec3 normal;"})
            QVERIFY2(vertex.text.contains(line), line);
        QVERIFY(!vertex.text.contains("modelMatrix;")); // used in a comment only
        QVERIFY(vertex.text.startsWith("precision highp float;"));
        // three.js's GLSL3 materials: inputs are `in`.
        const CoursePrelude es3 =
            coursePreludeFor("#version 300 es\n" + kThreeVertex.mid(kThreeVertex.indexOf("void")),
                             ShaderStage::Vertex, {});
        QVERIFY2(es3.text.contains("in vec3 position;"), es3.text.constData());

        // A source that declares its own is nobody's three.js.
        const QByteArray own =
            "uniform mat4 modelViewMatrix;\nattribute vec3 position;\n"
            "void main() { gl_Position = modelViewMatrix * vec4(position, 1.0); }";
        QVERIFY(!coursePreludeFor(own, ShaderStage::Vertex, {}).usesThreeJs);
        // A plain `position` alone says nothing about three.js.
        QVERIFY(!coursePreludeFor("void main() { gl_Position = vec4(position, 1.0); }",
                                  ShaderStage::Vertex, {})
                     .usesThreeJs);
    }

    void esFragmentShaderGetsADefaultPrecision()
    {
        const QByteArray noPrecision =
            "varying vec3 c;\nvoid main() { gl_FragColor = vec4(c, 1.0); }";
        const CoursePrelude es = coursePreludeFor(noPrecision, ShaderStage::Fragment, {});
        QCOMPARE(es.text, QByteArray("precision highp float;\n"));
        QCOMPARE(es.added.size(), 1);
        // Vertex shaders have one by default; desktop GLSL needs none.
        QVERIFY(coursePreludeFor(noPrecision, ShaderStage::Vertex, {}).text.isEmpty());
        QVERIFY(coursePreludeFor("#version 330 core\nout vec4 c; void main() { c = vec4(1.0); }",
                                 ShaderStage::Fragment, {})
                    .text.isEmpty());
    }

    void definesGoInTheirOrder()
    {
        CourseOptions options;
        options.defines = {{QStringLiteral("NUM_LIGHTS"), QStringLiteral("2")},
                           {QStringLiteral("FLAT"), QString()}};
        const CoursePrelude p =
            coursePreludeFor("#version 300 es\nvoid main() {}", ShaderStage::Vertex, options);
        QCOMPARE(p.text, QByteArray("#define FLAT\n#define NUM_LIGHTS 2\n"));
    }

    void defineArguments()
    {
        QString error;
        const auto parsed = parseDefineArgument(QStringLiteral("NUM_LIGHTS=2"), &error);
        QVERIFY(parsed);
        QCOMPARE(parsed->name, QStringLiteral("NUM_LIGHTS"));
        QCOMPARE(parsed->value, QStringLiteral("2"));
        QCOMPARE(parseDefineArgument(QStringLiteral("FLAT"), &error)->value, QString());
        QVERIFY(!parseDefineArgument(QStringLiteral("2N=1"), &error));
        QVERIFY(error.contains(QStringLiteral("GLSL identifier")));
        QVERIFY(!parseDefineArgument(QStringLiteral("N=1\n#error"), &error));
        QVERIFY(error.contains(QStringLiteral("one line")));
    }

    void anUndefinedTokenIsNamedWithTheFlag()
    {
        const QString mesa = QStringLiteral("`NUM_POINT_LIGHTS' undeclared");
        const QString explained = explainUndefinedToken(mesa, {});
        QVERIFY(explained.startsWith(mesa));
        QVERIFY(explained.contains(QStringLiteral("--define NUM_POINT_LIGHTS=VALUE")));
        QVERIFY(
            explainUndefinedToken(QStringLiteral("undefined macro NUM_LIGHTS in expression"), {})
                .contains(QStringLiteral("--define NUM_LIGHTS=VALUE")));
        // A student's lower-case name is their own typo, not the page's token.
        QCOMPARE(explainUndefinedToken(QStringLiteral("`lightPos' undeclared"), {}),
                 QStringLiteral("`lightPos' undeclared"));
        // Defined already: the message is about something else.
        QCOMPARE(explainUndefinedToken(mesa,
                                       {{QStringLiteral("NUM_POINT_LIGHTS"), QStringLiteral("2")}}),
                 mesa);
    }

    void rulesHaveKeys()
    {
        QCOMPARE(precisionRuleKey(PrecisionRule::Highp), QStringLiteral("highp"));
        QCOMPARE(precisionRuleKey(PrecisionRule::AsWritten), QStringLiteral("as-written"));
        QVERIFY(precisionRuleFromKey(QStringLiteral("as-written")) == PrecisionRule::AsWritten);
        QVERIFY(!precisionRuleFromKey(QStringLiteral("mediump")));
    }
};

QTEST_GUILESS_MAIN(TestCoursePrelude)
#include "tst_courseprelude.moc"
