#include "core/scene/SceneJson.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

using namespace phonglab;

namespace {

// A scene object of `mesh`, the rest as a new object has it.
SceneObject objectOf(const QString &mesh)
{
    SceneObject object;
    object.mesh = mesh;
    return object;
}

const QString kSceneDataDir = QStringLiteral(PHONGLAB_TEST_DATA_DIR "/scenes");

// Every field away from its default, awkward doubles included, so a field
// the writer or reader forgets (or rounds) shows up as an inequality.
Scene fullScene()
{
    Scene scene;
    SceneObject bunny;
    bunny.mesh = QStringLiteral("meshes/bunny.obj");
    bunny.transform.translate = {1.0, -2.0, 3.5};
    bunny.transform.rotateDeg = {10.0, 20.0 / 3.0, -30.0};
    bunny.transform.scale = {0.5, 2.0, -1.0};
    bunny.material.ka = {0.1, 0.2, 0.3};
    bunny.material.kd = {0.4, 0.5, 1.0 / 3.0};
    bunny.material.ks = {0.7, 0.8, 0.9};
    bunny.material.shininess = 64.5;
    SceneObject torus;
    torus.mesh = QStringLiteral("builtin:torus");
    torus.transform.translate = {-1.5, 0.25, 0.0};
    torus.transform.rotateDeg = {90.0, 0.0, 45.0};
    torus.transform.scale = {0.8, 0.8, 0.8};
    torus.material.kd = {0.9, 0.1, 0.1};
    torus.material.shininess = 8.0;
    torus.detail = 0.0625; // a level of detail; the bunny keeps the default 1
    scene.objects = {bunny, torus};

    scene.camera.eye = {1.0, 2.0, 6.0};
    scene.camera.target = {0.0, 0.5, 0.0};
    scene.camera.up = {0.0, 0.0, 1.0};
    scene.camera.fovDeg = 60.0;
    scene.camera.nearPlane = 0.25;
    scene.camera.farPlane = 250.0;
    scene.camera.frameObjects = false; // a shot the user composed: not the default
    scene.ambient = {0.05, 0.1, 0.15};
    scene.lights = {
        PointLight{
            {3.0, 4.0, 5.0}, {1.0, 0.9, 0.8}, {0.5, 0.5, 0.5}, {1.0, 0.1, 0.01}, "key light", true},
        PointLight{{-4.0, 2.0, 1.0}, {0.3, 0.3, 0.6}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.2}, "", false},
        PointLight{
            {0.0, -3.0, 0.1}, {2.5, 2.5, 2.5}, {1.0, 1.0, 1.0}, {0.5, 0.0, 0.0}, "rim", true},
    };
    scene.shading = ShadingMethod::BlinnPhong; // not the default
    scene.background = {0.3, 0.2, 0.1};
    scene.course.defines = {{QStringLiteral("NUM_LIGHTS"), QStringLiteral("3")},
                            {QStringLiteral("USE_BLINN"), QString()}};
    scene.course.precision = PrecisionRule::AsWritten; // not the default
    return scene;
}

Scene sphereScene()
{
    Scene scene;
    scene.objects = {objectOf(QStringLiteral("builtin:sphere"))};
    return scene;
}

QByteArray withSphere(const char *fields)
{
    return QByteArray(R"({"mesh": "builtin:sphere", )") + fields + '}';
}

QByteArray withLights(const char *lights)
{
    return QByteArray(R"({"mesh": "builtin:sphere", "lights": )") + lights + '}';
}

} // namespace

class TestSceneJson : public QObject
{
    Q_OBJECT

private slots:
    void savedScenesCarryTheGenerator();
    void roundTripFullScene();
    void roundTripSingleObject();
    void defaultsWhenOptionalFieldsMissing();
    void multiObjectFormDefaults();
    void rejectsBadInput_data();
    void rejectsBadInput();
    void syntaxErrorGivesLineAndOffset();
    void underflowReadsAsZero();
    void warnsAboutUnknownKeys();
    void warnsAboutTopLevelTransformWithObjects();
    void loadMissingFileSaysWhyOnce();
    void relativeMeshResolvesAgainstSceneFolder();
    void saveThenLoadGivesEqualScene();
    void saveIntoMissingDirectoryFails();
    void saveRefusesInvalidSceneAndKeepsOldFile();
    void docExampleLoadsCleanly();
    void detailRoundTripsAndDefaultsAreNotWritten();
    void oldFlatLoadsAsFacetedWithANote();
    void autoDetailAndObjectShadingRoundTrip();
};

