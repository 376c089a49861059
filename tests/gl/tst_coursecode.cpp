// Course code as courses write it (tests/data/course/, its README says
// whose style each is), through `phonglab check`: Angel & Shreiner's
// products and a vec4 light in camera coordinates, the webglfundamentals
// point light (world space, Blinn, one light colour and one material
// colour), structs and arrays of structs with an int shininess and a mode
// switch the page sets, a three.js ShaderMaterial with a token the page
// replaces, and a correct WebGL 1 pair declaring mediump. Each is bound,
// compiled and checked as its page runs it: a correct one passes, one that
// deviates is named with every deviation at once.
#include "PhonglabProcess.h"
#include "TestPaths.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using namespace phonglab::test;

namespace {

QString course(const QString &file)
{
    return QDir::isAbsolutePath(file) ? file
                                      : sourcePath(QStringLiteral("tests/data/course/") + file);
}

struct Check {
    ProcessRun run;
    QJsonObject json;
};

Check check(const QString &vertex, const QString &fragment, const QStringList &extra = {})
{
    Check c;
    c.run = runPhonglab(QStringList{QStringLiteral("check"), course(QStringLiteral("scene.json")),
                                    QStringLiteral("--size"), QStringLiteral("320x240"),
                                    QStringLiteral("--vertex"), course(vertex),
                                    QStringLiteral("--fragment"), course(fragment),
                                    QStringLiteral("--json")}
                        + extra);
    c.json = QJsonDocument::fromJson(c.run.out).object();
    return c;
}

QString said(const Check &c)
{
    return c.run.err + QString::fromUtf8(c.run.out);
}

QStringList together(const Check &c)
{
    QStringList keys;
    for (const QJsonValue &k : c.json.value(QStringLiteral("together"))
                                   .toObject()
                                   .value(QStringLiteral("keys"))
                                   .toArray())
        keys << k.toString();
    return keys;
}

QString binding(const Check &c, const QString &name)
{
    return c.json.value(QStringLiteral("bindings")).toObject().value(name).toString();
}

QString warningsOf(const Check &c)
{
    return c.json.value(QStringLiteral("warnings"))
        .toVariant()
        .toStringList()
        .join(QLatin1Char('\n'));
}

// `from` (which must occur) replaced by `to` in a copy of `path` at `copy`.
QString edited(const QString &path, const QString &copy, const char *from, const char *to)
{
    QFile in(path);
    if (!in.open(QIODevice::ReadOnly))
        qFatal("cannot read %s", qPrintable(path));
    QByteArray text = in.readAll();
    if (!text.contains(from))
        qFatal("%s no longer contains \"%s\"", qPrintable(path), from);
    text.replace(from, to);
    QFile out(copy);
    if (!out.open(QIODevice::WriteOnly) || out.write(text) != text.size())
        qFatal("cannot write %s", qPrintable(copy));
    return copy;
}

QString verdict(const Check &c)
{
    return c.json.value(QStringLiteral("verdict")).toString();
}

} // namespace

class TestCourseCode : public QObject
{
    Q_OBJECT

private slots:
    // The products, bound by name; the light in camera coordinates, bound
    // by --bind (the name says nothing of its coordinates).
    void angelProductsWithAVec4Light()
    {
        const Check c = check(
            QStringLiteral("angel/phong.vert"), QStringLiteral("angel/phong.frag"),
            {QStringLiteral("--bind"), QStringLiteral("lightPosition=light-position-camera")});
        QVERIFY2(c.run.exitCode == 0, qPrintable(said(c)));
        QCOMPARE(verdict(c), QStringLiteral("pass"));
        QCOMPARE(binding(c, QStringLiteral("ambientProduct")), QStringLiteral("ambient-product"));
        QCOMPARE(binding(c, QStringLiteral("diffuseProduct")), QStringLiteral("diffuse-product"));
        QCOMPARE(binding(c, QStringLiteral("specularProduct")), QStringLiteral("specular-product"));
        QCOMPARE(binding(c, QStringLiteral("lightPosition")),
                 QStringLiteral("light-position-camera"));
        // Taken for a world position, the same light is in the wrong place.
        const Check world =
            check(QStringLiteral("angel/phong.vert"), QStringLiteral("angel/phong.frag"));
        QCOMPARE(verdict(world), QStringLiteral("fail"));
    }

