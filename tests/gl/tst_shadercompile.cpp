// Compiling through the real driver: every diagnostic lands on the line the
// user wrote, and a failed build never replaces the program that works.
#include "RenderCheck.h"
#include "ResultChecks.h"
#include "render/draw/OffscreenRenderer.h"
#include "render/gl/GlFormat.h"
#include "render/program/ShaderProgram.h"

#include <QTest>

using namespace phonglab;
using namespace phonglab::test;

class TestShaderCompile : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void shippedShadersCompileCleanly();
    void fragmentErrorOnUserLine_data();
    void fragmentErrorOnUserLine();
    void vertexErrorOnUserLine();
    void linkErrorIsReported();
    void warningsAreNotErrors();
    void failedBuildKeepsPreviousProgram();

private:
    static const ShaderDiagnostic *firstError(const BuildReport &r);
    OffscreenRenderer m_offscreen; // provides the current context
    ShaderProgram m_program;
};

const ShaderDiagnostic *TestShaderCompile::firstError(const BuildReport &r)
{
    for (const ShaderDiagnostic &d : r.diagnostics)
        if (d.isError())
            return &d;
    return nullptr;
}

void TestShaderCompile::initTestCase()
{
    QSurfaceFormat::setDefaultFormat(phonglabSurfaceFormat(0));
    QVERIFY_OK(m_offscreen.create());
    m_offscreen.makeCurrent();
    qInfo("GL renderer: %s", qPrintable(m_offscreen.glRendererName()));
}

void TestShaderCompile::cleanupTestCase()
{
    m_offscreen.makeCurrent();
    m_program.destroy();
}

void TestShaderCompile::shippedShadersCompileCleanly()
{
    const BuildReport r = m_program.build(shippedShader(QStringLiteral("phong.vert")),
                                          shippedShader(QStringLiteral("phong.frag")));
    QVERIFY2(r.ok, qPrintable(r.errorSummary()));
    QVERIFY2(r.diagnostics.empty(), qPrintable(r.errorSummary()));
}

void TestShaderCompile::fragmentErrorOnUserLine_data()
{
    QTest::addColumn<QStringList>("defines");
    QTest::newRow("as written") << QStringList();
    // An injected prologue shifts the driver's numbering; #line maps it back.
    QTest::newRow("with injected prologue") << QStringList{
        QStringLiteral("PHONGLAB 1"), QStringLiteral("EXTRA 2"), QStringLiteral("MORE 3")};
}

void TestShaderCompile::fragmentErrorOnUserLine()
{
    QFETCH(QStringList, defines);
    const ShaderSource fs = testShader(QStringLiteral("shaders/error_line17.frag"));
    const BuildReport r = m_program.build(shippedShader(QStringLiteral("phong.vert")), fs, defines);
    QVERIFY(!r.ok);
    const ShaderDiagnostic *e = firstError(r);
    QVERIFY(e);
    qInfo("%s", qPrintable(e->format()));
    QCOMPARE(e->step, BuildStep::CompileFragment);
    QCOMPARE(e->file, fs.name);
    QCOMPARE(e->line, 17);
    QCOMPARE(e->column, 9); // `undeclaredThing` starts at column 9 of the user's line
    QVERIFY(e->message.contains(QStringLiteral("undeclaredThing")));
    QVERIFY(e->format().startsWith(fs.name + QStringLiteral(":17:9: error: ")));
}

void TestShaderCompile::vertexErrorOnUserLine()
{
    const ShaderSource vs = testShader(QStringLiteral("shaders/error_line9.vert"));
    const BuildReport r = m_program.build(vs, shippedShader(QStringLiteral("phong.frag")));
    QVERIFY(!r.ok);
    const ShaderDiagnostic *e = firstError(r);
    QVERIFY(e);
    QCOMPARE(e->step, BuildStep::CompileVertex);
    QCOMPARE(e->line, 9);
}

void TestShaderCompile::linkErrorIsReported()
{
    const BuildReport r = m_program.build(shippedShader(QStringLiteral("phong.vert")),
                                          testShader(QStringLiteral("shaders/link_no_main.frag")));
    QVERIFY(!r.ok);
    const ShaderDiagnostic *e = firstError(r);
    QVERIFY(e);
    QCOMPARE(e->step, BuildStep::Link);
    QVERIFY2(!e->message.isEmpty(), "a failed link must say why");
}

void TestShaderCompile::warningsAreNotErrors()
{
    const BuildReport r = m_program.build(shippedShader(QStringLiteral("phong.vert")),
                                          testShader(QStringLiteral("shaders/warning_only.frag")));
    QVERIFY2(r.ok, qPrintable(r.errorSummary()));
    QVERIFY(!r.hasErrors());
    for (const ShaderDiagnostic &d : r.diagnostics)
        QVERIFY(!d.isError());
}

void TestShaderCompile::failedBuildKeepsPreviousProgram()
{
    QVERIFY(m_program
                .build(shippedShader(QStringLiteral("phong.vert")),
                       shippedShader(QStringLiteral("phong.frag")))
                .ok);
    const GLuint good = m_program.id();
    QVERIFY(good != 0);
    const BuildReport bad =
        m_program.build(shippedShader(QStringLiteral("phong.vert")),
                        testShader(QStringLiteral("shaders/error_line17.frag")));
    QVERIFY(!bad.ok);
    QCOMPARE(m_program.id(), good);
    QVERIFY(m_program.isValid());
}

QTEST_MAIN(TestShaderCompile)
#include "tst_shadercompile.moc"