void TestSceneJson::roundTripFullScene()
{
    const Scene scene = fullScene();
    const QByteArray json = sceneToJson(scene);
    QVERIFY(QJsonDocument::fromJson(json).object().contains(QStringLiteral("objects")));

    const SceneLoadResult result = parseScene(json);
    QVERIFY2(result.ok(), qPrintable(result.error));
    QVERIFY2(result.warnings.isEmpty(), qPrintable(result.warnings.join(u'\n')));
    QCOMPARE(result.scene->objects.size(), std::size_t(2));
    QCOMPARE(result.scene->lights.size(), std::size_t(3));
    QVERIFY(*result.scene == scene);
}

void TestSceneJson::roundTripSingleObject()
{
    Scene scene = fullScene();
    scene.objects.resize(1);
    const QByteArray json = sceneToJson(scene);
    const QJsonObject root = QJsonDocument::fromJson(json).object();
    QCOMPARE(root.value(QStringLiteral("mesh")).toString(), QStringLiteral("meshes/bunny.obj"));
    QVERIFY(!root.contains(QStringLiteral("objects")));

    const SceneLoadResult result = parseScene(json);
    QVERIFY2(result.ok(), qPrintable(result.error));
    QVERIFY(*result.scene == scene);
}

void TestSceneJson::defaultsWhenOptionalFieldsMissing()
{
    const SceneLoadResult result =
        parseScene(R"({"mesh": "builtin:sphere"})", QStringLiteral("/scenes"));
    QVERIFY2(result.ok(), qPrintable(result.error));
    QVERIFY(result.warnings.isEmpty());
    QVERIFY(*result.scene == sphereScene());
    QVERIFY(result.scene->lights.empty());
    QCOMPARE(result.scene->baseDir, QStringLiteral("/scenes"));
    // An old scene is checked as a desktop browser computes it, with no defines.
    QVERIFY(result.scene->course.precision == PrecisionRule::Highp);
    QVERIFY(result.scene->course.defines.empty());
    QVERIFY(!sceneToJson(*result.scene).contains("precision"));
    QVERIFY(!sceneToJson(*result.scene).contains("defines"));
    // A number is the token's text.
    const SceneLoadResult defined =
        parseScene(withSphere(R"("defines": {"NUM_LIGHTS": 2, "SCALE": 0.5})"));
    QVERIFY2(defined.ok(), qPrintable(defined.error));
    QCOMPARE(defined.scene->course.defines.at(QStringLiteral("NUM_LIGHTS")), QStringLiteral("2"));
    QCOMPARE(defined.scene->course.defines.at(QStringLiteral("SCALE")), QStringLiteral("0.5"));

    // Partial objects keep the defaults of the fields they leave out.
    const SceneLoadResult partial = parseScene(withSphere(R"(
        "camera": {"fov_deg": 30}, "material": {"shininess": 5}, "lights": [{"position": [1, 2, 3]}])"));
    QVERIFY2(partial.ok(), qPrintable(partial.error));
    Camera camera;
    camera.fovDeg = 30.0;
    QVERIFY(partial.scene->camera == camera);
    Material material;
    material.shininess = 5.0;
    QVERIFY(partial.scene->objects.front().material == material);
    QCOMPARE(partial.scene->lights.size(), std::size_t(1));
    PointLight expected;
    expected.position = {1.0, 2.0, 3.0};
    QVERIFY(partial.scene->lights.front() == expected);
}

void TestSceneJson::multiObjectFormDefaults()
{
    const SceneLoadResult result =
        loadSceneFile(kSceneDataDir + QStringLiteral("/two_objects.json"));
    QVERIFY2(result.ok(), qPrintable(result.error));
    QVERIFY(result.warnings.isEmpty());
    const Scene &scene = *result.scene;
    QCOMPARE(scene.objects.size(), std::size_t(2));
    QCOMPARE(scene.objects[0].mesh, QStringLiteral("builtin:sphere"));
    QCOMPARE(scene.objects[0].transform.scale, glm::dvec3(1.0));
    QCOMPARE(scene.objects[0].material.shininess, 64.0);
    QCOMPARE(scene.objects[1].transform.rotateDeg, glm::dvec3(90.0, 0.0, 0.0));
    QVERIFY(scene.objects[1].material == Material{});
    QCOMPARE(scene.lights.size(), std::size_t(2));
    QCOMPARE(scene.lights[0].attenuation, glm::dvec3(1.0, 0.0, 0.0));
}

void TestSceneJson::rejectsBadInput_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("pathPrefix"); // the error must start with this
    QTest::addColumn<QString>("mentions");   // ... and contain this, when not empty

    auto row = [](const char *name, const QByteArray &json, const char *prefix,
                  const char *mentions = "") {
        QTest::newRow(name) << json << QString::fromUtf8(prefix) << QString::fromUtf8(mentions);
    };

    // Document level
    row("not json", R"({"mesh": "builtin:sphere",)", "JSON syntax error at line 1", "byte offset");
    row("empty input", "", "JSON syntax error");
    row("top level array", R"([{"mesh": "builtin:sphere"}])", "top level:", "object");

    // What the course's page adds
    row("defines not object", withSphere(R"("defines": ["N=2"])"), "defines:", "NAME: VALUE");
    row("define not identifier", withSphere(R"("defines": {"1N": 2})"),
        "defines.1N:", "GLSL identifier");
    row("define two lines", withSphere(R"("defines": {"N": "2\n#error"})"),
        "defines.N:", "one line");
    row("define array value", withSphere(R"("defines": {"N": [2]})"), "defines.N:", "got array");
    row("precision unknown", withSphere(R"("precision": "mediump")"), "precision:", "as-written");

    // Mesh / objects
    row("no mesh", R"({"camera": {}})", "mesh: required field missing", "objects");
    row("mesh and objects", R"({"mesh": "a.obj", "objects": [{"mesh": "b.obj"}]})",
        "objects:", "mesh");
    row("mesh not string", R"({"mesh": ["a.obj"]})", "mesh:", "got array");
    row("mesh empty", R"({"mesh": ""})", "mesh:", "empty");
    row("objects not array", R"({"objects": {"mesh": "a.obj"}})", "objects:", "array");
    row("objects empty", R"({"objects": []})", "objects:", "at least one");
    row("object not object", R"({"objects": ["a.obj"]})", "objects[0]:", "expected an object");
    row("object mesh missing", R"({"objects": [{"mesh": "a.obj"}, {}]})",
        "objects[1].mesh:", "required");
    row("object mesh empty", R"({"objects": [{"mesh": ""}]})", "objects[0].mesh:", "empty");
    row("object scale zero",
        R"({"objects": [{"mesh": "a"}, {"mesh": "b", "transform": {"scale": [1, 1, 0]}}]})",
        "objects[1].transform.scale[2]:", "0");
    row("object shininess zero", R"({"objects": [{"mesh": "a", "material": {"shininess": 0}}]})",
        "objects[0].material.shininess:");
    row("detail zero", R"({"objects": [{"mesh": "a"}, {"mesh": "b", "detail": 0}]})",
        "objects[1].detail: expected a number in (0, 1], got 0");
    row("detail negative", R"({"objects": [{"mesh": "a", "detail": -0.5}]})",
        "objects[0].detail:", "got -0.5");
    row("detail above one", R"({"objects": [{"mesh": "a", "detail": 1.5}]})",
        "objects[0].detail:", "(0, 1]");
    row("detail string", R"({"objects": [{"mesh": "a", "detail": "0.5"}]})",
        "objects[0].detail:", "got string");
    row("detail null", R"({"objects": [{"mesh": "a", "detail": null}]})",
        "objects[0].detail:", "got null");
    row("detail overflow", R"({"objects": [{"mesh": "a", "detail": 1e999}]})",
        "objects[0].detail:", "(0, 1]");
    row("single-object detail zero", withSphere(R"("detail": 0)"),
        "detail: expected a number in (0, 1], got 0");

    // Transform
    row("transform not object", withSphere(R"("transform": [1, 2, 3])"),
        "transform:", "expected an object");
    row("translate string", withSphere(R"("transform": {"translate": "1 2 3"})"),
        "transform.translate:", "got string");
    row("translate two elements", withSphere(R"("transform": {"translate": [1, 2]})"),
        "transform.translate:", "got 2 elements");
    row("rotate non-number", withSphere(R"("transform": {"rotate_deg": [0, "90", 0]})"),
        "transform.rotate_deg[1]:", "got string");
    row("scale zero", withSphere(R"("transform": {"scale": [1, 0, 1]})"),
        "transform.scale[1]:", "0");

    // Camera
    row("camera not object", withSphere(R"("camera": "front")"), "camera:");
    row("fov zero", withSphere(R"("camera": {"fov_deg": 0})"), "camera.fov_deg:", "(0, 180)");
    row("fov 180", withSphere(R"("camera": {"fov_deg": 180})"), "camera.fov_deg:", "(0, 180)");
    row("fov negative", withSphere(R"("camera": {"fov_deg": -45})"), "camera.fov_deg:");
    row("frame_objects not bool", withSphere(R"("camera": {"frame_objects": "no"})"),
        "camera.frame_objects:", "true or false");
    row("fov string", withSphere(R"("camera": {"fov_deg": "45"})"),
        "camera.fov_deg:", "got string");
    row("near zero", withSphere(R"("camera": {"near": 0})"), "camera.near:", "> 0");
    row("near negative", withSphere(R"("camera": {"near": -1})"), "camera.near:");
    row("far equals near", withSphere(R"("camera": {"near": 1, "far": 1})"), "camera.far:", "near");
    row("far below near", withSphere(R"("camera": {"near": 5, "far": 2})"), "camera.far:");
    row("eye equals target", withSphere(R"("camera": {"eye": [1, 2, 3], "target": [1, 2, 3]})"),
        "camera.target:", "eye");
    row("up parallel", withSphere(R"("camera": {"eye": [0, 5, 0], "target": [0, 0, 0]})"),
        "camera.up:", "parallel");
    row("up antiparallel", withSphere(R"("camera": {"eye": [0, 0, 4], "up": [0, 0, 2]})"),
        "camera.up:", "parallel");
    row("up zero", withSphere(R"("camera": {"up": [0, 0, 0]})"), "camera.up:");

    // Material, ambient, background, shading
    row("ka negative", withSphere(R"("material": {"ka": [-0.1, 0, 0]})"),
        "material.ka[0]:", ">= 0");
    row("kd wrong length", withSphere(R"("material": {"kd": [0.5, 0.5, 0.5, 1]})"),
        "material.kd:", "got 4 elements");
    row("ks null element", withSphere(R"("material": {"ks": [0.5, null, 0.5]})"),
        "material.ks[1]:", "got null");
    row("shininess zero", withSphere(R"("material": {"shininess": 0})"),
        "material.shininess:", "> 0");
    row("shininess negative", withSphere(R"("material": {"shininess": -8})"),
        "material.shininess:");
    row("ambient negative", withSphere(R"("ambient": [0.1, 0.1, -0.1])"), "ambient[2]:", ">= 0");
    row("background string", withSphere(R"("background": "#202020")"), "background:", "got string");
    row("shading unknown", withSphere(R"("shading": "toon")"), "shading:", "blinn-phong");
    row("shading not string", withSphere(R"("shading": 1)"), "shading:", "got number");
    row("format zero", withSphere(R"("format": 0)"), "format:", "got 0");
    row("format fraction", withSphere(R"("format": 1.5)"), "format:", "whole number");
    row("format string", withSphere(R"("format": "2")"), "format:", "got string");

    // Lights
    row("lights not array", withLights(R"({"position": [1, 1, 1]})"),
        "lights:", "expected an array");
    row("light not object", withLights(R"([[1, 1, 1]])"), "lights[0]:", "expected an object");
    row("light position missing",
        withLights(R"([{"position": [1, 1, 1]}, {"diffuse": [1, 1, 1]}])"),
        "lights[1].position:", "required");
    row("light diffuse element string",
        withLights(R"([{"position": [0, 0, 5]}, {"position": [1, 0, 5]},
        {"position": [2, 0, 5], "diffuse": [1, "1", 1]}])"),
        "lights[2].diffuse[1]:", "got string");
    row("light specular negative",
        withLights(R"([{"position": [1, 1, 1], "specular": [-1, 0, 0]}])"),
        "lights[0].specular[0]:", ">= 0");
    row("attenuation negative",
        withLights(R"([{"position": [1, 1, 1], "attenuation": [1, -0.1, 0]}])"),
        "lights[0].attenuation[1]:", ">= 0");
    row("attenuation sum zero",
        withLights(
            R"([{"position": [1, 1, 1]}, {"position": [1, 1, 1], "attenuation": [0, 0, 0]}])"),
        "lights[1].attenuation:", "c1 + c2 + c3 must be positive (got 0)");
    row("attenuation wrong length",
        withLights(R"([{"position": [1, 1, 1], "attenuation": [1, 0]}])"),
        "lights[0].attenuation:", "3 numbers");
    QByteArray nineLights = "[";
    for (int i = 0; i < kMaxLights + 1; ++i)
        nineLights += QByteArray(i ? ", " : "") + R"({"position": [1, 1, 1]})";
    row("too many lights", withLights(nineLights + "]"), "lights:", "at most 8");

    // Non-finite numbers: Qt cannot produce NaN, but these overflow a double.
    row("fov overflow", withSphere(R"("camera": {"fov_deg": 1e999})"), "camera.fov_deg:", "finite");
    row("position overflow", withLights(R"([{"position": [-1e999, 0, 0]}])"),
        "lights[0].position[0]:", "1e999");
    row("translate overflow", withSphere(R"("transform": {"translate": [0, 0, 2e400]})"),
        "transform.translate[2]:", "finite");
    row("overflow where object expected", withSphere(R"("camera": 1e999)"),
        "camera:", "out-of-range number");
    row("overflow where string expected", R"({"mesh": 1e999})", "mesh:", "out-of-range number");
}

void TestSceneJson::rejectsBadInput()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, pathPrefix);
    QFETCH(QString, mentions);

    const SceneLoadResult result = parseScene(json);
    QVERIFY2(!result.ok(), "accepted bad input");
    QVERIFY2(result.error.startsWith(pathPrefix), qPrintable(result.error));
    QVERIFY2(result.error.contains(mentions), qPrintable(result.error));
}