    // shadedCube lights per vertex: `gouraud` first, from its code, with
    // the vertex shader's lines, whatever else the image shows; no set of
    // per-fragment mistakes is offered for it.
    void angelShadedCubeIsGouraud()
    {
        const Check c = check(
            QStringLiteral("angel/shadedCube.vert"), QStringLiteral("angel/shadedCube.frag"),
            {QStringLiteral("--bind"), QStringLiteral("lightPosition=light-position-camera")});
        QCOMPARE(verdict(c), QStringLiteral("fail"));
        const QJsonObject first =
            c.json.value(QStringLiteral("diagnosis")).toArray().first().toObject();
        QCOMPARE(first.value(QStringLiteral("key")).toString(), QStringLiteral("gouraud"));
        QVERIFY(first.value(QStringLiteral("from_code")).toBool());
        const QJsonArray lines = first.value(QStringLiteral("lines")).toArray();
        QVERIFY2(!lines.isEmpty(), qPrintable(said(c)));
        QVERIFY(lines.first()
                    .toObject()
                    .value(QStringLiteral("file"))
                    .toString()
                    .endsWith(QLatin1String("shadedCube.vert")));
        QVERIFY(c.json.value(QStringLiteral("together")).isNull());
    }

    // Ia, Id and Is as a mat3's columns: bound by use (light-terms), one
    // light, and the correct pair passes with no --bind.
    void lightPartsAsMatrixColumns()
    {
        const Check c =
            check(QStringLiteral("columns/phong.vert"), QStringLiteral("columns/phong.frag"));
        QVERIFY2(c.run.exitCode == 0, qPrintable(said(c)));
        QCOMPARE(verdict(c), QStringLiteral("pass"));
        QCOMPARE(binding(c, QStringLiteral("uLamp")), QStringLiteral("light-terms"));
    }

    // The book's own fragment shader: the halfway vector and no attenuation,
    // both named.
    void angelBlinnIsNamedInFull()
    {
        const Check c = check(
            QStringLiteral("angel/phong.vert"), QStringLiteral("angel/blinn.frag"),
            {QStringLiteral("--bind"), QStringLiteral("lightPosition=light-position-camera")});
        QCOMPARE(verdict(c), QStringLiteral("fail"));
        QCOMPARE(together(c),
                 (QStringList{QStringLiteral("attenuation"), QStringLiteral("halfway-vector")}));
    }

    // World space, Blinn, no ambient, no attenuation: three deviations at
    // once, with no --bind. The lesson's u_specularColor is the specular
    // term's only factor, so its whole product Is·ks (bound by use).
    void webglFundamentalsWorldSpaceBlinn()
    {
        const Check c = check(QStringLiteral("webglfundamentals/point-light.vert"),
                              QStringLiteral("webglfundamentals/point-light.frag"));
        QCOMPARE(binding(c, QStringLiteral("u_specularColor")), QStringLiteral("specular-product"));
        QVERIFY(c.json.value(QStringLiteral("bindings_by_use"))
                    .toObject()
                    .contains(QStringLiteral("u_specularColor")));
        QCOMPARE(verdict(c), QStringLiteral("fail"));
        QCOMPARE(binding(c, QStringLiteral("u_lightWorldPosition")),
                 QStringLiteral("light-position"));
        QCOMPARE(binding(c, QStringLiteral("u_viewWorldPosition")), QStringLiteral("eye"));
        QCOMPARE(binding(c, QStringLiteral("u_color")), QStringLiteral("material-color"));
        QCOMPARE(binding(c, QStringLiteral("u_lightColor")), QStringLiteral("light-color"));
        QCOMPARE(together(c),
                 (QStringList{QStringLiteral("attenuation"), QStringLiteral("ambient"),
                              QStringLiteral("halfway-vector")}));
    }

