// Students' shaders as they write them, through `phonglab check`: WebGL 2
// (GLSL ES 3.00) and WebGL 1 (GLSL ES 1.00, no #version line) with their own
// names, bound automatically, explicitly (--bind, the scene's "bindings") or
// not at all (an error naming the uniform, never a `fail`); the slide's
// equation and the guarded one; lighting in world coordinates.
#include "PhonglabProcess.h"
#include "TestPaths.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using namespace phonglab::test;

namespace {

const QString kSize = QStringLiteral("320x240");

QString checkScene()
{
    return sourcePath(QStringLiteral("assets/scenes/check.json"));
}

QByteArray readAsset(const QString &path)
{
    QFile file(sourcePath(QStringLiteral("assets/shaders/") + path));
    if (!file.open(QIODevice::ReadOnly))
        qFatal("cannot read %s", qPrintable(file.fileName()));
    return file.readAll();
}

// `from` must occur, so a change of the example cannot void a mistake silently.
QByteArray replaced(QByteArray text, const char *from, const char *to)
{
    if (!text.contains(from))
        qFatal("the example no longer contains \"%s\"", from);
    return text.replace(from, to);
}

QJsonObject jsonOf(const ProcessRun &r)
{
    const QJsonDocument doc = QJsonDocument::fromJson(r.out);
    if (!doc.isObject())
        qWarning("not one JSON object:\n%s\n%s", r.out.constData(), qPrintable(r.err));
    return doc.object();
}

QString topKey(const QJsonObject &o)
{
    const QJsonArray diagnosis = o.value(QStringLiteral("diagnosis")).toArray();
    return diagnosis.isEmpty()
        ? QString()
        : diagnosis.first().toObject().value(QStringLiteral("key")).toString();
}

} // namespace

class TestBringYourOwnShader : public QObject
{
    Q_OBJECT

private slots:
    void correctPairsPass_data()
    {
        QTest::addColumn<QString>("dialect");
        QTest::addColumn<QString>("equation");
        QTest::newRow("WebGL 2, guarded") << QStringLiteral("webgl2") << QStringLiteral("guarded");
        QTest::newRow("WebGL 1, the slide's")
            << QStringLiteral("webgl1") << QStringLiteral("slide");
    }

    // No flags: every name bound by what it says, the verdict `pass`, the
    // equation the shader wrote named.
    void correctPairsPass()
    {
        QFETCH(QString, dialect);
        QFETCH(QString, equation);
        const ProcessRun r = check(readAsset(dialect + QStringLiteral("/phong.vert")),
                                   readAsset(dialect + QStringLiteral("/phong.frag")));
        QVERIFY2(r.exitCode == 0, qPrintable(r.err + QString::fromUtf8(r.out)));
        const QJsonObject o = jsonOf(r);
        QCOMPARE(o.value(QStringLiteral("verdict")).toString(), QStringLiteral("pass"));
        QCOMPARE(o.value(QStringLiteral("equation")).toString(), equation);
        const QJsonObject bindings = o.value(QStringLiteral("bindings")).toObject();
        const bool es3 = dialect == QLatin1String("webgl2");
        QCOMPARE(bindings.value(es3 ? QStringLiteral("aPosition") : QStringLiteral("a_position"))
                     .toString(),
                 QStringLiteral("position"));
        QCOMPARE(bindings.value(es3 ? QStringLiteral("uModelMatrix") : QStringLiteral("u_model"))
                     .toString(),
                 QStringLiteral("model"));
        QCOMPARE(bindings.value(es3 ? QStringLiteral("uKd") : QStringLiteral("u_kd")).toString(),
                 QStringLiteral("kd"));
        if (!es3)
            QCOMPARE(bindings.value(QStringLiteral("u_normalMatrix")).toString(),
                     QStringLiteral("normal-matrix"));
    }

