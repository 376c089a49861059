// What students' names mean (core/ShaderBindings): automatic binding by name
// and type, the user's explicit word, what cannot be bound, how many lights
// a program takes, and the scene file's "bindings".
#include "core/program/ShaderBindings.h"
#include "core/scene/SceneJson.h"

#include <QTest>

using namespace phonglab;

namespace {

using M = BindingMeaning;
using T = GlslType;

ShaderVariable uniform(const char *name, GlslType type, int arraySize = 1)
{
    return {QString::fromLatin1(name), type, arraySize, arraySize > 1, false};
}
ShaderVariable input(const char *name, GlslType type)
{
    return {QString::fromLatin1(name), type, 1, false, true};
}

} // namespace

Q_DECLARE_METATYPE(ShaderVariable)

class TestShaderBindings : public QObject
{
    Q_OBJECT

private slots:
    void namesStudentsWrite_data()
    {
        QTest::addColumn<ShaderVariable>("variable");
        QTest::addColumn<QString>("meaning"); // "" for none
        const auto row = [](const char *tag, ShaderVariable v, const char *meaning) {
            QTest::newRow(tag) << v << QString::fromLatin1(meaning);
        };
        // PhongLab's own names, unchanged.
        row("position", input("position", T::Vec3), "position");
        row("normal", input("normal", T::Vec3), "normal");
        row("modelMatrix", uniform("modelMatrix", T::Mat4), "model");
        row("modelViewMatrix", uniform("modelViewMatrix", T::Mat4), "model-view");
        row("normalMatrix", uniform("normalMatrix", T::Mat3), "normal-matrix");
        row("projectionMatrix", uniform("projectionMatrix", T::Mat4), "projection");
        row("viewMatrix", uniform("viewMatrix", T::Mat4), "view");
        row("lightPosition", uniform("lightPosition", T::Vec3, 8), "light-position");
        row("lightCount", uniform("lightCount", T::Int), "light-count");
        row("Id", uniform("Id", T::Vec3, 8), "Id");
        row("Is", uniform("Is", T::Vec3, 8), "Is");
        row("attenuation", uniform("attenuation", T::Vec3, 8), "attenuation");
        row("Ia", uniform("Ia", T::Vec3), "Ia");
        row("ka", uniform("ka", T::Vec3), "ka");
        row("shininess", uniform("shininess", T::Float), "shininess");
        // WebGL course names: prefixes, separators, suffixes, case.
        row("aPosition", input("aPosition", T::Vec3), "position");
        row("a_normal", input("a_normal", T::Vec4), "normal");
        row("inPosition", input("inPosition", T::Vec3), "position");
        row("uModelMatrix", uniform("uModelMatrix", T::Mat4), "model");
        row("u_world", uniform("u_world", T::Mat4), "model");
        row("uMVMatrix", uniform("uMVMatrix", T::Mat4), "model-view");
        row("uPMatrix", uniform("uPMatrix", T::Mat4), "projection");
        row("uNMatrix", uniform("uNMatrix", T::Mat3), "normal-matrix");
        row("u_mvp", uniform("u_mvp", T::Mat4), "model-view-projection");
        row("uViewProjection", uniform("uViewProjection", T::Mat4), "view-projection");
        row("uModelNormalMatrix", uniform("uModelNormalMatrix", T::Mat3), "model-normal-matrix");
        row("uEyePosition", uniform("uEyePosition", T::Vec3), "eye");
        row("u_cameraPos", uniform("u_cameraPos", T::Vec3), "eye");
        row("uLightPos", uniform("uLightPos", T::Vec3), "light-position");
        row("u_lightPosWorld", uniform("u_lightPosWorld", T::Vec4, 2), "light-position");
        row("uNumLights", uniform("uNumLights", T::Int), "light-count");
        row("uLightDiffuse", uniform("uLightDiffuse", T::Vec3, 2), "Id");
        row("uDiffuseColor", uniform("uDiffuseColor", T::Vec3), "Id");
        row("uSpecularIntensity", uniform("uSpecularIntensity", T::Vec3), "Is");
        row("uAmbientLight", uniform("uAmbientLight", T::Vec3), "Ia");
        row("uKd", uniform("uKd", T::Vec3), "kd");
        row("u_Ks", uniform("u_Ks", T::Vec3), "ks");
        row("uMaterialDiffuse", uniform("uMaterialDiffuse", T::Vec3), "kd");
        row("u_n", uniform("u_n", T::Float), "shininess");
        row("uSpecularExponent", uniform("uSpecularExponent", T::Float), "shininess");
        row("u_c1", uniform("u_c1", T::Float), "c1");
        row("uQuadraticAttenuation", uniform("uQuadraticAttenuation", T::Float), "c3");
        // Struct members: the container says what the member is.
        row("uLights[1].position", uniform("uLights[1].position", T::Vec3), "light-position");
        row("uLights[0].diffuse", uniform("uLights[0].diffuse", T::Vec3), "Id");
        row("uLight.constant", uniform("uLight.constant", T::Float), "c1");
        row("uMaterial.diffuse", uniform("uMaterial.diffuse", T::Vec3), "kd");
        row("material.shininess", uniform("material.shininess", T::Float), "shininess");
        // What courses pass: Angel's products, one colour for two terms, the
        // light already in camera coordinates, structs of every course, ints.
        row("ambientProduct", uniform("ambientProduct", T::Vec4), "ambient-product");
        row("diffuseProduct", uniform("diffuseProduct", T::Vec4), "diffuse-product");
        row("specularProduct[2]", uniform("specularProduct", T::Vec3, 2), "specular-product");
        row("uAmbientProduct", uniform("uAmbientProduct", T::Vec4), "ambient-product");
        row("u_lightColor", uniform("u_lightColor", T::Vec3), "light-color");
        row("light_colors[3]", uniform("light_colors", T::Vec3, 3), "light-color");
        row("lights[1].color", uniform("lights[1].color", T::Vec3), "light-color");
        row("pointLights[0].color", uniform("pointLights[0].color", T::Vec3), "light-color");
        row("material_color", uniform("material_color", T::Vec3), "material-color");
        row("u_color", uniform("u_color", T::Vec4), "material-color");
        row("lightPosEye", uniform("lightPosEye", T::Vec4), "light-position-camera");
        row("u_lightPositionView", uniform("u_lightPositionView", T::Vec3),
            "light-position-camera");
        row("u_lightWorldPosition", uniform("u_lightWorldPosition", T::Vec3), "light-position");
        row("u_viewWorldPosition", uniform("u_viewWorldPosition", T::Vec3), "eye");
        row("u_LampSet[0].pos", uniform("u_LampSet[0].pos", T::Vec3), "light-position");
        row("u_LampSet[1].diff", uniform("u_LampSet[1].diff", T::Vec3), "Id");
        row("u_LampSet[1].spec", uniform("u_LampSet[1].spec", T::Vec3), "Is");
        row("u_MatlSet[0].ambi", uniform("u_MatlSet[0].ambi", T::Vec3), "ka");
        row("u_MatlSet[0].shiny", uniform("u_MatlSet[0].shiny", T::Float), "shininess");
        row("material.shininess as int", uniform("material.shininess", T::Int), "shininess");
        row("lights[0].quadratic as int", uniform("lights[0].quadratic", T::Int), "c3");
        // The type decides, never the name alone.
        row("uLightPos as mat3", uniform("uLightPos", T::Mat3), "");
        row("n as mat3", uniform("n", T::Mat3), "normal-matrix");
        row("uModel as vec3", uniform("uModel", T::Vec3), "");
        row("normal as a uniform vec3", uniform("normal", T::Vec3), "");
        row("uKd as an array", uniform("uKd", T::Vec3, 2), "");
        row("position as a uniform", uniform("position", T::Vec3), "");
        // The user's own.
        row("gain", uniform("gain", T::Float), "");
        row("uTime", uniform("uTime", T::Float), "");
        row("attribute named ambient", uniform("ambient", T::Vec3), "");
    }