    // One colour for two values holds only a scene that gives both the same:
    // on the check scene (ka != kd) the lesson's u_color cannot draw it, and
    // that is an error naming both values, never a verdict.
    void sharedColourAgainstASceneThatDiffers()
    {
        const ProcessRun r = runPhonglab(
            {QStringLiteral("check"), sourcePath(QStringLiteral("assets/scenes/check.json")),
             QStringLiteral("--size"), QStringLiteral("160x120"), QStringLiteral("--vertex"),
             course(QStringLiteral("webglfundamentals/point-light.vert")),
             QStringLiteral("--fragment"),
             course(QStringLiteral("webglfundamentals/point-light.frag")),
             QStringLiteral("--json")});
        const QJsonObject json = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(json.value(QStringLiteral("verdict")).toString(), QStringLiteral("error"));
        const QString message = json.value(QStringLiteral("errors"))
                                    .toArray()
                                    .first()
                                    .toObject()
                                    .value(QStringLiteral("message"))
                                    .toString();
        QVERIFY2(message.contains(QStringLiteral("u_color is one colour for ka and kd"))
                     && message.contains(QStringLiteral("ka = (0.2, 0.2, 0.2)"))
                     && message.contains(QStringLiteral("kd = (0.6, 0.5, 0.4)")),
                 qPrintable(message));
    }

    // Structs and an array of structs, bound member by member; the page's
    // mode switch given as a constant.
    void structsAndAModeSwitch()
    {
        const Check c =
            check(QStringLiteral("structs/phong.vert"), QStringLiteral("structs/phong.frag"),
                  {QStringLiteral("--bind"), QStringLiteral("mode=1")});
        QVERIFY2(c.run.exitCode == 0, qPrintable(said(c)));
        QCOMPARE(verdict(c), QStringLiteral("pass"));
        QCOMPARE(binding(c, QStringLiteral("lights[1].color")), QStringLiteral("light-color"));
        QCOMPARE(binding(c, QStringLiteral("lights[0].quadratic")), QStringLiteral("c3"));
        QCOMPARE(binding(c, QStringLiteral("material.shininess")), QStringLiteral("shininess"));
        // Without the page's value the switch is PhongLab's gap, never a fail.
        const Check unset =
            check(QStringLiteral("structs/phong.vert"), QStringLiteral("structs/phong.frag"));
        QCOMPARE(verdict(unset), QStringLiteral("error"));
        QVERIFY2(said(unset).contains(QStringLiteral("mode")), qPrintable(said(unset)));
    }

    // three.js's prelude, the page's token, and the lines of the student's
    // own file in every message.
    void threeJsShaderMaterial()
    {
        const Check c =
            check(QStringLiteral("threejs/phong.vert"), QStringLiteral("threejs/phong.frag"),
                  {QStringLiteral("--define"), QStringLiteral("NUM_LIGHTS=2")});
        QVERIFY2(c.run.exitCode == 0, qPrintable(said(c)));
        QCOMPARE(verdict(c), QStringLiteral("pass"));
        const QJsonArray warnings = c.json.value(QStringLiteral("warnings")).toArray();
        QVERIFY2(!warnings.isEmpty()
                     && warnings.first().toString().contains(QStringLiteral("three.js")),
                 qPrintable(said(c)));
        QCOMPARE(binding(c, QStringLiteral("modelViewMatrix")), QStringLiteral("model-view"));
        QCOMPARE(binding(c, QStringLiteral("lightColors")), QStringLiteral("light-color"));

        const Check undefinedToken =
            check(QStringLiteral("threejs/phong.vert"), QStringLiteral("threejs/phong.frag"));
        QCOMPARE(verdict(undefinedToken), QStringLiteral("error"));
        const QJsonObject error =
            undefinedToken.json.value(QStringLiteral("errors")).toArray().first().toObject();
        const QString message = error.value(QStringLiteral("message")).toString();
        QVERIFY2(message.contains(QStringLiteral("NUM_LIGHTS"))
                     && message.contains(QStringLiteral("--define NUM_LIGHTS=VALUE")),
                 qPrintable(message));
        // Line 6 of the student's file declares the array.
        QCOMPARE(error.value(QStringLiteral("line")).toInt(), 6);
    }

