// Binding by use (core/program/BindingsByUse): where no name rule decides, a
// uniform means what the shader does with it, says why and where, and never
// overrides a name or the user's word.
#include "core/program/BindingsByUse.h"

#include <QTest>

using namespace phonglab;
using M = BindingMeaning;

namespace {

ShaderVariable uniform(const char *name, GlslType type, int arraySize = 1)
{
    return {QString::fromLatin1(name), type, arraySize, arraySize > 1, false};
}

struct Bound {
    ProgramBindings bindings;
    int count = 0;
    std::optional<M> of(const char *name) const
    {
        for (const VariableBinding &b : bindings.variables)
            if (b.variable.name == QLatin1String(name))
                return b.meaning;
        return std::nullopt;
    }
    const VariableBinding *binding(const char *name) const
    {
        for (const VariableBinding &b : bindings.variables)
            if (b.variable.name == QLatin1String(name))
                return &b;
        return nullptr;
    }
};

Bound bindAll(const std::vector<ShaderVariable> &variables, const QByteArray &vertex,
              const QByteArray &fragment, const ExplicitBindings &explicitBindings = {})
{
    Bound out{bindVariables(variables, explicitBindings), 0};
    out.count = bindByUse(out.bindings, vertex, fragment);
    return out;
}

const QByteArray kVertex = "attribute vec3 aPos;\nvoid main() { gl_Position = vec4(aPos, 1.0); }\n";

} // namespace

class TestBindingsByUse : public QObject
{
    Q_OBJECT

private slots:
    void exponentIsShininess();
    void loopBoundIsLightCount();
    void webGl1BreakIsLightCount();
    void positionChainPlacesMatrices_data();
    void positionChainPlacesMatrices();
    void subtractedFromPositionIsALight();
    void eyeWhereALightIsNamed();
    void termFactorsSplitTheProducts();
    void aGainBesideANamedColour();
    void aGainOfTheWholeColourStaysTheUsers();
    void aColourAddedBesideTheAmbientStaysTheUsers();
    void columnsAndElementsScaleTheirTerms();
    void namesAndTheUsersWordWin();
    void whatNoTermTakesStaysUnbound();
    void survivesEveryPrefix();
};

void TestBindingsByUse::exponentIsShininess()
{
    const QByteArray fragment = "precision mediump float;\nuniform float shinyThing;\n"
                                "uniform float glossy;\nstruct Stuff { float gleam; };\n"
                                "uniform Stuff stuff;\nvarying vec3 r, v;\nvoid main() {\n"
                                "  float e = glossy;\n"
                                "  float a = pow(max(dot(r, v), 0.0), shinyThing);\n"
                                "  float b = pow(max(dot(r, v), 0.0), e);\n"
                                "  float c = pow(dot(r, v), float(stuff.gleam));\n"
                                "  gl_FragColor = vec4(a + b + c);\n}\n";
    const Bound b =
        bindAll({uniform("shinyThing", GlslType::Float), uniform("glossy", GlslType::Float),
                 uniform("stuff.gleam", GlslType::Float)},
                kVertex, fragment);
    QCOMPARE(b.count, 3);
    QCOMPARE(b.of("shinyThing"), M::Shininess);
    QCOMPARE(b.of("glossy"), M::Shininess);
    QCOMPARE(b.of("stuff.gleam"), M::Shininess);
    const VariableBinding *shiny = b.binding("shinyThing");
    QVERIFY(shiny->byUse);
    QCOMPARE(shiny->byUse->line, 9);
    QCOMPARE(shiny->byUse->stage, ShaderStage::Fragment);
    QCOMPARE(shiny->byUse->reason, QStringLiteral("the exponent of pow"));
}

