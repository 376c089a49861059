// The Uniforms dock's two sources of truth: the linked program, which says
// which uniforms are active and of what type (glGetActiveUniform), and the
// shader text, which says what was declared and how to edit it
// (// @range lo hi, @color, @step s).
#include "ResultChecks.h"
#include "core/program/UniformAnnotations.h"
#include "render/draw/OffscreenRenderer.h"
#include "render/gl/GlFormat.h"
#include "render/program/ShaderProgram.h"
#include "render/program/UniformIntrospection.h"

#include <QFile>
#include <QOpenGLContext>
#include <QTest>

using namespace phonglab;

namespace {

const QByteArray kVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
void main() { gl_Position = vec4(position, 1.0); }
)";

// `unused` is declared but feeds nothing: the compiler drops it.
const QByteArray kWithUnused = R"(#version 330 core
uniform float gain; // @range 0 2
uniform float unused; // @range 0 1
out vec4 color;
void main() { color = vec4(gain); }
)";

QByteArray readShader(const QString &name)
{
    QFile file(QStringLiteral(PHONGLAB_SOURCE_DIR "/shaders/") + name);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

const ActiveUniformInfo *findActive(const std::vector<ActiveUniformInfo> &list,
                                    const QByteArray &name)
{
    for (const ActiveUniformInfo &u : list)
        if (u.name == name)
            return &u;
    return nullptr;
}

} // namespace

class TestUniformIntrospection : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void phongProgramListsItsActiveUniforms();
    void unusedUniformIsDeclaredButInactive();
    void parsesAnnotations();
    void parsesDeclarations();
    void ignoresCommentsAndOtherLines();

private:
    std::vector<ActiveUniformInfo> build(const QByteArray &vertex, const QByteArray &fragment);

    OffscreenRenderer m_offscreen;
    ShaderProgram m_program;
};

void TestUniformIntrospection::initTestCase()
{
    QSurfaceFormat::setDefaultFormat(phonglabSurfaceFormat(0));
    QVERIFY_OK(m_offscreen.create());
}

void TestUniformIntrospection::cleanupTestCase()
{
    m_offscreen.makeCurrent();
    m_program.destroy();
}

std::vector<ActiveUniformInfo> TestUniformIntrospection::build(const QByteArray &vertex,
                                                               const QByteArray &fragment)
{
    m_offscreen.makeCurrent();
    const BuildReport r =
        m_program.build({QStringLiteral("v"), vertex}, {QStringLiteral("f"), fragment});
    if (!r.ok)
        qWarning("%s", qPrintable(r.errorSummary()));
    return activeUniformsOf(QOpenGLContext::currentContext()->extraFunctions(), m_program.id());
}

void TestUniformIntrospection::phongProgramListsItsActiveUniforms()
{
    const std::vector<ActiveUniformInfo> active =
        build(readShader("phong.vert"), readShader("phong.frag"));
    QVERIFY(m_program.isValid());
    QStringList names;
    for (const ActiveUniformInfo &u : active)
        names.append(QString::fromUtf8(u.name));
    const QStringList expected = {"Ia",
                                  "Id",
                                  "Is",
                                  "attenuation",
                                  "ka",
                                  "kd",
                                  "ks",
                                  "lightCount",
                                  "lightPosition",
                                  "modelViewMatrix",
                                  "normalMatrix",
                                  "projectionMatrix",
                                  "shininess",
                                  "viewMatrix"};
    QCOMPARE(names, expected); // sorted by name (byte order: capitals first)

    struct Expect {
        const char *name;
        GLenum type;
        int size;
        bool isArray;
    };
    const Expect checks[] = {
        {"kd", GL_FLOAT_VEC3, 1, false},           {"shininess", GL_FLOAT, 1, false},
        {"lightCount", GL_INT, 1, false},          {"Id", GL_FLOAT_VEC3, 8, true},
        {"lightPosition", GL_FLOAT_VEC3, 8, true}, {"modelViewMatrix", GL_FLOAT_MAT4, 1, false},
        {"normalMatrix", GL_FLOAT_MAT3, 1, false},
    };
    for (const Expect &e : checks) {
        const ActiveUniformInfo *u = findActive(active, e.name);
        QVERIFY2(u, e.name);
        QCOMPARE(u->type, e.type);
        QCOMPARE(u->size, e.size);
        QCOMPARE(u->isArray, e.isArray);
        QVERIFY(u->location >= 0);
    }
    QCOMPARE(glslTypeName(GL_FLOAT_VEC3), QStringLiteral("vec3"));
    QCOMPARE(glslTypeName(GL_FLOAT_MAT4), QStringLiteral("mat4"));
}