    // What the image cannot be trusted to show: an accumulator and an
    // output read before they are set, whose value GLSL leaves undefined.
    // Each is a warning on the student's line, never the verdict (which is
    // the image's: here Mesa keeps garbage in the accumulator, so it fails).
    void undefinedReadsAreWarnedNeverChecked()
    {
        QTemporaryDir dir;
        const QString accumulator = edited(
            course(QStringLiteral("structs/phong.frag")), dir.filePath(QStringLiteral("acc.frag")),
            "    vec3 result = ambientLight * material.ambient;\n",
            "    vec3 result;\n    result += ambientLight * material.ambient;\n");
        const Check c = check(QStringLiteral("structs/phong.vert"), accumulator,
                              {QStringLiteral("--bind"), QStringLiteral("mode=1")});
        QVERIFY(verdict(c) == QLatin1String("pass") || verdict(c) == QLatin1String("fail"));
        QVERIFY2(
            warningsOf(c).contains(
                accumulator + QStringLiteral(":38:5: warning: 'result' is read before it is set")),
            qPrintable(warningsOf(c)));

        const QString output =
            edited(sourcePath(QStringLiteral("assets/shaders/webgl2/phong.frag")),
                   dir.filePath(QStringLiteral("out.frag")), "    outColor = vec4(I, 1.0);\n",
                   "    outColor += vec4(I, 1.0);\n");
        const Check o =
            check(sourcePath(QStringLiteral("assets/shaders/webgl2/phong.vert")), output);
        QVERIFY(verdict(o) == QLatin1String("pass") || verdict(o) == QLatin1String("fail"));
        QVERIFY2(warningsOf(o).contains(
                     QStringLiteral("warning: the output 'outColor' is read before it is written")),
                 qPrintable(warningsOf(o)));

        // The correct files: no such warning.
        for (const Check &correct :
             {check(QStringLiteral("structs/phong.vert"), QStringLiteral("structs/phong.frag"),
                    {QStringLiteral("--bind"), QStringLiteral("mode=1")}),
              check(sourcePath(QStringLiteral("assets/shaders/webgl2/phong.vert")),
                    sourcePath(QStringLiteral("assets/shaders/webgl2/phong.frag")))})
            QVERIFY2(!warningsOf(correct).contains(QStringLiteral("before it")),
                     qPrintable(warningsOf(correct)));
    }

    // mediump: checked at highp, as a desktop browser computes it; what the
    // declared precision changes on this driver said apart.
    void mediumpIsCheckedAsTheBrowserRunsIt()
    {
        const Check c =
            check(QStringLiteral("mediump/phong.vert"), QStringLiteral("mediump/phong.frag"));
        QVERIFY2(c.run.exitCode == 0, qPrintable(said(c)));
        QCOMPARE(verdict(c), QStringLiteral("pass"));
        const QJsonObject precision = c.json.value(QStringLiteral("precision")).toObject();
        QCOMPARE(precision.value(QStringLiteral("judged")).toString(), QStringLiteral("highp"));
        QCOMPARE(precision.value(QStringLiteral("declared")).toArray().first().toString(),
                 QStringLiteral("mediump"));
        QVERIFY(precision.value(QStringLiteral("as_written_max_error")).isDouble());
        qInfo("mediump as written on this driver: max %d/255, PSNR %.1f dB",
              precision.value(QStringLiteral("as_written_max_error")).toInt(),
              precision.value(QStringLiteral("as_written_psnr_db")).toDouble());

        // As written: what this driver does with it, which may fail; never
        // better than at highp.
        const Check asWritten =
            check(QStringLiteral("mediump/phong.vert"), QStringLiteral("mediump/phong.frag"),
                  {QStringLiteral("--precision"), QStringLiteral("as-written")});
        QCOMPARE(asWritten.json.value(QStringLiteral("precision"))
                     .toObject()
                     .value(QStringLiteral("judged"))
                     .toString(),
                 QStringLiteral("as-written"));
        QVERIFY(asWritten.json.value(QStringLiteral("max_error")).toInt()
                >= c.json.value(QStringLiteral("max_error")).toInt());

        // A uniform both stages declare at two precisions does not link in a
        // browser either: checked at highp it passes, and that is said.
        const Check mixed = check(QStringLiteral("../../../assets/shaders/webgl1/phong.vert"),
                                  QStringLiteral("mediump/phong.frag"));
        QCOMPARE(verdict(mixed), QStringLiteral("pass"));
        const QString error = mixed.json.value(QStringLiteral("precision"))
                                  .toObject()
                                  .value(QStringLiteral("as_written_error"))
                                  .toString();
        QVERIFY2(error.contains(QStringLiteral("precision")), qPrintable(said(mixed)));
    }
};

QTEST_GUILESS_MAIN(TestCourseCode)
#include "tst_coursecode.moc"