void TestBindingsByUse::loopBoundIsLightCount()
{
    const QByteArray fragment = "#version 300 es\nprecision highp float;\nuniform int howMany;\n"
                                "uniform vec3 spots[4];\nin vec3 p;\nout vec4 o;\nvoid main() {\n"
                                "  vec3 sum = vec3(0.0);\n"
                                "  for (int k = 0; k < howMany; ++k) {\n"
                                "    sum += normalize(spots[k] - p);\n  }\n"
                                "  o = vec4(sum, 1.0);\n}\n";
    const Bound b =
        bindAll({uniform("howMany", GlslType::Int), uniform("spots", GlslType::Vec3, 4)}, kVertex,
                fragment);
    QCOMPARE(b.of("howMany"), M::LightCount);
    QCOMPARE(b.binding("howMany")->byUse->line, 9);
    QCOMPARE(b.of("spots"), M::LightPosition); // subtracted from the surface position, per light

    // The same as the driver is handed it, the index clamped by the
    // browser's rules (core/program/BrowserRules).
    QByteArray clamped = fragment;
    clamped.replace("spots[k]", "spots[int(clamp(float(k), 0.0, float(4) - 1.0))]");
    const Bound c = bindAll(
        {uniform("howMany", GlslType::Int), uniform("spots", GlslType::Vec3, 4)}, kVertex, clamped);
    QCOMPARE(c.of("howMany"), M::LightCount);
}

void TestBindingsByUse::webGl1BreakIsLightCount()
{
    const QByteArray fragment =
        "precision highp float;\nuniform int lamps;\nuniform vec3 where[8];\n"
        "varying vec3 p;\nvoid main() {\n  vec3 sum = vec3(0.0);\n"
        "  for (int i = 0; i < 8; i++) {\n    if (i >= lamps) break;\n"
        "    sum += where[i] - p;\n  }\n  gl_FragColor = vec4(sum, 1.0);\n}\n";
    const Bound b = bindAll({uniform("lamps", GlslType::Int), uniform("where", GlslType::Vec3, 8)},
                            kVertex, fragment);
    QCOMPARE(b.of("lamps"), M::LightCount);
    QCOMPARE(b.binding("lamps")->byUse->line, 8);
}

void TestBindingsByUse::positionChainPlacesMatrices_data()
{
    QTest::addColumn<QByteArray>("position");
    QTest::addColumn<QStringList>("names");
    QTest::addColumn<QStringList>("expected");
    QTest::newRow("one: all three") << QByteArray("gl_Position = uAll * vec4(aPos, 1.0);")
                                    << QStringList{"uAll"} << QStringList{"model-view-projection"};
    QTest::newRow("two: projection and model-view")
        << QByteArray("gl_Position = uA * uB * vec4(aPos, 1.0);") << QStringList{"uA", "uB"}
        << QStringList{"projection", "model-view"};
    QTest::newRow("three") << QByteArray("gl_Position = uA * uB * uC * vec4(aPos, 1.0);")
                           << QStringList{"uA", "uB", "uC"}
                           << QStringList{"projection", "view", "model"};
    QTest::newRow("a name fixes the other: model")
        << QByteArray("gl_Position = uViewProjection * uThing * vec4(aPos, 1.0);")
        << QStringList{"uViewProjection", "uThing"} << QStringList{"view-projection", "model"};
    QTest::newRow("a name fixes the other: model-view")
        << QByteArray("gl_Position = projectionMatrix * (uThing * vec4(aPos, 1.0));")
        << QStringList{"projectionMatrix", "uThing"} << QStringList{"projection", "model-view"};
    QTest::newRow("through a local")
        << QByteArray("vec4 w = uObj * vec4(aPos, 1.0); gl_Position = uLens * w;")
        << QStringList{"uLens", "uObj"} << QStringList{"view-projection", "model"}; // uObj by name
}

void TestBindingsByUse::positionChainPlacesMatrices()
{
    QFETCH(QByteArray, position);
    QFETCH(QStringList, names);
    QFETCH(QStringList, expected);
    std::vector<ShaderVariable> variables;
    for (const QString &name : names)
        variables.push_back({name, GlslType::Mat4, 1, false, false});
    const QByteArray vertex = "attribute vec3 aPos;\nuniform mat4 " + names.join(", ").toLatin1()
        + ";\nvoid main() {\n  " + position + "\n}\n";
    const Bound b = bindAll(variables, vertex, "void main() { gl_FragColor = vec4(1.0); }");
    for (qsizetype k = 0; k < names.size(); ++k) {
        const auto meaning = b.of(names[k].toLatin1().constData());
        QVERIFY2(meaning, qPrintable(names[k]));
        QCOMPARE(bindingMeaningKey(*meaning), expected[k]);
    }
}