void TestSceneJson::syntaxErrorGivesLineAndOffset()
{
    // The missing comma sits on line 3. Positions must count in the original
    // text even after the out-of-range literal before it has been rewritten,
    // so they must match those of the same text with a same-length number.
    const QByteArray json =
        "{\n  \"camera\": {\"fov_deg\": 1e999},\n  \"mesh\": \"a.obj\" \"x\": 1\n}";
    QByteArray plain = json;
    plain.replace("1e999", "45.00");
    const SceneLoadResult result = parseScene(json);
    const SceneLoadResult reference = parseScene(plain);
    QVERIFY(!result.ok());
    QVERIFY2(result.error.startsWith(QStringLiteral("JSON syntax error at line 3, column ")),
             qPrintable(result.error));
    QVERIFY2(result.error.contains(QStringLiteral("(byte offset ")), qPrintable(result.error));
    QCOMPARE(result.error, reference.error);

    // Qt points at the offending token or one byte into it.
    const qsizetype offset = json.indexOf("\"x\"");
    const qsizetype column = offset - json.lastIndexOf('\n', offset);
    QVERIFY2(
        result.error.contains(QStringLiteral("column %1 (byte offset %2)").arg(column).arg(offset))
            || result.error.contains(
                QStringLiteral("column %1 (byte offset %2)").arg(column + 1).arg(offset + 1)),
        qPrintable(result.error));
}

