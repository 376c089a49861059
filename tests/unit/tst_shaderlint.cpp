// The static lint of students' shaders (core/program/ShaderLint): values GLSL
// leaves undefined, which no one image can be trusted to show (a driver may read
// them as 0).
#include "core/program/ShaderLint.h"

#include <QTest>

using namespace phonglab;
using Kind = LintFinding::Kind;

Q_DECLARE_METATYPE(LintFinding::Kind)

class TestShaderLint : public QObject
{
    Q_OBJECT

private slots:
    void correctShadersGiveNothing_data();
    void correctShadersGiveNothing();
    void bugsAreFoundWhereTheyAre_data();
    void bugsAreFoundWhereTheyAre();
    void eachVariableOnce();
    void messageNamesTheVariable();
    void survivesEveryPrefix();
};

// A WebGL 1 Phong fragment shader as a course hands it in.
static const char kWebGl1Phong[] = R"glsl(precision mediump float;

#define MAX_LIGHTS 4

varying vec3 vNormal;
varying vec3 vPosition;

uniform vec3 lightPosition[MAX_LIGHTS];
uniform vec3 Id[MAX_LIGHTS];
uniform vec3 Is[MAX_LIGHTS];
uniform int lightCount;
uniform vec3 Ia, ka, kd, ks;
uniform float shininess;

void main()
{
    vec3 N = normalize(vNormal);
    vec3 V = normalize(-vPosition);
    vec3 result = vec3(0.0); // result += per light below
    for (int i = 0; i < MAX_LIGHTS; ++i) {
        if (i >= lightCount)
            break;
        vec3 L = normalize(lightPosition[i] - vPosition);
        vec3 R = reflect(-L, N);
        float NdotL = max(dot(N, L), 0.0);
        float spec = 0.0;
        if (NdotL > 0.0)
            spec = pow(max(dot(R, V), 0.0), shininess);
        result += kd * Id[i] * NdotL + ks * Is[i] * spec;
    }
    gl_FragColor = vec4(Ia * ka + result, 1.0);
}
)glsl";