void TestBindingsByUse::subtractedFromPositionIsALight()
{
    const QByteArray fragment =
        "precision highp float;\nuniform vec3 beacon;\nuniform vec4 other;\n"
        "varying vec3 pos, nrm;\nvoid main() {\n"
        "  vec3 L = normalize(beacon - pos);\n"
        "  vec3 K = normalize(pos - other.xyz);\n"
        "  gl_FragColor = vec4(max(dot(nrm, L), 0.0) + dot(nrm, K));\n}\n";
    const Bound b = bindAll({uniform("beacon", GlslType::Vec3), uniform("other", GlslType::Vec4)},
                            kVertex, fragment);
    QCOMPARE(b.of("beacon"), M::LightPosition);
    QCOMPARE(b.binding("beacon")->byUse->line, 6);
    QVERIFY(b.binding("beacon")->byUse->reason.contains(QStringLiteral("pos")));
    QCOMPARE(b.of("other"), M::LightPosition);
}

void TestBindingsByUse::eyeWhereALightIsNamed()
{
    const QByteArray fragment = "precision highp float;\nuniform vec3 lightPosition;\n"
                                "uniform vec3 watcher;\nvarying vec3 pos, nrm;\nvoid main() {\n"
                                "  vec3 L = normalize(lightPosition - pos);\n"
                                "  vec3 V = normalize(watcher - pos);\n"
                                "  gl_FragColor = vec4(dot(reflect(-L, nrm), V));\n}\n";
    const Bound b =
        bindAll({uniform("lightPosition", GlslType::Vec3), uniform("watcher", GlslType::Vec3)},
                kVertex, fragment);
    QCOMPARE(b.of("lightPosition"), M::LightPosition);
    QVERIFY(!b.binding("lightPosition")->byUse); // by its name
    QCOMPARE(b.of("watcher"), M::Eye);
}

void TestBindingsByUse::termFactorsSplitTheProducts()
{
    // Names no rule knows: each term's first colour takes the product, the
    // other factors are 1.
    const QByteArray fragment =
        "precision highp float;\nuniform vec3 tintA, tintB, tintC, tintD;\nuniform float "
        "strength;\nuniform vec3 beacon;\nvarying vec3 pos, nrm;\nvoid main() {\n"
        "  vec3 L = normalize(beacon - pos);\n  vec3 R = reflect(-L, nrm);\n"
        "  float lambert = max(dot(nrm, L), 0.0);\n"
        "  vec3 diffuse = tintA * tintB * lambert;\n"
        "  float spec = pow(max(dot(R, normalize(-pos)), 0.0), 32.0);\n"
        "  vec3 specular = strength * spec * tintC;\n"
        "  gl_FragColor = vec4(tintD + diffuse + specular, 1.0);\n}\n";
    const Bound b =
        bindAll({uniform("tintA", GlslType::Vec3), uniform("tintB", GlslType::Vec3),
                 uniform("tintC", GlslType::Vec3), uniform("tintD", GlslType::Vec3),
                 uniform("strength", GlslType::Float), uniform("beacon", GlslType::Vec3)},
                kVertex, fragment);
    QCOMPARE(b.of("beacon"), M::LightPosition);
    QCOMPARE(b.of("tintA"), M::DiffuseProduct);
    QCOMPARE(b.of("tintB"), M::Gain);
    QCOMPARE(b.of("tintC"), M::SpecularProduct);
    QCOMPARE(b.of("strength"), M::Gain);
    QCOMPARE(b.of("tintD"), M::AmbientProduct);
    QCOMPARE(b.binding("tintA")->byUse->line, 10);
    QCOMPARE(b.binding("tintA")->byUse->reason, QStringLiteral("scales the diffuse term"));
    QVERIFY(b.bindings.unboundUniforms().empty());
}

void TestBindingsByUse::aGainBesideANamedColour()
{
    // A scalar ka beside a colour whose name says Ia: the colour holds Ia·ka,
    // the gain is 1, and the product is right whatever the scene's ka.
    const QByteArray fragment =
        "precision highp float;\nuniform float kA;\nuniform vec3 uAmbientLight;\n"
        "uniform vec3 diffuseProduct;\nuniform vec3 beacon;\nvarying vec3 pos, nrm;\n"
        "void main() {\n  vec3 L = normalize(beacon - pos);\n"
        "  vec3 c = kA * uAmbientLight + diffuseProduct * max(dot(nrm, L), 0.0);\n"
        "  gl_FragColor = vec4(c, 1.0);\n}\n";
    const Bound b =
        bindAll({uniform("kA", GlslType::Float), uniform("uAmbientLight", GlslType::Vec3),
                 uniform("diffuseProduct", GlslType::Vec3), uniform("beacon", GlslType::Vec3)},
                kVertex, fragment);
    QCOMPARE(b.of("diffuseProduct"), M::DiffuseProduct);
    QCOMPARE(b.of("kA"), M::Gain);
    QCOMPARE(b.of("uAmbientLight"), M::AmbientProduct);
    QVERIFY(b.binding("uAmbientLight")->byUse->reason.contains(QStringLiteral("kA")));
}

