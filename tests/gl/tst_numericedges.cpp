// The numeric edge sweep: every shipped shading method at the values where
// the equation or its arithmetic is on the edge (pow at 0, a light on or
// inside the surface, no constant attenuation, tiny and huge scales, the
// eye inside, extreme fields of view, broken normals in a file). Rendered
// into a float target so a NaN or an infinity is seen instead of clamped
// away. Each case: no non-finite pixel ever; within the reference's bounds
// where the equation defines the answer (Phong, Blinn-Phong, normals; Gouraud
// and flat approximate it, so for them only finiteness is asserted and the
// distance is reported); otherwise a refusal at load or the documented
// behaviour. PHONGLAB_SWEEP_TABLE=FILE writes the results as a Markdown table
// (docs/reliability.md).
#include "RenderCheck.h"
#include "TestPaths.h"
#include "core/reference/PhongReference.h"
#include "core/scene/SceneJson.h"
#include "mesh/loading/MeshLoader.h"
#include "render/gl/GlFormat.h"

#include <QFile>
#include <QGuiApplication>
#include <QTemporaryDir>
#include <QTest>

#include <functional>

using namespace phonglab;
using namespace phonglab::test;

namespace {

// What a case promises when the equation defines the pixels.
enum class Expect {
    Reference, // within the reference's bounds (exact methods), finite (all)
    // As Reference, away from the steps the equation itself has: with a
    // small n the specular term jumps from ~ks·Is to 0 where N·L or R·V
    // reaches 0, and a pixel on the step may fall either side.
    ReferenceOffSteps,
    Background, // the documented outcome: nothing drawn (eye inside a closed object)
    Finite,     // nothing to compare (the object projects below a pixel): finite only
};

struct EdgeCase {
    const char *name;
    std::function<void(Scene &)> change;
    Expect expect = Expect::Reference;
};

constexpr ShadingMethod kMethods[] = {ShadingMethod::Phong,   ShadingMethod::BlinnPhong,
                                      ShadingMethod::Gouraud, ShadingMethod::Flat,
                                      ShadingMethod::Faceted, ShadingMethod::Normals};

bool exactMethod(ShadingMethod m)
{
    return m == ShadingMethod::Phong || m == ShadingMethod::BlinnPhong
        || m == ShadingMethod::Normals;
}

// Camera, lights and objects all scaled by s about the origin: the same
// picture (attenuation is off in the base scene) at other magnitudes.
void scaleWorld(Scene &s, double factor)
{
    for (SceneObject &o : s.objects) {
        o.transform.scale *= factor;
        o.transform.translate *= factor;
    }
    for (PointLight &l : s.lights)
        l.position *= factor;
    s.camera.eye *= factor;
    s.camera.target *= factor;
    s.camera.nearPlane *= factor;
    s.camera.farPlane *= factor;
}

const std::vector<EdgeCase> &edgeCases()
{
    static const std::vector<EdgeCase> cases = {
        {"shininess 1e-3", [](Scene &s) { s.objects[0].material.shininess = 1e-3; },
         Expect::ReferenceOffSteps},
        {"shininess 1", [](Scene &s) { s.objects[0].material.shininess = 1.0; },
         Expect::ReferenceOffSteps},
        {"shininess 1e4", [](Scene &s) { s.objects[0].material.shininess = 1e4; }},
        {"light on the surface",
         [](Scene &s) {
             s.lights[0].position = {0.0, 0.0, 1.0};
         }},
        {"light inside the object",
         [](Scene &s) {
             s.lights[0].position = {0.1, 0.2, 0.0};
         }},
        {"attenuation c1 = c2 = 0",
         [](Scene &s) {
             s.lights[0].attenuation = {0.0, 0.0, 0.04};
         }},
        {"attenuation c1 = c2 = 0, light on the surface",
         [](Scene &s) {
             s.lights[0].attenuation = {0.0, 0.0, 1.0};
             s.lights[0].position = {0.0, 0.0, 1.0};
         }},
        {"object scale 1e-6 (world scaled with it)", [](Scene &s) { scaleWorld(s, 1e-6); }},
        {"object scale 1e6 (world scaled with it)", [](Scene &s) { scaleWorld(s, 1e6); }},
        {"fov 0.01 deg", [](Scene &s) { s.camera.fovDeg = 0.01; }},
        {"fov 179.9 deg", [](Scene &s) { s.camera.fovDeg = 179.9; }, Expect::Finite},
        {"fov 179 deg, eye 0.02 above the surface",
         [](Scene &s) {
             s.camera.fovDeg = 179.0;
             s.camera.eye = {0.0, 0.0, 1.02};
             s.camera.nearPlane = 1e-3;
         }},
        {"near 1e-6, far 1e9",
         [](Scene &s) {
             s.camera.nearPlane = 1e-6;
             s.camera.farPlane = 1e9;
         }},
        {"eye inside the object",
         [](Scene &s) {
             s.camera.eye = {0.0, 0.0, 0.3};
             s.camera.nearPlane = 1e-3;
         },
         Expect::Background},
    };
    return cases;
}

// Pixels next to a jump of the reference's specular term between two
// neighbours (over 0.02 summed over R, G, B: a broad highlight changes far
// less from one pixel to the next): the equation's own steps.
std::vector<std::uint8_t> offSteps(const ReferenceImage &ref)
{
    std::vector<std::uint8_t> keep(ref.coverage.size(), 1);
    const auto value = [&](int x, int y) {
        const glm::dvec3 &v = ref.specular[std::size_t(ref.index(x, y))];
        return v.r + v.g + v.b;
    };
    for (int y = 0; y + 1 < ref.height; ++y)
        for (int x = 0; x + 1 < ref.width; ++x) {
            const double here = value(x, y);
            if (std::abs(here - value(x + 1, y)) > 0.02 || std::abs(here - value(x, y + 1)) > 0.02)
                for (int dy = -1; dy <= 2; ++dy)
                    for (int dx = -1; dx <= 2; ++dx)
                        if (x + dx >= 0 && y + dy >= 0 && x + dx < ref.width && y + dy < ref.height)
                            keep[std::size_t(ref.index(x + dx, y + dy))] = 0;
        }
    return keep;
}

struct SweepRow {
    QString edgeCase;
    QString method;
    qint64 nonFinite = 0;
    QString result;
};

} // namespace