void TestShaderLint::correctShadersGiveNothing_data()
{
    QTest::addColumn<QByteArray>("code");
    const auto ok = [](const char *tag, const char *code) {
        QTest::newRow(tag) << QByteArray(code);
    };
    ok("webgl1 phong with a light loop", kWebGl1Phong);
    ok("webgl2 output written, then read", R"glsl(#version 300 es
precision highp float;
in vec3 vNormal;
uniform vec3 ambient;
layout(location = 0) out vec4 fragColor;
void main()
{
    fragColor = vec4(normalize(vNormal) * 0.5 + 0.5, 1.0);
    fragColor += vec4(ambient, 0.0);
    fragColor.rgb = fragColor.rgb * 0.9;
}
)glsl");
    ok("both branches of if/else", R"glsl(varying float vShade;
void main()
{
    vec3 color;
    if (vShade > 0.5) {
        color = vec3(1.0);
    } else if (vShade > 0.2) {
        color = vec3(0.5);
    } else
        color = vec3(0.0);
    gl_FragColor = vec4(color, 1.0);
}
)glsl");
    ok("struct fields and arrays", R"glsl(struct Light {
    vec3 position;
    vec3 color;
};
uniform vec3 lp;
void main()
{
    Light light;
    light.position = lp;
    light.color = vec3(1.0);
    vec3 a[2];
    a[0] = light.position;
    a[1] = light.color;
    vec3 c;
    c.x = 1.0;
    gl_FragColor = vec4(a[0] + a[1] + c, float(a.length()));
}
)glsl");
    ok("loop counters, set inside a loop, used after", R"glsl(void main()
{
    float w[4];
    for (int i = 0; i < 4; i++)
        w[i] = float(i);
    float last;
    int k = 0;
    while (k < 3) {
        last = w[k];
        k++;
    }
    gl_FragColor = vec4(w[0], w[3], last, 1.0);
}
)glsl");
    ok("out parameter and unknown call", R"glsl(#version 330 core
out vec4 outColor;
void shade(in vec3 n, out vec3 color, inout float energy)
{
    color = n * energy;
    energy *= 0.5;
}
void main()
{
    vec3 c;
    float e = 1.0;
    shade(vec3(1.0), c, e);
    float whole;
    float part = modf(2.5, whole);
    outColor = vec4(c * part * whole, e);
}
)glsl");
    ok("defines and comments mention the bug", R"glsl(#define ACCUMULATE(v, x) v += x
#define ZERO vec3(0.0)
// vec3 result; result += light; would be the bug
/* for (...) result += ...;
   and fragColor += ... */
void main()
{
    vec3 result = ZERO;
    ACCUMULATE(result, vec3(0.1));
    gl_FragColor = vec4(result, 1.0);
}
)glsl");
    ok("one branch only, maybe set", R"glsl(uniform bool on;
void main()
{
    float x;
    if (on)
        x = 1.0;
    gl_FragColor = vec4(x);
}
)glsl");
    ok("read under a condition, set later in the loop", R"glsl(void main()
{
    float prev;
    float sum = 0.0;
    for (int i = 0; i < 4; ++i) {
        if (i > 0)
            sum += prev;
        sum += (i > 1 && prev > 0.0) ? 1.0 : 0.0;
        prev = float(i);
    }
    gl_FragColor = vec4(sum);
}
)glsl");
    ok("parameters, shadowing and a helper writing the output", R"glsl(#version 300 es
precision mediump float;
out vec4 fragColor;
uniform vec3 lightColor;
in vec3 vColor;
vec3 tint(vec3 result) { result *= lightColor; return result; }
void setColor() { fragColor = vec4(vColor, 1.0); }
void main()
{
    setColor();
    fragColor.rgb += tint(vColor);
    vec3 a = vColor, b;
    b = a;
    {
        vec3 a;
        a = b;
    }
    fragColor.a = a.x * b.y;
}
)glsl");
    ok("varyings, uniforms and ES 1.00 outputs", R"glsl(attribute vec3 position;
varying vec3 vNormal;
uniform mat4 mvp;
void main()
{
    vNormal = position;
    gl_Position = mvp * vec4(position, 1.0);
    gl_Position.z += vNormal.z * 0.0;
}
)glsl");
    ok("loop bodies without braces, do-while", R"glsl(uniform vec3 v;
void main()
{
    float p;
    float s = 0.0;
    for (int i = 0; i < 4; ++i)
        if (i > 0)
            s += p;
        else
            p = 1.0;
    float q;
    do {
        q = s;
    } while (q < 0.0);
    gl_FragColor = vec4(s, q, p, 1.0);
}
)glsl");
    ok("helper called through a macro", R"glsl(#version 300 es
precision mediump float;
#define MAX_LIGHTS 2
#define SHADE shade()
out vec4 fragColor;
void shade() { fragColor = vec4(0.0); }
void main()
{
    SHADE;
    for (int i = 0; i < MAX_LIGHTS; ++i)
        fragColor += vec4(0.1);
}
)glsl");
    ok("switch over all cases", R"glsl(#version 300 es
precision mediump float;
uniform int mode;
out vec4 color;
void main()
{
    float k;
    switch (mode) {
    case 0: k = 0.5; break;
    default: k = 1.0; break;
    }
    color = vec4(k);
}
)glsl");
}

void TestShaderLint::correctShadersGiveNothing()
{
    QFETCH(QByteArray, code);
    const std::vector<LintFinding> found = lintShader(code);
    for (const LintFinding &f : found)
        qWarning("unexpected: %d:%d %s", f.line, f.column, qPrintable(f.message));
    QVERIFY(found.empty());
}