void TestBindingsByUse::aGainOfTheWholeColourStaysTheUsers()
{
    // An exposure slider scales every term: the Uniforms dock's to turn.
    const QByteArray fragment =
        "precision highp float;\nuniform float exposure;\nuniform vec3 ambientProduct, "
        "diffuseProduct, specularProduct;\nvarying vec3 nrm, L, R, V;\nvoid main() {\n"
        "  vec3 I = ambientProduct + diffuseProduct * max(dot(nrm, L), 0.0)"
        " + specularProduct * pow(max(dot(R, V), 0.0), 8.0);\n"
        "  gl_FragColor = vec4(I * exposure, 1.0);\n}\n";
    const Bound b = bindAll(
        {uniform("exposure", GlslType::Float), uniform("ambientProduct", GlslType::Vec3),
         uniform("diffuseProduct", GlslType::Vec3), uniform("specularProduct", GlslType::Vec3)},
        kVertex, fragment);
    QCOMPARE(b.of("exposure"), std::nullopt);
}

void TestBindingsByUse::aColourAddedBesideTheAmbientStaysTheUsers()
{
    // `+= uZork` beside a named ambientProduct is no factor of the
    // ambient term (it was bound as its gain, 1, and whitened the image
    // into a fail); nothing places it, which check says.
    const QByteArray fragment =
        "precision highp float;\nuniform vec3 uZork;\nuniform vec3 ambientProduct, "
        "diffuseProduct, specularProduct;\nvarying vec3 nrm, L, R, V;\nvoid main() {\n"
        "  vec3 I = ambientProduct + diffuseProduct * max(dot(nrm, L), 0.0)"
        " + specularProduct * pow(max(dot(R, V), 0.0), 8.0);\n"
        "  I += uZork;\n  gl_FragColor = vec4(I, 1.0);\n}\n";
    const Bound b = bindAll(
        {uniform("uZork", GlslType::Vec3), uniform("ambientProduct", GlslType::Vec3),
         uniform("diffuseProduct", GlslType::Vec3), uniform("specularProduct", GlslType::Vec3)},
        kVertex, fragment);
    QCOMPARE(b.of("uZork"), std::nullopt);
}

void TestBindingsByUse::columnsAndElementsScaleTheirTerms()
{
    // A mat3 whose columns are Ia, Id, Is beside named coefficients, and a
    // vec3[3] of ka, kd, ks beside named intensities.
    const QByteArray lightColumns =
        "precision highp float;\nuniform mat3 lamp;\nuniform vec3 ka, kd, ks;\n"
        "varying vec3 n, L, R, V;\nvoid main() {\n"
        "  vec3 c = lamp[0] * ka + lamp[1] * kd * max(dot(n, L), 0.0)"
        " + lamp[2] * ks * pow(max(dot(R, V), 0.0), 8.0);\n"
        "  gl_FragColor = vec4(c, 1.0);\n}\n";
    const Bound a = bindAll({uniform("lamp", GlslType::Mat3), uniform("ka", GlslType::Vec3),
                             uniform("kd", GlslType::Vec3), uniform("ks", GlslType::Vec3)},
                            kVertex, lightColumns);
    QCOMPARE(a.of("lamp"), M::LightTerms);
    QCOMPARE(a.binding("lamp")->byUse->line, 6);
    QCOMPARE(a.bindings.lightCapacity(), 1);
    const QByteArray materialElements =
        "precision highp float;\nuniform vec3 coefs[3];\nuniform vec3 Ia, Id, Is;\n"
        "varying vec3 n, L, R, V;\nvoid main() {\n"
        "  vec3 c = Ia * coefs[0] + Id * coefs[1] * max(dot(n, L), 0.0)"
        " + Is * coefs[2] * pow(max(dot(R, V), 0.0), 8.0);\n"
        "  gl_FragColor = vec4(c, 1.0);\n}\n";
    const Bound b = bindAll({uniform("coefs", GlslType::Vec3, 3), uniform("Ia", GlslType::Vec3),
                             uniform("Id", GlslType::Vec3), uniform("Is", GlslType::Vec3)},
                            kVertex, materialElements);
    QCOMPARE(b.of("coefs"), M::MaterialTerms);
    // Out of order (the specular column in the ambient term): no binding.
    QByteArray swapped = lightColumns;
    swapped.replace("lamp[0] * ka", "lamp[2] * ka");
    const Bound c = bindAll({uniform("lamp", GlslType::Mat3), uniform("ka", GlslType::Vec3),
                             uniform("kd", GlslType::Vec3), uniform("ks", GlslType::Vec3)},
                            kVertex, swapped);
    QCOMPARE(c.of("lamp"), std::nullopt);
}