class TestNumericEdges : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void sweep_data();
    void sweep();
    void brokenNormalsInAFile_data();
    void brokenNormalsInAFile();
    void refusedAtLoad_data();
    void refusedAtLoad();
    void wrongShaderNaNIsSeen();

private:
    void record(const QString &edgeCase, const QString &method, qint64 nonFinite,
                const QString &result);
    std::vector<SweepRow> m_rows;
    QTemporaryDir m_dir;
};

void TestNumericEdges::initTestCase()
{
    QSurfaceFormat::setDefaultFormat(phonglabSurfaceFormat(0));
    QVERIFY(m_dir.isValid());
}

void TestNumericEdges::record(const QString &edgeCase, const QString &method, qint64 nonFinite,
                              const QString &result)
{
    qInfo("%-46s %-12s non-finite %lld  %s", qPrintable(edgeCase), qPrintable(method), nonFinite,
          qPrintable(result));
    m_rows.push_back({edgeCase, method, nonFinite, result});
}

void TestNumericEdges::cleanupTestCase()
{
    const QString path = qEnvironmentVariable("PHONGLAB_SWEEP_TABLE");
    if (path.isEmpty())
        return;
    QFile out(path);
    QVERIFY(out.open(QIODevice::WriteOnly | QIODevice::Text));
    out.write("| case | method | NaN/Inf pixels | result |\n|---|---|---:|---|\n");
    for (const SweepRow &r : m_rows)
        out.write(QStringLiteral("| %1 | %2 | %3 | %4 |\n")
                      .arg(r.edgeCase, r.method)
                      .arg(r.nonFinite)
                      .arg(r.result)
                      .toUtf8());
}

void TestNumericEdges::sweep_data()
{
    QTest::addColumn<int>("caseIndex");
    QTest::addColumn<int>("method");
    for (int c = 0; c < int(edgeCases().size()); ++c)
        for (ShadingMethod m : kMethods)
            QTest::addRow("%s, %s", edgeCases()[c].name, qPrintable(shadingName(m))) << c << int(m);
}