    void namesStudentsWrite()
    {
        QFETCH(ShaderVariable, variable);
        QFETCH(QString, meaning);
        const std::optional<BindingMeaning> found = automaticMeaning(variable);
        QCOMPARE(found ? bindingMeaningKey(*found) : QString(), meaning);
    }

    void keysRoundTrip()
    {
        for (const QString &key : bindingMeaningKeys())
            QCOMPARE(bindingMeaningKey(*bindingMeaningFromKey(key)), key);
        QCOMPARE(bindingMeaningKeys().size(), int(kBindingMeaningCount));
        QVERIFY(!bindingMeaningFromKey(QStringLiteral("Model")));
    }

    void explicitWinsAndIsChecked()
    {
        const std::vector<ShaderVariable> variables = {
            uniform("normalMatrix", T::Mat3), uniform("uLightPos2", T::Vec3),
            uniform("uKd", T::Vec3), uniform("uGain", T::Float)};
        const ExplicitBindings explicitBindings = {
            {QStringLiteral("normalMatrix"), M::ModelNormalMatrix}, // world-space lighting
            {QStringLiteral("uKd"), std::nullopt},                  // the user's own
            {QStringLiteral("uGain"), M::Model},                    // cannot hold
            {QStringLiteral("uNothing"), M::Eye}};                  // no such variable
        const ProgramBindings b = bindVariables(variables, explicitBindings);
        QCOMPARE(b.meaningOf(QStringLiteral("normalMatrix")), M::ModelNormalMatrix);
        QVERIFY(b.variables[0].isExplicit);
        QCOMPARE(b.meaningOf(QStringLiteral("uLightPos2")), std::nullopt);
        QCOMPARE(b.meaningOf(QStringLiteral("uKd")), std::nullopt);
        QCOMPARE(b.meaningOf(QStringLiteral("uGain")), std::nullopt);
        QCOMPARE(b.problems.size(), 1);
        QVERIFY2(b.problems[0].contains(QLatin1String("uGain=model")), qPrintable(b.problems[0]));
        QCOMPARE(b.notes.size(), 1);
        QVERIFY2(b.notes[0].contains(QLatin1String("uNothing")), qPrintable(b.notes[0]));
        // Unbound uniforms and what they probably are.
        const auto unbound = b.unboundUniforms();
        QCOMPARE(unbound.size(), std::size_t(3));
        QCOMPARE(likelyMeaning(unbound[0]->variable), M::LightPosition);
        QCOMPARE(likelyMeaning(uniform("uTime", T::Float)), std::nullopt);
    }

