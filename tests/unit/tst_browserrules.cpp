// What the browser's WebGL does to a shader before its GPU sees it
// (core/program/BrowserRules): every variable and output left unset starts
// at zero, on the student's own lines. Whether the pixels then equal the
// browser's is tests/gl/tst_browserdifferential's.
#include "core/program/BrowserRules.h"

#include <QTest>

using namespace phonglab;

class TestBrowserRules : public QObject
{
    Q_OBJECT

private slots:
    void unsetVariablesStartAtZero_data();
    void unsetVariablesStartAtZero();
    void indicesAreClampedIntoTheArray();
    void valuesAndConstantsAreLeftAlone();
    void everyLineStaysTheStudents();
    void columnsMapBack();
    void survivesEveryPrefix();
};

void TestBrowserRules::unsetVariablesStartAtZero_data()
{
    QTest::addColumn<QByteArray>("code");
    QTest::addColumn<bool>("fragment");
    QTest::addColumn<QByteArray>("expected");
    QTest::addColumn<QStringList>("zeroed");

    QTest::newRow("local vec3") << QByteArray(
        "void main() {\n  vec3 acc;\n  acc += vec3(0.25);\n}\n")
                                << true
                                << QByteArray("void main() {\n  vec3 acc = vec3(0.0);\n  acc += "
                                              "vec3(0.25);\n}\n")
                                << QStringList{"acc"};
    QTest::newRow("scalars and a list")
        << QByteArray("void main() { highp float a, b = 1.0, c; int i; uint u; bool f; }") << true
        << QByteArray("void main() { highp float a = 0.0, b = 1.0, c = 0.0; int i = 0; uint u = "
                      "0u; bool f = false; }")
        << QStringList{"a", "c", "i", "u", "f"};
    QTest::newRow("matrix and ivec")
        << QByteArray("void main() { mat3 m; ivec2 k; bvec3 t; }") << true
        << QByteArray("void main() { mat3 m = mat3(0.0); ivec2 k = ivec2(0); bvec3 t = "
                      "bvec3(false); }")
        << QStringList{"m", "k", "t"};
    QTest::newRow("array, element by element")
        << QByteArray("void main() { float a[3]; a[1] += 0.5; }") << true
        << QByteArray("void main() { float a[3]; for (int phonglab_i = 0; phonglab_i < (3); "
                      "phonglab_i++) a[phonglab_i] = 0.0; a[1] += 0.5; }")
        << QStringList{"a"};
    QTest::newRow("struct, member by member")
        << QByteArray("#version 300 es\nstruct L { vec3 c; float k[2]; };\nvoid main() { L l; }")
        << true
        << QByteArray("#version 300 es\nstruct L { vec3 c; float k[2]; };\nvoid main() { L l = "
                      "L(vec3(0.0), float[2](0.0,0.0)); }")
        << QStringList{"l"};
    QTest::newRow("inside a loop body, each time")
        << QByteArray("void main() { for (int i = 0; i < 4; i++) { float t; t += 1.0; } }") << true
        << QByteArray("void main() { for (int i = 0; i < 4; i++) { float t = 0.0; t += 1.0; } }")
        << QStringList{"t"};
    QTest::newRow("global") << QByteArray("vec3 g;\nvoid main() { g += vec3(0.5); }") << true
                            << QByteArray("vec3 g = vec3(0.0);\nvoid main() { g += vec3(0.5); }")
                            << QStringList{"g"};
    QTest::newRow("es3 output")
        << QByteArray("#version 300 es\nlayout(location = 0) out vec4 fragColor;\nvoid main() {\n"
                      "  fragColor.r = 0.5;\n}\n")
        << true
        << QByteArray("#version 300 es\nlayout(location = 0) out vec4 fragColor;\nvoid main() { "
                      "fragColor = vec4(0.0);\n  fragColor.r = 0.5;\n}\n")
        << QStringList{"fragColor"};
    QTest::newRow("gl_FragColor")
        << QByteArray("void main() { gl_FragColor.r = 0.5; }") << true
        << QByteArray("void main() { gl_FragColor = vec4(0.0); gl_FragColor.r = 0.5; }")
        << QStringList{"gl_FragColor"};
    QTest::newRow("gl_FragData: its first, and no gl_FragColor")
        << QByteArray("void main() { if (x) gl_FragData[0] = vec4(1.0); }") << true
        << QByteArray("void main() { gl_FragData[0] = vec4(0.0); if (x) gl_FragData[0] = "
                      "vec4(1.0); }")
        << QStringList{"gl_FragData[0]"};
    QTest::newRow("vertex: varyings and gl_Position")
        << QByteArray("attribute vec2 p;\nvarying vec3 v;\nvoid main() { gl_Position = "
                      "vec4(p, 0.0, 1.0); }")
        << false
        << QByteArray("attribute vec2 p;\nvarying vec3 v;\nvoid main() { gl_Position = "
                      "vec4(0.0); v = vec3(0.0); gl_Position = vec4(p, 0.0, 1.0); }")
        << QStringList{"gl_Position", "v"};
    QTest::newRow("out parameter, on entry")
        << QByteArray("void f(in float a, out vec3 v, inout float w) { v.x = a; }\nvoid main() "
                      "{}")
        << true
        << QByteArray("void f(in float a, out vec3 v, inout float w) { v = vec3(0.0); v.x = a; "
                      "}\nvoid main() {}")
        << QStringList{"v"};
}