void TestSceneJson::underflowReadsAsZero()
{
    const SceneLoadResult result =
        parseScene(withSphere(R"("transform": {"translate": [1e-999, -1e-400, 1]})"));
    QVERIFY2(result.ok(), qPrintable(result.error));
    QCOMPARE(result.scene->objects.front().transform.translate, glm::dvec3(0.0, 0.0, 1.0));
}

void TestSceneJson::warnsAboutUnknownKeys()
{
    const SceneLoadResult result = parseScene(R"({
        "mesh": "builtin:sphere",
        "camera": {"fovy": 60},
        "lights": [{"position": [1, 1, 1]}, {"position": [2, 2, 2], "colour": [1, 0, 0]}],
        "objectz": [],
        "material": {"shine": 3}
    })");
    QVERIFY2(result.ok(), qPrintable(result.error));
    QCOMPARE(result.warnings.size(), qsizetype(4));
    QVERIFY(result.warnings.contains(QStringLiteral("camera.fovy: unknown key, ignored")));
    QVERIFY(result.warnings.contains(QStringLiteral("lights[1].colour: unknown key, ignored")));
    QVERIFY(result.warnings.contains(QStringLiteral("objectz: unknown key, ignored")));
    QVERIFY(result.warnings.contains(QStringLiteral("material.shine: unknown key, ignored")));
    // The unknown key changed nothing.
    QCOMPARE(result.scene->camera.fovDeg, Camera{}.fovDeg);

    const SceneLoadResult nested =
        parseScene(R"({"objects": [{"mesh": "a", "transform": {"rotate": [0, 90, 0]}}]})");
    QVERIFY2(nested.ok(), qPrintable(nested.error));
    QCOMPARE(nested.warnings,
             QStringList{QStringLiteral("objects[0].transform.rotate: unknown key, ignored")});
}

