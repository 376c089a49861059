// Driver logs to diagnostics, and the prologue that #line maps back; no GL.
#include "render/program/ShaderDiagnostic.h"
#include "render/program/ShaderSource.h"

#include <QTest>

using namespace phonglab;

class TestShaderDiagnostic : public QObject
{
    Q_OBJECT

private slots:
    void parsesMesa();
    void parsesNvidia();
    void parsesAmdStyle();
    void parsesUnlocatedLinkError();
    void keepsContinuationLines();
    void subtractsPrologueLines();
    void formatsLikeACompiler();
    void prologueGoesAfterVersion();
    void prologueWithoutVersion();
    void prologueForOldGlsl();
    void noDefinesLeavesTextAlone();
    void columnsMapBackOverCollapsedWhitespace();
    void missingSemicolonPointsAtTheLineItBelongsTo();
};

void TestShaderDiagnostic::parsesMesa()
{
    const auto d = parseShaderLog(QStringLiteral("0:12(5): error: `foo' undeclared\n"
                                                 "0:3(10): warning: unused variable\n"),
                                  BuildStep::CompileFragment, QStringLiteral("a.frag"));
    QCOMPARE(d.size(), std::size_t(2));
    QCOMPARE(d[0].line, 12);
    QCOMPARE(d[0].column, 5);
    QVERIFY(d[0].isError());
    QCOMPARE(d[0].message, QStringLiteral("`foo' undeclared"));
    QCOMPARE(d[1].line, 3);
    QCOMPARE(d[1].column, 10);
    QVERIFY(!d[1].isError());
}

void TestShaderDiagnostic::parsesNvidia()
{
    const auto d = parseShaderLog(QStringLiteral("0(27) : error C1008: undefined variable \"foo\""),
                                  BuildStep::CompileVertex, QStringLiteral("a.vert"));
    QCOMPARE(d.size(), std::size_t(1));
    QCOMPARE(d[0].line, 27);
    QCOMPARE(d[0].column, 0);
    QCOMPARE(d[0].step, BuildStep::CompileVertex);
    QCOMPARE(d[0].message, QStringLiteral("undefined variable \"foo\""));
}

void TestShaderDiagnostic::parsesAmdStyle()
{
    const auto d = parseShaderLog(QStringLiteral("ERROR: 0:8: 'x' : undeclared identifier"),
                                  BuildStep::CompileFragment, {});
    QCOMPARE(d.size(), std::size_t(1));
    QCOMPARE(d[0].line, 8);
    QVERIFY(d[0].isError());
}

void TestShaderDiagnostic::parsesUnlocatedLinkError()
{
    const auto d =
        parseShaderLog(QStringLiteral("error: fragment shader input `v' has no matching output"),
                       BuildStep::Link, QStringLiteral("a.vert+a.frag"));
    QCOMPARE(d.size(), std::size_t(1));
    QCOMPARE(d[0].line, 0);
    QVERIFY(d[0].isError());
    QCOMPARE(
        d[0].format(),
        QStringLiteral("a.vert+a.frag: error: fragment shader input `v' has no matching output"));
}

void TestShaderDiagnostic::keepsContinuationLines()
{
    const auto d = parseShaderLog(
        QStringLiteral("0:4(1): error: syntax error, unexpected\n    NEW_IDENTIFIER"),
        BuildStep::CompileFragment, {});
    QCOMPARE(d.size(), std::size_t(1));
    QVERIFY(d[0].message.endsWith(QStringLiteral("NEW_IDENTIFIER")));
}

void TestShaderDiagnostic::subtractsPrologueLines()
{
    const auto d =
        parseShaderLog(QStringLiteral("0:5(2): error: a\n0:2(1): error: in the prologue"),
                       BuildStep::CompileFragment, {}, 3);
    QCOMPARE(d[0].line, 2);
    QCOMPARE(d[1].line, 0); // inside the injected lines: no user line to blame
    QCOMPARE(d[1].column, 0);
}