void TestBrowserRules::unsetVariablesStartAtZero()
{
    QFETCH(QByteArray, code);
    QFETCH(bool, fragment);
    QFETCH(QByteArray, expected);
    QFETCH(QStringList, zeroed);
    const BrowserRewrite r =
        applyBrowserRules(code, fragment ? ShaderStage::Fragment : ShaderStage::Vertex);
    QCOMPARE(r.code, expected);
    QCOMPARE(r.zeroed, zeroed);
}

void TestBrowserRules::indicesAreClampedIntoTheArray()
{
    // A uniform array, a local one sized by a macro, a parameter: each index
    // that is no number is clamped, as ANGLE does; declarations, number
    // indices and members of structs are left as written.
    const QByteArray code =
        "#version 300 es\n#define N 2\nuniform vec3 L[4], M[N];\nstruct S { float k[2]; };\n"
        "uniform S s;\nout vec4 o;\nfloat f(float p[2], int j) { return p[j]; }\n"
        "void main() {\n  float a[N] = float[N](1.0, 2.0);\n  int i = 5;\n"
        "  o = vec4(L[i] + M[i - 1] + L[0], a[i] + s.k[i] + f(a, i));\n}\n";
    const BrowserRewrite r = applyBrowserRules(code, ShaderStage::Fragment);
    const auto clamped = [](const char *array, const char *index, const char *size) {
        return QByteArray(array) + "[int(clamp(float(" + index + "), 0.0, float(" + size
            + ") - 1.0))]";
    };
    QVERIFY2(r.code.contains(clamped("L", "i", "4")), r.code.constData());
    QVERIFY(r.code.contains(clamped("M", "i - 1", "N")));
    QVERIFY(r.code.contains(clamped("a", "i", "N")));
    QVERIFY(r.code.contains(clamped("p", "j", "2")));
    QVERIFY(r.code.contains("L[0]"));
    QVERIFY(r.code.contains("s.k[i]"));
    QVERIFY(r.code.contains("uniform vec3 L[4], M[N];"));
    QVERIFY(r.code.contains("float a[N] = float[N](1.0, 2.0);"));
    QVERIFY(r.code.contains("float f(float p[2], int j)"));
    QCOMPARE(r.code.count('\n'), code.count('\n'));
}