void TestNumericEdges::sweep()
{
    QFETCH(int, caseIndex);
    QFETCH(int, method);
    const EdgeCase &edge = edgeCases()[std::size_t(caseIndex)];
    Scene scene = loadTestScene(QStringLiteral("gl_sphere_one_light"));
    scene.shading = ShadingMethod(method);
    edge.change(scene);
    CheckOptions options;
    options.floatTarget = true;
    RenderCheck check = checkAgainstReference(scene, options);
    QVERIFY2(check.error.isEmpty(), qPrintable(check.error));
    const QString name = QString::fromLatin1(edge.name);
    if (edge.expect == Expect::ReferenceOffSteps) {
        const std::vector<std::uint8_t> keep = offSteps(check.referenceData);
        check.comparison = compareOutsideBand(check.gpu, check.referenceData, scene.background,
                                              kSilhouetteBandPx, &keep)
                               .error;
    }
    if (edge.expect == Expect::Finite) {
        record(name, shadingName(scene.shading), check.nonFinitePixels,
               QStringLiteral("finite; the sphere projects below a pixel (%1 px compared)")
                   .arg(check.comparison.pixelsCompared));
        QCOMPARE(check.nonFinitePixels, 0);
        return;
    }
    const QString methodName = shadingName(scene.shading);

    if (edge.expect == Expect::Background) {
        // The back faces of a closed surface are culled, so from inside it
        // nothing of it is drawn: the view shows what lies beyond.
        RgbImage background(check.gpu.width, check.gpu.height);
        background.fill(uchar(encodeChannel(scene.background.r)),
                        uchar(encodeChannel(scene.background.g)),
                        uchar(encodeChannel(scene.background.b)));
        const int differing = compareImages(check.gpu, background).maxError;
        record(name, methodName, check.nonFinitePixels,
               differing <= 1
                   ? QStringLiteral("background only (closed surface seen from inside is culled)")
                   : QStringLiteral("drawn: max %1/255 from the background").arg(differing));
        QCOMPARE(check.nonFinitePixels, 0);
        QVERIFY(differing <= 1);
        return;
    }
    const bool exact = exactMethod(scene.shading);
    const bool within = check.matches();
    record(name, methodName, check.nonFinitePixels,
           QStringLiteral("%1%2: %3")
               .arg(exact ? (within ? QStringLiteral("within bounds")
                                    : QStringLiteral("OUT OF BOUNDS"))
                          : QStringLiteral("approximation"),
                    edge.expect == Expect::ReferenceOffSteps
                        ? QStringLiteral(" off the specular steps")
                        : QString(),
                    check.comparison.summary()));
    QCOMPARE(check.nonFinitePixels, 0);
    QVERIFY2(check.comparison.pixelsCompared > 0, "the case drew nothing to compare");
    if (exact && !within)
        QFAIL(qPrintable(
            QStringLiteral("%1 (images in %2)")
                .arg(check.comparison.summary(),
                     saveArtifacts(name + QLatin1Char('-') + methodName, check, scene))));
}

void TestNumericEdges::brokenNormalsInAFile_data()
{
    QTest::addColumn<int>("method");
    for (ShadingMethod m : kMethods)
        QTest::addRow("%s", qPrintable(shadingName(m))) << int(m);
}