void TestShaderDiagnostic::formatsLikeACompiler()
{
    ShaderDiagnostic d;
    d.file = QStringLiteral("shaders/phong.frag");
    d.line = 17;
    d.column = 9;
    d.message = QStringLiteral("boom");
    QCOMPARE(d.format(), QStringLiteral("shaders/phong.frag:17:9: error: boom"));
    d.severity = ShaderDiagnostic::Severity::Warning;
    d.column = 0;
    QCOMPARE(d.format(), QStringLiteral("shaders/phong.frag:17: warning: boom"));
}

void TestShaderDiagnostic::prologueGoesAfterVersion()
{
    const QByteArray code = "// header\n#version 330 core\nvoid main() {}\n";
    const QByteArray out = withPrologue(code, {QStringLiteral("A 1"), QStringLiteral("B")});
    QCOMPARE(
        out,
        QByteArray(
            "// header\n#version 330 core\n#define A 1\n#define B\n#line 3\nvoid main() {}\n"));
}

void TestShaderDiagnostic::prologueWithoutVersion()
{
    // No #version line is a WebGL 1 shader: GLSL ES 1.00, which must say so to a
    // desktop driver. Mesa numbers ES 1.00 lines as 3.30 does: "#line 1" is line 1.
    const QByteArray out = withPrologue("void main() {}\n", {QStringLiteral("A")});
    QCOMPARE(out, QByteArray("#version 100\n#define A\n#line 1\nvoid main() {}\n"));
}

void TestShaderDiagnostic::prologueForOldGlsl()
{
    // Before GLSL 3.30, "#line N" numbers the following line N + 1.
    const QByteArray out = withPrologue("#version 120\nvoid main() {}\n", {QStringLiteral("A")});
    QCOMPARE(out, QByteArray("#version 120\n#define A\n#line 1\nvoid main() {}\n"));
}

void TestShaderDiagnostic::noDefinesLeavesTextAlone()
{
    const QByteArray code = "#version 330 core\nvoid main() {}\n";
    QCOMPARE(withPrologue(code, {}), code);
}

void TestShaderDiagnostic::columnsMapBackOverCollapsedWhitespace()
{
    // Mesa numbers columns after its preprocessor collapsed each whitespace
    // run: "    x =\t\tfoo" reads " x = foo", where foo is column 6.
    const QByteArray code = "line one\n    x =\t\tfoo;\nshort\n";
    std::vector<ShaderDiagnostic> d(3);
    d[0].line = 2;
    d[0].column = 6;
    d[1].line = 3;
    d[1].column = 40; // past the end of the line: unknown
    d[2].line = 9;
    d[2].column = 1; // no such line: unknown
    mapColumnsToSource(d, code);
    QCOMPARE(d[0].column, 10);
    QCOMPARE(d[0].line, 2);
    QCOMPARE(d[1].column, 0);
    QCOMPARE(d[2].column, 0);
}

void TestShaderDiagnostic::missingSemicolonPointsAtTheLineItBelongsTo()
{
    // Mesa finds "vec3 a = vec3(1.0)" unfinished at the c of the next line.
    const QByteArray code = "void main()\n{\n    vec3 a = vec3(1.0)   // note\n\n"
                            "    c = vec4(a, 1.0);\n    d = 1 e = 2;\n}\n";
    const QString expecting =
        QStringLiteral("syntax error, unexpected IDENTIFIER, expecting ',' or ';'");
    std::vector<ShaderDiagnostic> d(3);
    d[0].line = 5; // the first token of its line: moved
    d[0].column = 5;
    d[0].message = expecting;
    d[1].line = 6; // inside its line: the compiler's place is right
    d[1].column = 11;
    d[1].message = expecting;
    d[2].line = 5; // another error at a line's start: left alone
    d[2].column = 5;
    d[2].message = QStringLiteral("syntax error, unexpected IDENTIFIER");
    pointAtMissingSemicolons(d, code);
    QCOMPARE(d[0].line, 3);
    QCOMPARE(d[0].column, 23); // just past "vec3(1.0)", before the spaces and the comment
    QCOMPARE(d[1].line, 6);
    QCOMPARE(d[1].column, 11);
    QCOMPARE(d[2].line, 5);
    QCOMPARE(d[2].column, 5);
}

QTEST_APPLESS_MAIN(TestShaderDiagnostic)
#include "tst_shaderdiagnostic.moc"