    // One mistake each, in the student's own names: named by its key.
    void mistakesAreNamed_data()
    {
        QTest::addColumn<QString>("dialect");
        QTest::addColumn<QByteArray>("vertex");
        QTest::addColumn<QByteArray>("fragment");
        QTest::addColumn<QString>("key");
        const QByteArray v2 = readAsset(QStringLiteral("webgl2/phong.vert"));
        const QByteArray f2 = readAsset(QStringLiteral("webgl2/phong.frag"));
        const QByteArray v1 = readAsset(QStringLiteral("webgl1/phong.vert"));
        const QByteArray f1 = readAsset(QStringLiteral("webgl1/phong.frag"));
        QTest::newRow("WebGL 2 reflect(L, N)")
            << "webgl2" << v2 << replaced(f2, "reflect(-L, N)", "reflect(L, N)")
            << "reflect-incident";
        QTest::newRow("WebGL 2 normals by model-view")
            << "webgl2" << replaced(v2, "transpose(inverse(mat3(modelView)))", "mat3(modelView)")
            << f2 << "normal-matrix";
        QTest::newRow("WebGL 2 light not viewed")
            << "webgl2" << v2
            << replaced(f2, "(uViewMatrix * vec4(uLightPosition[i], 1.0)).xyz", "uLightPosition[i]")
            << "light-space";
        QTest::newRow("WebGL 2 no attenuation")
            << "webgl2" << v2
            << replaced(f2, "float fatt = min(1.0 / (c.x + c.y * d + c.z * d * d), 1.0);",
                        "float fatt = 1.0;")
            << "attenuation";
        QTest::newRow("WebGL 1 no ambient")
            << "webgl1" << v1 << replaced(f1, "vec3 I = u_Ia * u_ka;", "vec3 I = vec3(0.0);")
            << "ambient";
        QTest::newRow("WebGL 2 V away from the eye")
            << "webgl2" << v2 << replaced(f2, "normalize(-vPositionCam)", "normalize(vPositionCam)")
            << "view-vector";
    }

    void mistakesAreNamed()
    {
        QFETCH(QString, dialect);
        QFETCH(QByteArray, vertex);
        QFETCH(QByteArray, fragment);
        QFETCH(QString, key);
        const ProcessRun r = check(vertex, fragment);
        QCOMPARE(r.exitCode, 1);
        const QJsonObject o = jsonOf(r);
        QCOMPARE(o.value(QStringLiteral("verdict")).toString(), QStringLiteral("fail"));
        const QJsonObject top = o.value(QStringLiteral("diagnosis")).toArray().first().toObject();
        QStringList keys{top.value(QStringLiteral("key")).toString()};
        for (const QJsonValue &k : top.value(QStringLiteral("also")).toArray())
            keys << k.toString();
        QVERIFY2(keys.contains(key), qPrintable(QString::fromUtf8(r.out)));
    }

    // --equation demands one: the other is then backface-specular.
    void demandedEquation()
    {
        const ProcessRun slideAsGuarded =
            check(readAsset(QStringLiteral("webgl1/phong.vert")),
                  readAsset(QStringLiteral("webgl1/phong.frag")),
                  {QStringLiteral("--equation"), QStringLiteral("guarded")});
        QCOMPARE(slideAsGuarded.exitCode, 1);
        QCOMPARE(topKey(jsonOf(slideAsGuarded)), QStringLiteral("backface-specular"));
        const ProcessRun guardedAsSlide =
            check(readAsset(QStringLiteral("webgl2/phong.vert")),
                  readAsset(QStringLiteral("webgl2/phong.frag")),
                  {QStringLiteral("--equation"), QStringLiteral("slide")});
        QCOMPARE(guardedAsSlide.exitCode, 1);
        QCOMPARE(topKey(jsonOf(guardedAsSlide)), QStringLiteral("backface-specular"));
        const ProcessRun slideAsSlide =
            check(readAsset(QStringLiteral("webgl1/phong.vert")),
                  readAsset(QStringLiteral("webgl1/phong.frag")),
                  {QStringLiteral("--equation"), QStringLiteral("slide")});
        QCOMPARE(slideAsSlide.exitCode, 0);
        const ProcessRun wrong = check({}, {}, {QStringLiteral("--equation"), QStringLiteral("x")});
        QCOMPARE(wrong.exitCode, 2);
    }

    // A name nothing explains, used where no term of the equation takes it
    // (a switch): an error that names it, never a `fail`; the user's word,
    // on the command line or in the scene, makes it theirs.
    void unboundUniformIsAnErrorUntilBound()
    {
        const QByteArray vertex = readAsset(QStringLiteral("webgl2/phong.vert"));
        QByteArray fragment = readAsset(QStringLiteral("webgl2/phong.frag"));
        fragment.replace("uniform vec3 uKa;", "uniform vec3 uKa;\nuniform float uThing;")
            .replace("void main()\n{", "void main()\n{\n    if (uThing > 0.5) discard;");
        QVERIFY(fragment.contains("discard"));
        const ProcessRun unbound = check(vertex, fragment);
        QCOMPARE(unbound.exitCode, 1);
        const QJsonObject o = jsonOf(unbound);
        QCOMPARE(o.value(QStringLiteral("verdict")).toString(), QStringLiteral("error"));
        const QString message = o.value(QStringLiteral("errors"))
                                    .toArray()
                                    .first()
                                    .toObject()
                                    .value(QStringLiteral("message"))
                                    .toString();
        QVERIFY2(message.contains(QLatin1String("uThing"))
                     && message.contains(QLatin1String("float")),
                 qPrintable(message));

        const ProcessRun bound =
            check(vertex, fragment, {QStringLiteral("--bind"), QStringLiteral("uThing=none")});
        QVERIFY2(bound.exitCode == 0, qPrintable(QString::fromUtf8(bound.out)));
        QCOMPARE(jsonOf(bound)
                     .value(QStringLiteral("bindings"))
                     .toObject()
                     .value(QStringLiteral("uThing")),
                 QStringLiteral("none"));

        QFile original(checkScene());
        QVERIFY(original.open(QIODevice::ReadOnly));
        QJsonObject scene = QJsonDocument::fromJson(original.readAll()).object();
        scene.insert(QStringLiteral("bindings"), QJsonObject{{"uThing", "none"}});
        const QString scenePath =
            write(QJsonDocument(scene).toJson(), QStringLiteral("bound.json"));
        const ProcessRun fromScene = check(vertex, fragment, {}, scenePath);
        QVERIFY2(fromScene.exitCode == 0, qPrintable(QString::fromUtf8(fromScene.out)));

        const ProcessRun cannotHold =
            check(vertex, fragment, {QStringLiteral("--bind"), QStringLiteral("uKd=model")});
        QCOMPARE(cannotHold.exitCode, 1);
        QCOMPARE(jsonOf(cannotHold).value(QStringLiteral("verdict")).toString(),
                 QStringLiteral("error"));
    }