void TestUniformIntrospection::unusedUniformIsDeclaredButInactive()
{
    const std::vector<ActiveUniformInfo> active = build(kVertex, kWithUnused);
    QVERIFY(findActive(active, "gain"));
    QVERIFY(!findActive(active, "unused"));

    const std::vector<UniformDeclaration> declared =
        parseUniformDeclarations(QString::fromUtf8(kWithUnused));
    QCOMPARE(int(declared.size()), 2);
    QCOMPARE(declared[1].name, QStringLiteral("unused"));
}

void TestUniformIntrospection::parsesAnnotations()
{
    const auto declared =
        parseUniformDeclarations(QStringLiteral("uniform float gain; // @range 0 2 @step 0.05\n"
                                                "uniform vec3 tint;  // the tint @color\n"
                                                "uniform float bad;  // @range 2 1 @step -1\n"
                                                "uniform float plain;\n"));
    QCOMPARE(int(declared.size()), 4);
    QVERIFY(declared[0].hasRange());
    QCOMPARE(*declared[0].rangeLow, 0.0);
    QCOMPARE(*declared[0].rangeHigh, 2.0);
    QCOMPARE(*declared[0].step, 0.05);
    QVERIFY(!declared[0].color);
    QVERIFY(declared[1].color);
    QVERIFY(!declared[1].hasRange());
    QVERIFY(!declared[2].hasRange()); // reversed: ignored
    QVERIFY(!declared[2].step);       // not positive: ignored
    QVERIFY(!declared[3].hasRange() && !declared[3].color && !declared[3].step);
}

void TestUniformIntrospection::parsesDeclarations()
{
    const auto declared = parseUniformDeclarations(
        QStringLiteral("const int MAX_LIGHTS = 8;\n"
                       "uniform vec3 Id[MAX_LIGHTS];   // diffuse intensity\n"
                       "uniform float a, b[4], c; // @range -1 1\n"
                       "layout(location = 3) uniform highp mat4 m;\n"
                       "  uniform sampler2D image;\n"));
    QCOMPARE(int(declared.size()), 6);
    QCOMPARE(declared[0].name, QStringLiteral("Id"));
    QCOMPARE(declared[0].type, QStringLiteral("vec3"));
    QVERIFY(declared[0].isArray);
    QCOMPARE(declared[0].arraySize, 0); // sized by a constant
    QCOMPARE(declared[1].name, QStringLiteral("a"));
    QCOMPARE(declared[2].name, QStringLiteral("b"));
    QVERIFY(declared[2].isArray);
    QCOMPARE(declared[2].arraySize, 4);
    QCOMPARE(declared[3].name, QStringLiteral("c"));
    for (int i = 1; i <= 3; ++i) {
        QCOMPARE(declared[size_t(i)].type, QStringLiteral("float"));
        QCOMPARE(*declared[size_t(i)].rangeLow, -1.0); // every declarator of the line
    }
    QCOMPARE(declared[4].name, QStringLiteral("m"));
    QCOMPARE(declared[4].type, QStringLiteral("mat4"));
    QCOMPARE(declared[5].type, QStringLiteral("sampler2D"));
}

void TestUniformIntrospection::ignoresCommentsAndOtherLines()
{
    const auto declared =
        parseUniformDeclarations(QStringLiteral("// uniform float commented;\n"
                                                "/* uniform float blocked;\n"
                                                "   uniform float stillBlocked; */\n"
                                                "in vec3 normalCam;\n"
                                                "uniform Lights { vec3 p; };\n"
                                                "uniform float kept;\n"));
    QCOMPARE(int(declared.size()), 1);
    QCOMPARE(declared[0].name, QStringLiteral("kept"));
    // phong.frag declares 11 of the program's 14 uniforms (the matrices are in phong.vert).
    QCOMPARE(int(parseUniformDeclarations(QString::fromUtf8(readShader("phong.frag"))).size()), 11);
}

QTEST_MAIN(TestUniformIntrospection)
#include "tst_uniformintrospection.moc"
