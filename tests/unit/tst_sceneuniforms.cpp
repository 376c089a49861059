// The scene's "uniforms": values of the shader's own uniforms, and which of
// a running program's values a saved scene keeps (render/program/SceneUniforms).
#include "core/scene/SceneJson.h"
#include "render/program/SceneUniforms.h"

#include <QTest>

using namespace phonglab;

namespace {
QByteArray sceneWith(const QByteArray &uniforms)
{
    return R"({"mesh": "builtin:sphere", "uniforms": )" + uniforms + "}";
}
} // namespace

class TestSceneUniforms : public QObject
{
    Q_OBJECT

private slots:
    void absentMeansNone();
    void readsNumbersAndVectors();
    void roundTrips();
    void refusesBadValues_data();
    void refusesBadValues();
    void savesOnlyTheUsersPlainNumbers();
};

void TestSceneUniforms::absentMeansNone()
{
    const SceneLoadResult r = parseScene(R"({"mesh": "builtin:sphere"})");
    QVERIFY(r.ok());
    QVERIFY(r.scene->uniforms.empty());
    QVERIFY(!sceneToJson(*r.scene).contains("\"uniforms\""));
}

void TestSceneUniforms::readsNumbersAndVectors()
{
    const SceneLoadResult r =
        parseScene(sceneWith(R"({"gain": 0.5, "tint": [1, 0.25, 0], "lights[2]": 3})"));
    QVERIFY2(r.ok(), qPrintable(r.error));
    QCOMPARE(r.scene->uniforms.size(), std::size_t(3));
    QCOMPARE(r.scene->uniforms.at(QStringLiteral("gain")), std::vector<double>{0.5});
    QCOMPARE(r.scene->uniforms.at(QStringLiteral("tint")), (std::vector<double>{1.0, 0.25, 0.0}));
    QVERIFY(r.warnings.isEmpty());
}

void TestSceneUniforms::roundTrips()
{
    const SceneLoadResult first = parseScene(sceneWith(R"({"gain": 0.5, "tint": [1, 0.25, 0]})"));
    QVERIFY(first.ok());
    const SceneLoadResult again = parseScene(sceneToJson(*first.scene));
    QVERIFY2(again.ok(), qPrintable(again.error));
    QVERIFY(*again.scene == *first.scene);
}

void TestSceneUniforms::refusesBadValues_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("prefix");
    QTest::newRow("not an object") << sceneWith("[1, 2]") << "uniforms:";
    QTest::newRow("string value") << sceneWith(R"({"gain": "high"})") << "uniforms.gain:";
    QTest::newRow("empty array") << sceneWith(R"({"tint": []})") << "uniforms.tint:";
    QTest::newRow("17 numbers") << sceneWith(
        R"({"m": [1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17]})")
                                << "uniforms.m:";
    QTest::newRow("overflow") << sceneWith(R"({"gain": 1e999})") << "uniforms.gain:";
    QTest::newRow("element not a number")
        << sceneWith(R"({"tint": [1, "x", 0]})") << "uniforms.tint[1]:";
}

void TestSceneUniforms::refusesBadValues()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, prefix);
    const SceneLoadResult r = parseScene(json);
    QVERIFY(!r.ok());
    QVERIFY2(r.error.startsWith(prefix), qPrintable(r.error));
}

namespace {
UniformValue uniform(const char *name, GLenum type, UniformValue::Kind kind,
                     std::initializer_list<double> values)
{
    UniformValue v;
    v.name = name;
    v.type = type;
    v.kind = kind;
    v.components = int(values.size());
    int i = 0;
    for (const double x : values) { // only the kind's own words, as the driver fills them
        switch (kind) {
        case UniformValue::Kind::Float: v.floats[i] = GLfloat(x); break;
        case UniformValue::Kind::Int: v.ints[i] = GLint(x); break;
        case UniformValue::Kind::UInt: v.uints[i] = GLuint(x); break;
        }
        ++i;
    }
    return v;
}
} // namespace

// The user's own numbers are kept, with their element index; what the
// renderer or the scene's docks set, and samplers (texture units), are not.
void TestSceneUniforms::savesOnlyTheUsersPlainNumbers()
{
    using Kind = UniformValue::Kind;
    UniformSnapshot snapshot;
    snapshot.values = {
        uniform("gain", GL_FLOAT, Kind::Float, {0.5}),
        uniform("tint", GL_FLOAT_VEC3, Kind::Float, {1, 0.25, 0}),
        uniform("steps[2]", GL_INT, Kind::Int, {-3}),
        uniform("mask", GL_UNSIGNED_INT, Kind::UInt, {7}),
        uniform("flag", GL_BOOL, Kind::Int, {1}),
        uniform("image", GL_SAMPLER_2D, Kind::Int, {0}),
        uniform("modelViewMatrix", GL_FLOAT_MAT4, Kind::Float,
                {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}),
        uniform("kd", GL_FLOAT_VEC3, Kind::Float, {0.5, 0.5, 0.5}),
        uniform("Id[1]", GL_FLOAT_VEC3, Kind::Float, {1, 1, 1}),
    };
    const std::map<QString, std::vector<double>> expected = {
        {QStringLiteral("gain"), {0.5}},    {QStringLiteral("tint"), {1, 0.25, 0}},
        {QStringLiteral("steps[2]"), {-3}}, {QStringLiteral("mask"), {7}},
        {QStringLiteral("flag"), {1}},
    };
    const std::vector<ShaderVariable> variables = {
        {QStringLiteral("gain"), GlslType::Float},
        {QStringLiteral("tint"), GlslType::Vec3},
        {QStringLiteral("steps"), GlslType::Int, 3, true},
        {QStringLiteral("mask"), GlslType::UInt},
        {QStringLiteral("flag"), GlslType::Bool},
        {QStringLiteral("image"), GlslType::Other},
        {QStringLiteral("modelViewMatrix"), GlslType::Mat4},
        {QStringLiteral("kd"), GlslType::Vec3},
        {QStringLiteral("Id"), GlslType::Vec3, 2, true},
    };
    QCOMPARE(userUniformValues(snapshot, bindVariables(variables, {})), expected);
    // A uniform the user bound to a meaning is PhongLab's to set, not saved.
    std::map<QString, std::vector<double>> withoutGain = expected;
    withoutGain.erase(QStringLiteral("gain"));
    QCOMPARE(userUniformValues(
                 snapshot,
                 bindVariables(variables, {{QStringLiteral("gain"), BindingMeaning::Shininess}})),
             withoutGain);
}

QTEST_APPLESS_MAIN(TestSceneUniforms)
#include "tst_sceneuniforms.moc"