    // A model matrix under a name no rule knows is placed by the gl_Position
    // chain, and says so; the shader then passes with no --bind.
    void unknownMatrixNameIsBoundByUse()
    {
        const QByteArray vertex =
            readAsset(QStringLiteral("webgl2/phong.vert")).replace("uModelMatrix", "uThing");
        const ProcessRun run = check(vertex, readAsset(QStringLiteral("webgl2/phong.frag")));
        QVERIFY2(run.exitCode == 0, qPrintable(QString::fromUtf8(run.out)));
        const QJsonObject o = jsonOf(run);
        QCOMPARE(o.value(QStringLiteral("bindings")).toObject().value(QStringLiteral("uThing")),
                 QStringLiteral("model"));
        const QJsonObject why = o.value(QStringLiteral("bindings_by_use"))
                                    .toObject()
                                    .value(QStringLiteral("uThing"))
                                    .toObject();
        QCOMPARE(why.value(QStringLiteral("meaning")).toString(), QStringLiteral("model"));
        QCOMPARE(why.value(QStringLiteral("stage")).toString(), QStringLiteral("vertex"));
        QCOMPARE(why.value(QStringLiteral("line")).toInt(), 24); // gl_Position = ...
        QVERIFY(
            why.value(QStringLiteral("reason")).toString().contains(QLatin1String("gl_Position")));
    }