void TestSceneJson::warnsAboutTopLevelTransformWithObjects()
{
    const SceneLoadResult result =
        parseScene(R"({"objects": [{"mesh": "a"}], "transform": {"scale": [2, 2, 2]}})");
    QVERIFY2(result.ok(), qPrintable(result.error));
    QCOMPARE(result.warnings.size(), qsizetype(1));
    QVERIFY2(result.warnings.front().startsWith(QStringLiteral("transform:")),
             qPrintable(result.warnings.front()));
    QCOMPARE(result.scene->objects.front().transform, Transform{});
}

void TestSceneJson::loadMissingFileSaysWhyOnce()
{
    // The caller names the file ("phonglab: error: FILE: ..."), as it does
    // for every other scene error: the message itself does not, or the path
    // would be printed twice.
    const QString path = QStringLiteral("/nonexistent/phonglab/missing.json");
    const SceneLoadResult result = loadSceneFile(path);
    QVERIFY(!result.ok());
    QVERIFY2(result.error.startsWith(QStringLiteral("cannot read scene file (")),
             qPrintable(result.error));
    QVERIFY2(!result.error.contains(path), qPrintable(result.error));
}

void TestSceneJson::relativeMeshResolvesAgainstSceneFolder()
{
    const QString dir = QDir(kSceneDataDir).absolutePath();
    const SceneLoadResult result =
        loadSceneFile(kSceneDataDir + QStringLiteral("/relative_mesh.json"));
    QVERIFY2(result.ok(), qPrintable(result.error));
    const Scene &scene = *result.scene;
    QCOMPARE(scene.baseDir, dir);
    QCOMPARE(scene.objects.front().mesh, QStringLiteral("meshes/teapot.obj")); // kept as written
    QCOMPARE(scene.resolveMeshPath(scene.objects.front().mesh),
             dir + QStringLiteral("/meshes/teapot.obj"));
    QCOMPARE(scene.resolveMeshPath(QStringLiteral("builtin:torus")),
             QStringLiteral("builtin:torus"));

    // A relative path given to loadSceneFile still yields an absolute baseDir.
    const QString previous = QDir::currentPath();
    QVERIFY(QDir::setCurrent(QFileInfo(dir).absolutePath()));
    const SceneLoadResult relative =
        loadSceneFile(QFileInfo(dir).fileName() + QStringLiteral("/relative_mesh.json"));
    QDir::setCurrent(previous);
    QVERIFY2(relative.ok(), qPrintable(relative.error));
    QCOMPARE(relative.scene->baseDir, dir);
}