void TestShaderLint::bugsAreFoundWhereTheyAre_data()
{
    QTest::addColumn<QByteArray>("code");
    QTest::addColumn<int>("line");
    QTest::addColumn<int>("column");
    QTest::addColumn<QString>("variable");
    QTest::addColumn<Kind>("kind");
    const auto bug = [](const char *tag, int line, int column, const char *variable, Kind kind,
                        const char *code) {
        QTest::newRow(tag) << QByteArray(code) << line << column << QString::fromLatin1(variable)
                           << kind;
    };
    bug("accumulator never started", 7, 9, "result", Kind::ReadBeforeSet,
        R"glsl(precision mediump float;
uniform vec3 Id[4];
void main()
{
    vec3 result;
    for (int i = 0; i < 4; ++i)
        result += Id[i];
    gl_FragColor = vec4(result, 1.0);
}
)glsl");
    bug("read on the right of its first write", 4, 9, "x", Kind::ReadBeforeSet,
        R"glsl(void main()
{
    float x;
    x = x * 2.0;
    gl_FragColor = vec4(x);
}
)glsl");
    bug("output accumulated first", 7, 5, "fragColor", Kind::OutputReadBeforeWritten,
        R"glsl(#version 300 es
precision highp float;
uniform vec3 ambient;
out vec4 fragColor;
void main()
{
    fragColor += vec4(ambient, 0.0);
    fragColor.a = 1.0;
}
)glsl");
    bug("output accumulated in a light loop", 10, 9, "fragColor", Kind::OutputReadBeforeWritten,
        R"glsl(#version 300 es
precision mediump float;
#define MAX_LIGHTS 2
uniform vec3 Id[MAX_LIGHTS];
out vec4 fragColor;
vec3 diffuse(int i) { return Id[i]; }
void main()
{
    for (int i = 0; i < MAX_LIGHTS; ++i)
        fragColor.rgb += diffuse(i);
    fragColor.a = 1.0;
}
)glsl");
    bug("output swizzle scaled first", 6, 2, "outColor", Kind::OutputReadBeforeWritten,
        R"glsl(#version 330 core
layout(location = 0) out vec4 outColor;
uniform float x;
void main()
{
	outColor.rgb *= x;
	outColor = vec4(1.0);
}
)glsl");
    bug("read in an expression", 5, 13, "result", Kind::ReadBeforeSet,
        R"glsl(varying vec3 vColor;
void main()
{
    vec3 color = vColor, result;
    color = result * 2.0;
    result = color;
    gl_FragColor = vec4(color + result, 1.0);
}
)glsl");
    bug("after a comment naming it", 5, 35, "n", Kind::ReadBeforeSet,
        R"glsl(void main()
{
    vec3 n; /* n is set below: n = ... */
    // n += vec3(1.0);
    gl_FragColor = vec4(normalize(n), 1.0); n = vec3(0.0);
}
)glsl");
    bug("set in one branch, read in the other", 8, 29, "s", Kind::ReadBeforeSet,
        R"glsl(uniform bool on;
void main()
{
    float s;
    if (on)
        s = 1.0;
    else
        gl_FragColor = vec4(s);
}
)glsl");
    bug("passed to an in parameter", 5, 39, "d", Kind::ReadBeforeSet,
        R"glsl(float twice(float v) { return 2.0 * v; }
void main()
{
    float d;
    /* é */ gl_FragColor = vec4(twice(d));
}
)glsl");
    bug("incremented in a loop", 6, 13, "count", Kind::ReadBeforeSet,
        R"glsl(void main()
{
    int count;
    for (int i = 0; i < 3; ++i) {
        if (i > 1)
            count++;
    }
    gl_FragColor = vec4(float(count));
}
)glsl");
}

void TestShaderLint::bugsAreFoundWhereTheyAre()
{
    QFETCH(QByteArray, code);
    QFETCH(int, line);
    QFETCH(int, column);
    QFETCH(QString, variable);
    QFETCH(Kind, kind);
    const std::vector<LintFinding> found = lintShader(code);
    QCOMPARE(found.size(), std::size_t(1));
    QCOMPARE(found[0].line, line);
    QCOMPARE(found[0].column, column);
    QCOMPARE(found[0].variable, variable);
    QCOMPARE(found[0].kind, kind);
}

void TestShaderLint::eachVariableOnce()
{
    const std::vector<LintFinding> found = lintShader(R"glsl(#version 300 es
precision highp float;
out vec4 fragColor;
uniform bool on;
void main()
{
    vec3 a, b;
    if (on)
        fragColor = vec4(a, 1.0);
    else
        fragColor = vec4(a + b, 1.0);
    fragColor.rgb += a + b;
}
)glsl");
    QCOMPARE(found.size(), std::size_t(2));
    QCOMPARE(found[0].variable, QStringLiteral("a"));
    QCOMPARE(found[0].line, 9);
    QCOMPARE(found[1].variable, QStringLiteral("b"));
    QCOMPARE(found[1].line, 11);
    QCOMPARE(found[1].column, 30);
}

void TestShaderLint::messageNamesTheVariable()
{
    const std::vector<LintFinding> found =
        lintShader("out vec4 o; void main() { vec3 r; o += vec4(r, 1.0); }");
    QCOMPARE(found.size(), std::size_t(2));
    QCOMPARE(found[0].kind, Kind::OutputReadBeforeWritten);
    QVERIFY(found[0].message.contains(QStringLiteral("'o'")));
    QCOMPARE(found[1].kind, Kind::ReadBeforeSet);
    QVERIFY(found[1].message.startsWith(QStringLiteral("'r' is read before it is set")));
}

// An editor lints while the student types: every cut of a shader is checked
// without a crash, and the comments' bugs never show.
void TestShaderLint::survivesEveryPrefix()
{
    const QByteArray whole(kWebGl1Phong);
    for (qsizetype size = 0; size <= whole.size(); ++size)
        QVERIFY(lintShader(whole.left(size)).empty());
}

QTEST_APPLESS_MAIN(TestShaderLint)
#include "tst_shaderlint.moc"