    // Lighting in world coordinates (the eye, the model's normal matrix)
    // gives the same image.
    void worldSpaceLightingPasses()
    {
        const QByteArray vertex = R"(#version 300 es
in vec3 aPosition;
in vec3 aNormal;
uniform mat4 uModel;
uniform mat4 uViewProjection;
uniform mat3 uModelNormalMatrix;
out vec3 vWorld;
out vec3 vNormal;
void main() {
    vec4 w = uModel * vec4(aPosition, 1.0);
    vWorld = w.xyz;
    vNormal = uModelNormalMatrix * aNormal;
    gl_Position = uViewProjection * w;
}
)";
        const QByteArray fragment = R"(#version 300 es
precision highp float;
in vec3 vWorld;
in vec3 vNormal;
uniform vec3 uEye;
uniform int uLightCount;
uniform vec3 uLightPosition[8];
uniform vec3 uId[8];
uniform vec3 uIs[8];
uniform vec3 uAttenuation[8];
uniform vec3 uIa;
uniform vec3 uKa;
uniform vec3 uKd;
uniform vec3 uKs;
uniform float uShininess;
out vec4 color;
void main() {
    vec3 N = normalize(vNormal);
    vec3 V = normalize(uEye - vWorld);
    vec3 I = uIa * uKa;
    for (int i = 0; i < uLightCount; ++i) {
        vec3 toLight = uLightPosition[i] - vWorld;
        float d = length(toLight);
        vec3 L = toLight / d;
        float NdotL = dot(N, L);
        if (NdotL <= 0.0) continue;
        vec3 R = reflect(-L, N);
        vec3 c = uAttenuation[i];
        float fatt = min(1.0 / (c.x + c.y * d + c.z * d * d), 1.0);
        I += fatt * (uId[i] * uKd * NdotL + uIs[i] * uKs * pow(max(0.0, dot(R, V)), uShininess));
    }
    color = vec4(I, 1.0);
}
)";
        const ProcessRun r = check(vertex, fragment);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err + QString::fromUtf8(r.out)));
        const QJsonObject bindings = jsonOf(r).value(QStringLiteral("bindings")).toObject();
        QCOMPARE(bindings.value(QStringLiteral("uEye")).toString(), QStringLiteral("eye"));
        QCOMPARE(bindings.value(QStringLiteral("uModelNormalMatrix")).toString(),
                 QStringLiteral("model-normal-matrix"));
    }

    // A single light uniform takes light 0; the check says so.
    void oneLightShaderIsCheckedWithOneLight()
    {
        QByteArray fragment = readAsset(QStringLiteral("webgl2/phong.frag"));
        fragment = replaced(fragment, "uniform vec3 uLightPosition[MAX_LIGHTS];",
                            "uniform vec3 uLightPosition;");
        fragment = replaced(fragment, "uLightPosition[i]", "uLightPosition");
        const ProcessRun r = check(readAsset(QStringLiteral("webgl2/phong.vert")), fragment);
        const QJsonObject o = jsonOf(r);
        QVERIFY2(r.exitCode == 0, qPrintable(QString::fromUtf8(r.out)));
        const QJsonArray notes = o.value(QStringLiteral("notes")).toArray();
        QVERIFY(!notes.isEmpty());
        QVERIFY2(notes.first().toString().contains(QLatin1String("takes 1 light")),
                 qPrintable(notes.first().toString()));
    }

    // Errors land on the user's lines, in either dialect; GLSL ES 1.00's
    // missing inverse() is said plainly.
    void dialectErrorsOnTheUsersLines()
    {
        QByteArray v1 = readAsset(QStringLiteral("webgl1/phong.vert"));
        v1 = replaced(v1, "    v_normal = u_normalMatrix * a_normal;",
                      "    v_normal = transpose(inverse(mat3(u_view * u_model))) * a_normal;");
        const int line = QByteArray(v1.left(v1.indexOf("transpose(inverse"))).count('\n') + 1;
        const ProcessRun es1 = check(v1, readAsset(QStringLiteral("webgl1/phong.frag")), {}, {},
                                     /*json=*/false);
        QCOMPARE(es1.exitCode, 1);
        QVERIFY2(es1.err.contains(QStringLiteral("student.vert:%1:").arg(line)),
                 qPrintable(es1.err));
        QVERIFY2(es1.err.contains(QLatin1String("GLSL ES 1.00")), qPrintable(es1.err));

        QByteArray f2 = readAsset(QStringLiteral("webgl2/phong.frag"));
        f2 = replaced(f2, "    vec3 I = uAmbientLight * uKa;", "    vec3 I = uAmbientLight * uKa");
        // The compiler finds the missing ';' at the next statement; it is
        // pointed at just past the line where it belongs.
        const QByteArray unfinished = "    vec3 I = uAmbientLight * uKa";
        const int unfinishedLine =
            QByteArray(f2.left(f2.indexOf(unfinished + '\n'))).count('\n') + 1;
        const ProcessRun es3 =
            check(readAsset(QStringLiteral("webgl2/phong.vert")), f2, {}, {}, false);
        QCOMPARE(es3.exitCode, 1);
        QVERIFY2(es3.err.contains(QStringLiteral("student.frag:%1:%2: error")
                                      .arg(unfinishedLine)
                                      .arg(unfinished.size() + 1)),
                 qPrintable(es3.err));

        // A GLSL ES stage with a desktop one cannot link: said plainly.
        const ProcessRun mixed = runPhonglab(
            {QStringLiteral("check"), checkScene(), QStringLiteral("--size"), kSize,
             QStringLiteral("--fragment"),
             write(readAsset(QStringLiteral("webgl2/phong.frag")), QStringLiteral("mixed.frag"))});
        QCOMPARE(mixed.exitCode, 1);
        QVERIFY2(mixed.err.contains(QLatin1String("both stages must be written in the same GLSL")),
                 qPrintable(mixed.err));
    }

private:
    ProcessRun check(const QByteArray &vertex, const QByteArray &fragment,
                     const QStringList &extra = {}, const QString &scene = {}, bool json = true)
    {
        QStringList args{QStringLiteral("check"), scene.isEmpty() ? checkScene() : scene,
                         QStringLiteral("--size"), kSize};
        if (!vertex.isEmpty())
            args << QStringLiteral("--vertex") << write(vertex, QStringLiteral("student.vert"));
        if (!fragment.isEmpty())
            args << QStringLiteral("--fragment") << write(fragment, QStringLiteral("student.frag"));
        if (json)
            args << QStringLiteral("--json");
        return runPhonglab(args + extra);
    }

    QString write(const QByteArray &text, const QString &name)
    {
        const QString path = m_dir.filePath(name);
        QFile file(path);
        if (!file.open(QIODevice::WriteOnly) || file.write(text) != text.size())
            qFatal("cannot write %s", qPrintable(path));
        return path;
    }

    QTemporaryDir m_dir;
};

QTEST_GUILESS_MAIN(TestBringYourOwnShader)
#include "tst_bringyourownshader.moc"
