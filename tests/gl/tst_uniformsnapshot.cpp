// Uniform values survive a rebuild: ShaderProgram::snapshot() reads every
// active uniform through the driver, restore() sets them on a new program
// where name and type match, and nothing else.
#include "ResultChecks.h"
#include "render/draw/OffscreenRenderer.h"
#include "render/gl/GlFormat.h"
#include "render/program/ProgramBuilder.h"
#include "render/program/ShaderProgram.h"

#include <QTest>

using namespace phonglab;

namespace {

const QByteArray kVertex = R"(#version 330 core
layout(location = 0) in vec3 position;
void main() { gl_Position = vec4(position, 1.0); }
)";

// Every uniform feeds the output, so none is optimised away.
const QByteArray kFirst = R"(#version 330 core
uniform float gain;
uniform vec3 tint;
uniform int mode;
uniform uint mask;
uniform bool flag;
uniform mat3 basis;
uniform vec2 offsets[3];
uniform sampler2D image;
out vec4 color;
void main() {
    vec3 c = tint * gain + basis * vec3(offsets[0] + offsets[1] + offsets[2], float(mode));
    c += texture(image, vec2(0.5)).rgb + vec3(float(mask), flag ? 1.0 : 0.0, 0.0);
    color = vec4(c, 1.0);
}
)";

// Same names, some of other types or sizes: `tint` is now a vec4, `offsets`
// has two elements, `mode` is gone, `extra` is new.
const QByteArray kSecond = R"(#version 330 core
uniform float gain;
uniform vec4 tint;
uniform uint mask;
uniform bool flag;
uniform mat3 basis;
uniform vec2 offsets[2];
uniform sampler2D image;
uniform float extra;
out vec4 color;
void main() {
    vec3 c = tint.rgb * gain + basis * vec3(offsets[0] + offsets[1], extra);
    c += texture(image, vec2(0.5)).rgb + vec3(float(mask), flag ? 1.0 : 0.0, 0.0);
    color = vec4(c, 1.0);
}
)";

} // namespace

class TestUniformSnapshot : public QObject, protected QOpenGLExtraFunctions
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void snapshotReadsEveryActiveUniform();
    void restoreMatchesNameAndType();
    void adoptKeepsProgramAndFreesOld();

private:
    void build(ShaderProgram &program, const QByteArray &fragment);
    void setFirstValues();

    OffscreenRenderer m_offscreen;
    ShaderProgram m_first;
    ShaderProgram m_second;
};

void TestUniformSnapshot::initTestCase()
{
    QSurfaceFormat::setDefaultFormat(phonglabSurfaceFormat(0));
    QVERIFY_OK(m_offscreen.create());
    m_offscreen.makeCurrent();
    initializeOpenGLFunctions();
}

void TestUniformSnapshot::cleanupTestCase()
{
    m_offscreen.makeCurrent();
    m_first.destroy();
    m_second.destroy();
}

void TestUniformSnapshot::build(ShaderProgram &program, const QByteArray &fragment)
{
    const BuildReport r =
        program.build({QStringLiteral("v"), kVertex}, {QStringLiteral("f"), fragment});
    QVERIFY2(r.ok, qPrintable(r.errorSummary()));
}

void TestUniformSnapshot::setFirstValues()
{
    m_first.bind();
    glUniform1f(m_first.uniformLocation("gain"), 0.75f);
    glUniform3f(m_first.uniformLocation("tint"), 0.1f, 0.2f, 0.3f);
    glUniform1i(m_first.uniformLocation("mode"), 7);
    glUniform1ui(m_first.uniformLocation("mask"), 5u);
    glUniform1i(m_first.uniformLocation("flag"), 1);
    const glm::mat3 basis(1, 2, 3, 4, 5, 6, 7, 8, 9);
    glUniformMatrix3fv(m_first.uniformLocation("basis"), 1, GL_FALSE, &basis[0][0]);
    const GLfloat offsets[6] = {0.5f, 1.5f, 2.5f, 3.5f, 4.5f, 5.5f};
    glUniform2fv(m_first.uniformLocation("offsets"), 3, offsets);
    glUniform1i(m_first.uniformLocation("image"), 3);
    glUseProgram(0);
}

void TestUniformSnapshot::snapshotReadsEveryActiveUniform()
{
    build(m_first, kFirst);
    setFirstValues();
    const UniformSnapshot snapshot = m_first.snapshot();
    QCOMPARE(int(snapshot.values.size()), 10); // 7 plain + 3 array elements

    const UniformValue *gain = snapshot.find("gain");
    QVERIFY(gain);
    QCOMPARE(gain->type, GLenum(GL_FLOAT));
    QCOMPARE(gain->floats[0], 0.75f);
    const UniformValue *basis = snapshot.find("basis");
    QVERIFY(basis);
    QCOMPARE(basis->components, 9);
    QCOMPARE(basis->floats[8], 9.0f);
    QCOMPARE(snapshot.find("offsets[2]")->floats[1], 5.5f);
    QCOMPARE(snapshot.find("mode")->ints[0], 7);
    QCOMPARE(snapshot.find("mask")->uints[0], 5u);
    QCOMPARE(snapshot.find("flag")->ints[0], 1);
    QCOMPARE(snapshot.find("image")->ints[0], 3);
}

void TestUniformSnapshot::restoreMatchesNameAndType()
{
    build(m_first, kFirst);
    setFirstValues();
    const UniformSnapshot before = m_first.snapshot();
    build(m_second, kSecond);
    m_second.restore(before);
    const UniformSnapshot after = m_second.snapshot();

    QCOMPARE(after.find("gain")->floats[0], 0.75f);
    QCOMPARE(after.find("mask")->uints[0], 5u);
    QCOMPARE(after.find("flag")->ints[0], 1);
    QCOMPARE(after.find("basis")->floats[4], 5.0f);
    QCOMPARE(after.find("image")->ints[0], 3);
    QCOMPARE(after.find("offsets[0]")->floats[0], 0.5f);
    QCOMPARE(after.find("offsets[1]")->floats[1], 3.5f);
    QVERIFY(!after.find("offsets[2]"));
    // Another type under the same name keeps the new program's default.
    QCOMPARE(after.find("tint")->type, GLenum(GL_FLOAT_VEC4));
    QCOMPARE(after.find("tint")->floats[0], 0.0f);
    QCOMPARE(after.find("extra")->floats[0], 0.0f);

    GLint current = -1;
    glGetIntegerv(GL_CURRENT_PROGRAM, &current);
    QCOMPARE(current, 0); // restore() puts back whatever was bound
}

void TestUniformSnapshot::adoptKeepsProgramAndFreesOld()
{
    build(m_first, kFirst);
    const GLuint old = m_first.id();
    BuiltProgram built =
        ProgramBuilder().build({QStringLiteral("v"), kVertex}, {QStringLiteral("f"), kSecond});
    QVERIFY2(built.ok(), qPrintable(built.report.errorSummary()));
    QVERIFY(built.compileNs > 0 && built.linkNs > 0);
    const GLuint adopted = built.program.id();
    m_first.adopt(std::move(built.program));
    QVERIFY(!built.program); // one owner: the shader program
    QCOMPARE(m_first.id(), adopted);
    QVERIFY(glIsProgram(adopted));
    QVERIFY(!glIsProgram(old));
}

QTEST_MAIN(TestUniformSnapshot)
#include "tst_uniformsnapshot.moc"