void TestSceneJson::saveThenLoadGivesEqualScene()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("saved.json"));
    const Result<> saved = saveSceneFile(fullScene(), path);
    QVERIFY2(saved, qPrintable(saved.error()));

    const SceneLoadResult result = loadSceneFile(path);
    QVERIFY2(result.ok(), qPrintable(result.error));
    QVERIFY(*result.scene == fullScene());
    QCOMPARE(result.scene->baseDir, QFileInfo(path).absolutePath());
    // QSaveFile renames its temporary into place: nothing else is left behind.
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden),
             QStringList{QStringLiteral("saved.json")});
}

void TestSceneJson::saveIntoMissingDirectoryFails()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString missingDir = dir.filePath(QStringLiteral("no/such/dir"));
    const QString path = missingDir + QStringLiteral("/scene.json");
    const Result<> saved = saveSceneFile(sphereScene(), path);
    QVERIFY(!saved);
    QVERIFY2(saved.error().contains(path), qPrintable(saved.error()));
    QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("no"))));
    QVERIFY(QDir(dir.path())
                .entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot)
                .isEmpty());
}

void TestSceneJson::saveRefusesInvalidSceneAndKeepsOldFile()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("scene.json"));
    const Result<> saved = saveSceneFile(sphereScene(), path);
    QVERIFY2(saved, qPrintable(saved.error()));
    QFile original(path);
    QVERIFY(original.open(QIODevice::ReadOnly));
    const QByteArray before = original.readAll();
    original.close();

    Scene broken = sphereScene();
    broken.objects.front().transform.scale.y = 0.0;
    const Result<> refused = saveSceneFile(broken, path);
    QVERIFY(!refused);
    QVERIFY2(refused.error().contains(QStringLiteral("transform.scale[1]")),
             qPrintable(refused.error()));

    Scene empty;
    const Result<> refusedEmpty = saveSceneFile(empty, path);
    QVERIFY(!refusedEmpty);
    QVERIFY2(refusedEmpty.error().contains(QStringLiteral("objects:")),
             qPrintable(refusedEmpty.error()));

    QVERIFY(original.open(QIODevice::ReadOnly));
    QCOMPARE(original.readAll(), before);
}