void TestBrowserRules::valuesAndConstantsAreLeftAlone()
{
    const QByteArray code = "precision mediump float;\nuniform vec3 u;\nconst float k = 2.0;\n"
                            "varying vec3 v;\nstruct S { vec3 a; };\nuniform S s;\n"
                            "float helper(float x);\n"
                            "void main() {\n  const vec3 c = vec3(1.0);\n  vec3 a = u * k;\n"
                            "  vec3(1.0);\n  float b = max(a.x, 0.0), d = 1.0;\n"
                            "  for (int i = 0; i < 2; ++i) a += c;\n"
                            "  gl_FragData[0] = vec4(a + v, b + d);\n}\n";
    const BrowserRewrite r = applyBrowserRules(code, ShaderStage::Fragment);
    // The output alone, as main() starts.
    QCOMPARE(r.zeroed, QStringList{"gl_FragData[0]"});
    QCOMPARE(r.insertions.size(), std::size_t(1));
    QCOMPARE(
        r.code,
        QByteArray(code).replace("void main() {", "void main() { gl_FragData[0] = vec4(0.0);"));
}

void TestBrowserRules::everyLineStaysTheStudents()
{
    const QByteArray code = "#version 300 es\nprecision highp float;\nout vec4 o;\nvec3 g[2];\n"
                            "void main()\n{\n  vec3 a;\n  float b[4];\n\n  o = vec4(a, b[0]);\n}\n";
    const BrowserRewrite r = applyBrowserRules(code, ShaderStage::Fragment);
    QCOMPARE(r.code.count('\n'), code.count('\n'));
    const QList<QByteArray> before = code.split('\n');
    const QList<QByteArray> after = r.code.split('\n');
    for (qsizetype line = 0; line < before.size(); ++line)
        QVERIFY2(
            after[line].trimmed().startsWith(before[line].left(before[line].indexOf(';')).trimmed())
                || before[line].trimmed().isEmpty(),
            after[line].constData());
    QCOMPARE(r.zeroed, (QStringList{"a", "b", "o", "g"}));
}

void TestBrowserRules::columnsMapBack()
{
    // Line 1: "void main() { vec3 a; a.x = y; }" becomes
    //         "void main() { vec3 a = vec3(0.0); a.x = y; }": `y` at 29 in
    // the source, 41 after the insertion of 12 characters at column 21.
    const QByteArray code = "void main() { vec3 a; a.x = y; }";
    const BrowserRewrite r = applyBrowserRules(code, ShaderStage::Fragment);
    QCOMPARE(r.insertions.size(), std::size_t(1));
    QCOMPARE(r.insertions[0].column, 21);
    QCOMPARE(r.code.indexOf('y') + 1, 41);
    QCOMPARE(r.sourceColumn(1, 41), 29);
    QCOMPARE(r.sourceColumn(1, 15), 15); // before the insertion: as it was
    QCOMPARE(r.sourceColumn(1, 25), 21); // inside it: where it went in
    QCOMPARE(r.sourceColumn(2, 41), 41); // another line: as it was
}

void TestBrowserRules::survivesEveryPrefix()
{
    // Cut anywhere (an editor's text while typing): no crash, no hang, and the
    // text grows only by what was inserted.
    const QByteArray code =
        "#version 300 es\nstruct L { vec3 c; float k[2]; } ;\nout vec4 o;\nL ls[2];\n"
        "void f(out L l, out float z[2]) { l.c = vec3(1.0); }\n"
        "void main() { L l; float a[2], b; for (int i = 0; i < 2; i++) { vec3 t; t += l.c; } "
        "f(l, a); o = vec4(l.c, b); }\n";
    for (qsizetype cut = 0; cut <= code.size(); ++cut) {
        const QByteArray prefix = code.left(cut);
        for (ShaderStage stage : {ShaderStage::Vertex, ShaderStage::Fragment}) {
            const BrowserRewrite r = applyBrowserRules(prefix, stage);
            qsizetype added = 0;
            for (const SourceInsertion &at : r.insertions)
                added += at.text.size();
            QCOMPARE(r.code.size(), prefix.size() + added);
        }
    }
}

QTEST_GUILESS_MAIN(TestBrowserRules)
#include "tst_browserrules.moc"