    void lightCapacity()
    {
        const auto capacity = [](std::vector<ShaderVariable> v) {
            return bindVariables(v, {}).lightCapacity();
        };
        QCOMPARE(capacity({uniform("uKd", T::Vec3)}), std::nullopt);
        QCOMPARE(capacity({uniform("uLightPos", T::Vec3), uniform("uId", T::Vec3)}), 1);
        QCOMPARE(capacity({uniform("uLightPos", T::Vec3, 4), uniform("uId", T::Vec3, 2)}), 2);
        QCOMPARE(capacity({uniform("uLights[0].position", T::Vec3),
                           uniform("uLights[1].position", T::Vec3),
                           uniform("uLights[2].position", T::Vec3)}),
                 3);
    }

    void parsesArguments()
    {
        QString error;
        const auto parsed = parseBindingArgument(QStringLiteral("uWorld=model"), &error);
        QVERIFY(parsed);
        QCOMPARE(parsed->name, QStringLiteral("uWorld"));
        QCOMPARE(parsed->meaning, M::Model);
        const auto none = parseBindingArgument(QStringLiteral("uKd=none"), &error);
        QVERIFY(none && !none->meaning);
        QVERIFY(!parseBindingArgument(QStringLiteral("uWorld=modle"), &error));
        QVERIFY2(error.contains(QLatin1String("unknown meaning 'modle'")), qPrintable(error));
        QVERIFY(!parseBindingArgument(QStringLiteral("uWorld"), &error));
        QVERIFY(!parseBindingArgument(QStringLiteral("=model"), &error));
    }

    void sceneFileBindings()
    {
        const QByteArray json = R"({"mesh": "builtin:sphere",
            "bindings": {"uWorld": "model", "uGain": "none"}})";
        const SceneLoadResult loaded = parseScene(json, QString());
        QVERIFY2(loaded.ok(), qPrintable(loaded.error));
        QVERIFY(loaded.warnings.isEmpty());
        const ExplicitBindings expected = {{QStringLiteral("uWorld"), M::Model},
                                           {QStringLiteral("uGain"), std::nullopt}};
        QCOMPARE(loaded.scene->bindings, expected);
        // Saved and read again: the same.
        const SceneLoadResult again = parseScene(sceneToJson(*loaded.scene), QString());
        QVERIFY2(again.ok(), qPrintable(again.error));
        QCOMPARE(again.scene->bindings, expected);

        const SceneLoadResult wrong =
            parseScene(R"({"mesh": "builtin:sphere", "bindings": {"uWorld": "modle"}})", QString());
        QVERIFY(!wrong.ok());
        QVERIFY2(wrong.error.startsWith(QLatin1String("bindings.uWorld: unknown meaning")),
                 qPrintable(wrong.error));
        const SceneLoadResult notText =
            parseScene(R"({"mesh": "builtin:sphere", "bindings": {"uWorld": 3}})", QString());
        QVERIFY(!notText.ok());
        QVERIFY2(notText.error.startsWith(QLatin1String("bindings.uWorld: expected")),
                 qPrintable(notText.error));
    }
};

QTEST_APPLESS_MAIN(TestShaderBindings)
#include "tst_shaderbindings.moc"