// docs/scene-format.md's example must stay a valid, warning-free scene.
void TestSceneJson::docExampleLoadsCleanly()
{
    QFile doc(QStringLiteral(PHONGLAB_SOURCE_DIR "/docs/scene-format.md"));
    QVERIFY2(doc.open(QIODevice::ReadOnly | QIODevice::Text), qPrintable(doc.fileName()));
    const QString text = QString::fromUtf8(doc.readAll());
    static const QRegularExpression block(QStringLiteral("```json\\n(.*?)```"),
                                          QRegularExpression::DotMatchesEverythingOption);
    auto it = block.globalMatch(text);
    int examples = 0;
    while (it.hasNext()) {
        const QString json = it.next().captured(1);
        const SceneLoadResult result = parseScene(json.toUtf8());
        QVERIFY2(result.ok(), qPrintable(result.error + QStringLiteral("\n") + json));
        QVERIFY2(result.warnings.isEmpty(), qPrintable(result.warnings.join(u'\n')));
        ++examples;
    }
    QVERIFY(examples >= 1);
}

// "detail" is written only when it is not 1, in both forms, and reads back
// exactly; a top-level "detail" next to "objects" is ignored with a warning.
void TestSceneJson::detailRoundTripsAndDefaultsAreNotWritten()
{
    const Scene scene = fullScene();
    const QJsonObject root = QJsonDocument::fromJson(sceneToJson(scene)).object();
    const QJsonArray objects = root.value(QStringLiteral("objects")).toArray();
    QVERIFY(!objects.at(0).toObject().contains(QStringLiteral("detail")));
    QCOMPARE(objects.at(1).toObject().value(QStringLiteral("detail")).toDouble(), 0.0625);

    Scene single = sphereScene();
    QVERIFY(
        !QJsonDocument::fromJson(sceneToJson(single)).object().contains(QStringLiteral("detail")));
    single.objects.front().detail = 0.1; // not a binary fraction: must still read back exactly
    const QByteArray json = sceneToJson(single);
    QCOMPARE(QJsonDocument::fromJson(json).object().value(QStringLiteral("detail")).toDouble(),
             0.1);
    const SceneLoadResult back = parseScene(json);
    QVERIFY2(back.ok(), qPrintable(back.error));
    QVERIFY2(back.warnings.isEmpty(), qPrintable(back.warnings.join(u'\n')));
    QVERIFY(*back.scene == single);

    const SceneLoadResult one = parseScene(R"({"objects": [{"mesh": "a", "detail": 1}]})");
    QVERIFY2(one.ok(), qPrintable(one.error));
    QCOMPARE(one.scene->objects.front().detail, 1.0);

    const SceneLoadResult ignored = parseScene(R"({"objects": [{"mesh": "a"}], "detail": 0.5})");
    QVERIFY2(ignored.ok(), qPrintable(ignored.error));
    QCOMPARE(ignored.scene->objects.front().detail, 1.0);
    QVERIFY(ignored.warnings.join(u'\n').contains(QStringLiteral("detail: ignored")));
}

// Before "format": 2, "flat" named the per-fragment shader now called
// "faceted": such a file keeps its look and says so; a saved scene carries
// the format, so its "flat" is flat shading once per face.
void TestSceneJson::oldFlatLoadsAsFacetedWithANote()
{
    const SceneLoadResult old = parseScene(R"({"mesh": "builtin:sphere", "shading": "flat"})");
    QVERIFY2(old.ok(), qPrintable(old.error));
    QCOMPARE(old.scene->shading, ShadingMethod::Faceted);
    QCOMPARE(old.warnings.size(), 1);
    QVERIFY2(old.warnings.front().startsWith(QStringLiteral("shading: ")),
             qPrintable(old.warnings.front()));
    QVERIFY(old.warnings.front().contains(QStringLiteral("\"faceted\"")));

    const SceneLoadResult now =
        parseScene(R"({"format": 2, "mesh": "builtin:sphere", "shading": "flat"})");
    QVERIFY2(now.ok(), qPrintable(now.error));
    QVERIFY2(now.warnings.isEmpty(), qPrintable(now.warnings.join(u'\n')));
    QCOMPARE(now.scene->shading, ShadingMethod::Flat);

    for (const ShadingMethod method : {ShadingMethod::Flat, ShadingMethod::Faceted}) {
        Scene scene = sphereScene();
        scene.shading = method;
        const QByteArray json = sceneToJson(scene);
        QCOMPARE(QJsonDocument::fromJson(json).object().value(QStringLiteral("format")).toInt(),
                 kSceneFormat);
        const SceneLoadResult back = parseScene(json);
        QVERIFY2(back.ok() && back.warnings.isEmpty(), qPrintable(back.error));
        QCOMPARE(back.scene->shading, method);
    }

    const SceneLoadResult newer = parseScene(R"({"format": 3, "mesh": "builtin:sphere"})");
    QVERIFY2(newer.ok(), qPrintable(newer.error));
    QVERIFY2(newer.warnings.join(u'\n').contains(QStringLiteral("format: 3 is newer")),
             qPrintable(newer.warnings.join(u'\n')));
}