void TestNumericEdges::brokenNormalsInAFile()
{
    // An octahedron whose file normals are zero, NaN and infinite at some
    // corners, plus a zero-area triangle: the importer replaces what cannot
    // be a direction and drops the degenerate face, each with a warning.
    QFETCH(int, method);
    const QString path = m_dir.filePath(QStringLiteral("broken_normals.obj"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n"
               "vn 0 0 0\nvn nan nan nan\nvn inf 0 0\nvn 0.577 0.577 0.577\n"
               "f 1//4 3//1 5//2\nf 3//3 2//1 5//2\nf 2//1 4//1 5//1\nf 4//2 1//3 5//4\n"
               "f 3//1 1//2 6//3\nf 2//1 3//2 6//1\nf 4//4 2//1 6//2\nf 1//1 4//1 6//1\n"
               "f 1//1 1//1 5//1\n");
    file.close();
    const MeshLoadResult loaded = loadMesh(path);
    QVERIFY2(loaded.ok(), qPrintable(loaded.error));
    const QString warnings = loaded.warnings.join(QLatin1Char('\n'));
    QVERIFY2(warnings.contains(QLatin1String("normal")), qPrintable(warnings));

    Scene scene = loadTestScene(QStringLiteral("gl_sphere_one_light"));
    scene.shading = ShadingMethod(method);
    scene.objects[0].mesh = path;
    CheckOptions options;
    options.floatTarget = true;
    // The reference is the analytic box only as far as coverage goes; what
    // is asserted here is that every pixel is finite.
    options.standIns.insert(path, QStringLiteral("builtin:sphere"));
    const RenderCheck check = checkAgainstReference(scene, options);
    QVERIFY2(check.error.isEmpty(), qPrintable(check.error));
    record(QStringLiteral("zero, NaN and infinite normals and a zero-area face in a file"),
           shadingName(scene.shading), check.nonFinitePixels,
           QStringLiteral("loads with %1 warning(s); replaced normals computed")
               .arg(loaded.warnings.size()));
    QCOMPARE(check.nonFinitePixels, 0);
}

void TestNumericEdges::refusedAtLoad_data()
{
    QTest::addColumn<QByteArray>("camera");
    QTest::addColumn<QByteArray>("material");
    QTest::addColumn<QByteArray>("attenuation");
    QTest::addColumn<QString>("expected");
    const QByteArray camera =
        R"("eye": [0, 0, 4], "target": [0, 0, 0], "up": [0, 1, 0], "fov_deg": 45, "near": 0.1, "far": 100)";
    const QByteArray material = R"("shininess": 32)";
    const QByteArray attenuation = "[1, 0, 0]";
    QTest::newRow("eye on the target")
        << QByteArray(R"("eye": [1, 2, 3], "target": [1, 2, 3])") << material << attenuation
        << "camera.target: must differ from eye";
    QTest::newRow("up parallel to the view")
        << QByteArray(R"("eye": [0, 0, 4], "target": [0, 0, 0], "up": [0, 0, 2])") << material
        << attenuation << "camera.up: must not be parallel";
    QTest::newRow("fov 0") << QByteArray(R"("fov_deg": 0)") << material << attenuation
                           << "camera.fov_deg: must be in (0, 180)";
    QTest::newRow("fov 180") << QByteArray(R"("fov_deg": 180)") << material << attenuation
                             << "camera.fov_deg: must be in (0, 180)";
    QTest::newRow("near 0") << QByteArray(R"("near": 0)") << material << attenuation
                            << "camera.near: must be > 0";
    QTest::newRow("far at near") << QByteArray(R"("near": 1, "far": 1)") << material << attenuation
                                 << "camera.far: must be greater";
    QTest::newRow("shininess 0") << camera << QByteArray(R"("shininess": 0)") << attenuation
                                 << "material.shininess: must be > 0";
    QTest::newRow("attenuation all zero") << camera << material << QByteArray("[0, 0, 0]")
                                          << "lights[0].attenuation: c1 + c2 + c3 must be positive";
    QTest::newRow("near 1e400") << QByteArray(R"("near": 1e400)") << material << attenuation
                                << "camera.near: must be a finite number";
}

void TestNumericEdges::refusedAtLoad()
{
    QFETCH(QByteArray, camera);
    QFETCH(QByteArray, material);
    QFETCH(QByteArray, attenuation);
    QFETCH(QString, expected);
    const QByteArray json = R"({"mesh": "builtin:sphere", "camera": {)" + camera
        + R"(}, "material": {)" + material
        + R"(}, "lights": [{"position": [3, 3, 4], "attenuation": )" + attenuation + "}]}";
    const SceneLoadResult loaded = parseScene(json);
    QVERIFY(!loaded.ok());
    record(QString::fromLatin1(QTest::currentDataTag()), QStringLiteral("(all)"), 0,
           QStringLiteral("refused at load: %1").arg(loaded.error));
    QVERIFY2(loaded.error.contains(expected), qPrintable(loaded.error));
}

void TestNumericEdges::wrongShaderNaNIsSeen()
{
    // The sweep's first assertion must be able to fail: a specular factor
    // taken through sqrt(R·V − 1) is NaN everywhere but the highlight's
    // centre. (A NaN fed to pow() would not do: llvmpipe's exp2 clamps its
    // argument.) An 8-bit target shows those pixels as some colour; the
    // float target counts them.
    ShaderSource fragment = shippedShader(QStringLiteral("phong.frag"));
    const QByteArray power = "pow(RdotV, shininess)";
    QVERIFY2(fragment.code.contains(power), "phong.frag no longer reads as this test expects");
    fragment.code.replace(power, "sqrt(RdotV - 1.0)");
    Scene scene = loadTestScene(QStringLiteral("gl_sphere_one_light"));
    CheckOptions options;
    options.fragment = fragment;
    options.floatTarget = true;
    const RenderCheck check = checkAgainstReference(scene, options);
    QVERIFY2(check.error.isEmpty(), qPrintable(check.error));
    qInfo("wrong shader (sqrt(R.V - 1)): %lld NaN/Inf pixels", check.nonFinitePixels);
    QVERIFY(check.nonFinitePixels > 100);
}

QTEST_MAIN(TestNumericEdges)
#include "tst_numericedges.moc"