void TestBindingsByUse::namesAndTheUsersWordWin()
{
    const QByteArray fragment = "precision highp float;\nuniform float shininess;\n"
                                "uniform float myExp;\nvarying vec3 r, v;\nvoid main() {\n"
                                "  gl_FragColor = vec4(pow(dot(r, v), shininess) + pow(dot(r, v), "
                                "myExp));\n}\n";
    ExplicitBindings word;
    word[QStringLiteral("myExp")] = std::nullopt; // "none": the user's own
    const Bound b =
        bindAll({uniform("shininess", GlslType::Float), uniform("myExp", GlslType::Float)}, kVertex,
                fragment, word);
    QCOMPARE(b.count, 0);
    QCOMPARE(b.of("shininess"), M::Shininess);
    QVERIFY(!b.binding("shininess")->byUse);
    QCOMPARE(b.of("myExp"), std::nullopt);
}

void TestBindingsByUse::whatNoTermTakesStaysUnbound()
{
    const QByteArray fragment = "precision highp float;\nuniform float cutOff;\nuniform int mode;\n"
                                "uniform vec3 spotDir;\nvarying vec3 L;\nvoid main() {\n"
                                "  float c = 0.0;\n  if (dot(-L, spotDir) > cutOff) c = 1.0;\n"
                                "  if (mode == 1) c = 0.5;\n  gl_FragColor = vec4(c);\n}\n";
    const Bound b = bindAll({uniform("cutOff", GlslType::Float), uniform("mode", GlslType::Int),
                             uniform("spotDir", GlslType::Vec3)},
                            kVertex, fragment);
    QCOMPARE(b.count, 0);
    QCOMPARE(b.bindings.unboundUniforms().size(), std::size_t(3));
}

void TestBindingsByUse::survivesEveryPrefix()
{
    const QByteArray vertex = "attribute vec3 aPos;\nuniform mat4 uA, uB;\nvoid main() {\n"
                              "  vec4 w = uB * vec4(aPos, 1.0);\n  gl_Position = uA * w;\n}\n";
    const QByteArray fragment =
        "precision highp float;\nuniform int kk;\nuniform vec3 q[4];\n"
        "uniform float e;\nvarying vec3 p;\nvoid main() {\n"
        "  vec3 s; for (int i = 0; i < kk; i++) { if (i >= kk) break; "
        "s += pow(length(q[i] - p), e); }\n  gl_FragColor = vec4(s, 1.0);\n}\n";
    const std::vector<ShaderVariable> variables = {
        uniform("uA", GlslType::Mat4), uniform("uB", GlslType::Mat4), uniform("kk", GlslType::Int),
        uniform("q", GlslType::Vec3, 4), uniform("e", GlslType::Float)};
    for (qsizetype cut = 0; cut <= fragment.size(); ++cut)
        bindAll(variables, vertex.left(cut % (vertex.size() + 1)), fragment.left(cut));
    const Bound whole = bindAll(variables, vertex, fragment);
    for (const VariableBinding &b : whole.bindings.variables)
        QVERIFY2(b.meaning, qPrintable(b.variable.name));
    QCOMPARE(whole.count, 5);
}

QTEST_GUILESS_MAIN(TestBindingsByUse)
#include "tst_bindingsbyuse.moc"