// Desktops tell a PhongLab scene from other JSON by this line (the shared-
// MIME magic of packaging/org.phonglab.PhongLab.mime.xml looks at the first
// 4096 bytes), and reading it back is silent.
void TestSceneJson::savedScenesCarryTheGenerator()
{
    Scene scene = sphereScene();
    scene.objects.resize(8, scene.objects.front()); // a long "objects" array
    const QByteArray json = sceneToJson(scene);
    const qsizetype at =
        json.indexOf(QByteArrayLiteral("\"generator\": \"PhongLab " PHONGLAB_VERSION));
    QVERIFY2(at >= 0, json.left(400).constData());
    QVERIFY2(at < 4096, qPrintable(QStringLiteral("at byte %1").arg(at)));
    const SceneLoadResult back = parseScene(json);
    QVERIFY2(back.ok() && back.warnings.isEmpty(), qPrintable(back.warnings.join(u'\n')));
}

// "detail": "auto" in both forms, and an object's own "shading" (which
// forces the "objects" form: at the top level "shading" is the scene's).
void TestSceneJson::autoDetailAndObjectShadingRoundTrip()
{
    const SceneLoadResult single = parseScene(R"({"mesh": "builtin:sphere", "detail": "auto"})");
    QVERIFY2(single.ok(), qPrintable(single.error));
    QVERIFY(single.scene->objects.front().autoDetail);
    QCOMPARE(single.scene->objects.front().detail, 1.0);

    const SceneLoadResult many = parseScene(R"({"objects": [
        {"mesh": "builtin:sphere", "detail": "auto", "shading": "gouraud"},
        {"mesh": "builtin:torus", "detail": 0.25}], "shading": "phong"})");
    QVERIFY2(many.ok(), qPrintable(many.error));
    QVERIFY2(many.warnings.isEmpty(), qPrintable(many.warnings.join(u'\n')));
    const Scene &scene = *many.scene;
    QVERIFY(scene.objects[0].autoDetail);
    QCOMPARE(scene.objects[0].shading, std::optional(ShadingMethod::Gouraud));
    QCOMPARE(scene.shadingOf(scene.objects[0]), ShadingMethod::Gouraud);
    QVERIFY(!scene.objects[1].autoDetail);
    QCOMPARE(scene.shadingOf(scene.objects[1]), ShadingMethod::Phong);

    const SceneLoadResult back = parseScene(sceneToJson(scene));
    QVERIFY2(back.ok(), qPrintable(back.error));
    QVERIFY(*back.scene == scene);

    Scene one = scene;
    one.objects.resize(1);
    const QJsonObject root = QJsonDocument::fromJson(sceneToJson(one)).object();
    QVERIFY(root.contains(QStringLiteral("objects")));
    QVERIFY(*parseScene(sceneToJson(one)).scene == one);

    const SceneLoadResult bad = parseScene(R"({"mesh": "builtin:sphere", "detail": "half"})");
    QCOMPARE(bad.error,
             QStringLiteral("detail: expected a number in (0, 1] or \"auto\", got string"));
    const SceneLoadResult badShading =
        parseScene(R"({"objects": [{"mesh": "builtin:sphere", "shading": "toon"}]})");
    QVERIFY2(badShading.error.startsWith(QStringLiteral("objects[0].shading: unknown shading")),
             qPrintable(badShading.error));
}

QTEST_GUILESS_MAIN(TestSceneJson)
#include "tst_scenejson.moc"
