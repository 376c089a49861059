// The shipped shading methods (shaders/<name>.vert/.frag) on the GPU:
// Blinn-Phong and the normals view against their exact CPU references,
// Gouraud and faceted against the Phong reference they approximate, and the
// `--shading` option of `phonglab render`. Prints the figures it measures.
#include "PhonglabProcess.h"
#include "RenderCheck.h"
#include "ResultChecks.h"
#include "core/reference/PhongReference.h"
#include "core/scene/ShadingMethod.h"
#include "mesh/import/BuiltinMeshes.h"
#include "render/draw/OffscreenRenderer.h"
#include "render/gl/GlFormat.h"
#include "render/program/ShaderProgram.h"
#include "render/program/UniformIntrospection.h"

#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QProcess>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>

using namespace phonglab;
using namespace phonglab::test;

namespace {

// The coarse sphere of the Gouraud test: 16 slices x 8 stacks, vertices
// 22.5 degrees apart, far wider than a shininess-200 highlight (its half
// width at half maximum is about 5 degrees).
constexpr int kCoarseSlices = 16;
constexpr int kCoarseStacks = 8;
constexpr double kTightShininess = 200.0;
// The coarse outline lies up to ~6 px inside the true sphere's: compare
// outside a band that wide so the outline's error, the same for every
// method, does not drown the shading's.
constexpr int kCoarseBandPx = 8;

// How much larger Gouraud's error must be on the coarse sphere.
constexpr double kClearlyWorse = 2.0;

// Gouraud on the fine builtin sphere is close to per-fragment Phong.
constexpr double kGouraudFineMinPsnrDb = 35.0;
// Flat faces: faceted shading must reproduce Phong's picture of the box.
constexpr int kFacetedBoxMaxSteps = 1;
// Faceting of the fine sphere must show: at least this far off somewhere.
constexpr int kFacetedSphereMinMaxSteps = 10;

QSet<QByteArray> activeUniformNames(GLuint program)
{
    QSet<QByteArray> names;
    for (const ActiveUniformInfo &u :
         activeUniformsOf(QOpenGLContext::currentContext()->extraFunctions(), program))
        names.insert(u.name);
    return names;
}

QSet<QByteArray> activeAttributes(GLuint program)
{
    QOpenGLExtraFunctions *gl = QOpenGLContext::currentContext()->extraFunctions();
    GLint count = 0, maxLength = 0;
    gl->glGetProgramiv(program, GL_ACTIVE_ATTRIBUTES, &count);
    gl->glGetProgramiv(program, GL_ACTIVE_ATTRIBUTE_MAX_LENGTH, &maxLength);
    QSet<QByteArray> names;
    QByteArray name(qMax(maxLength, 1), '\0');
    for (GLint i = 0; i < count; ++i) {
        GLsizei length = 0;
        GLint size = 0;
        GLenum type = 0;
        gl->glGetActiveAttrib(program, GLuint(i), maxLength, &length, &size, &type, name.data());
        names.insert(name.left(length));
    }
    return names;
}

QString joined(const QSet<QByteArray> &set)
{
    QStringList list;
    for (const QByteArray &s : set)
        list << QString::fromLatin1(s);
    list.sort();
    return list.join(QStringLiteral(", "));
}

// A shipped shader with one line changed: the mistake under test, made in
// the very file that ships. nullopt when `from` is not in it (the shipped
// file changed and the test must follow).
std::optional<ShaderSource> mutatedShader(const QString &fileName, const QByteArray &from,
                                          const QByteArray &to)
{
    ShaderSource source = shippedShader(fileName);
    if (source.code.count(from) != 1)
        return std::nullopt;
    source.code.replace(from, to);
    source.name = QStringLiteral("mutated-") + fileName;
    return source;
}

Scene withShading(Scene scene, ShadingMethod method)
{
    scene.shading = method;
    return scene;
}

} // namespace

class TestShadingPresets : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void presetBuilds_data();
    void presetBuilds();
    void blinnPhongMatchesReference_data();
    void blinnPhongMatchesReference();
    void blinnPhongMistakesFail_data();
    void blinnPhongMistakesFail();
    void normalsMatchReference_data();
    void normalsMatchReference();
    void normalsViewShowsWrongNormalMatrix();
    void gouraudCloseToPhongOnFineSphere();
    void gouraudWorseThanPhongOnCoarseSphere();
    void facetedEqualsPhongOnBox();
    void facetedShowsFacetsOnSphere();
    void cliRendersGouraudScene();
    void cliShadingOverridesScene();
    void cliRejectsUnknownShading();

private:
    void report(const QString &name, const RenderCheck &check);
    void verifyMatches(const QString &name, const RenderCheck &check, const Scene &scene);

    QTemporaryDir m_dir;
};

void TestShadingPresets::initTestCase()
{
    QSurfaceFormat::setDefaultFormat(phonglabSurfaceFormat(0));
    QVERIFY(m_dir.isValid());
    qInfo("bounds: PSNR >= %.1f dB, max error <= %d/255, outside a %d px silhouette band, %dx%d px",
          kMinPsnrDb, kMaxErrorSteps, kSilhouetteBandPx, kTestImageSide, kTestImageSide);
}

void TestShadingPresets::report(const QString &name, const RenderCheck &check)
{
    qInfo("%-44s %s", qPrintable(name), qPrintable(check.comparison.summary()));
}

void TestShadingPresets::verifyMatches(const QString &name, const RenderCheck &check,
                                       const Scene &scene)
{
    QVERIFY2(check.error.isEmpty(), qPrintable(check.error));
    report(name, check);
    // A render that compared almost nothing proves nothing.
    QVERIFY2(check.comparison.pixelsCompared > kTestImageSide * kTestImageSide / 10,
             qPrintable(check.comparison.summary()));
    if (!check.matches())
        QFAIL(qPrintable(QStringLiteral("%1 (images in %2)")
                             .arg(check.comparison.summary(), saveArtifacts(name, check, scene))));
}

// --- Every preset builds, and reads only what phong.* reads ------------------

void TestShadingPresets::presetBuilds_data()
{
    QTest::addColumn<QString>("method");
    for (const QString &name : shadingNames())
        QTest::newRow(qPrintable(name)) << name;
}

void TestShadingPresets::presetBuilds()
{
    QFETCH(QString, method);
    OffscreenRenderer offscreen;
    QVERIFY_OK(offscreen.create());
    const BuildReport built = offscreen.renderer().loadShading(*shadingFromName(method));
    QVERIFY2(built.ok && !built.hasErrors(), qPrintable(built.errorSummary()));
    if (!built.diagnostics.empty())
        qInfo("%s: %d warning(s):\n%s", qPrintable(method), int(built.diagnostics.size()),
              qPrintable(built.errorSummary()));

    // The renderer drives every method through phong.*'s uniforms and
    // attributes. A preset that needed anything else would silently read
    // zeros, so its active uniforms must be a subset of Phong's.
    ShaderProgram phong, preset;
    QVERIFY(phong
                .build(shippedShader(QStringLiteral("phong.vert")),
                       shippedShader(QStringLiteral("phong.frag")))
                .ok);
    QVERIFY(preset
                .build(shippedShader(method + QStringLiteral(".vert")),
                       shippedShader(method + QStringLiteral(".frag")))
                .ok);
    const QSet<QByteArray> allowedUniforms = activeUniformNames(phong.id());
    const QSet<QByteArray> uniforms = activeUniformNames(preset.id());
    const QSet<QByteArray> attributes = activeAttributes(preset.id());
    qInfo("%-12s uniforms: %s; attributes: %s", qPrintable(method), qPrintable(joined(uniforms)),
          qPrintable(joined(attributes)));
    // Beyond Phong's, a preset may only declare its own tuning uniforms,
    // and those must carry a default in the source (nobody else sets them):
    // Blinn-Phong's exponentFactor starts at the matched 4.
    const QHash<QByteArray, float> ownDefaults{{"exponentFactor", float(kBlinnExponentFactor)}};
    for (const QByteArray &extra : uniforms - allowedUniforms) {
        QVERIFY2(ownDefaults.contains(extra),
                 qPrintable(QStringLiteral("uniform phong.* does not have and nobody sets: ")
                            + QString::fromLatin1(extra)));
        QOpenGLExtraFunctions *gl = QOpenGLContext::currentContext()->extraFunctions();
        GLfloat value = 0.0f;
        gl->glGetUniformfv(preset.id(), gl->glGetUniformLocation(preset.id(), extra.constData()),
                           &value);
        QCOMPARE(value, ownDefaults.value(extra));
    }
    // Flat shading alone reads the face layout's centroid (GpuMesh.h).
    const QSet<QByteArray> allowedAttributes = activeAttributes(phong.id())
        + (method == QLatin1String("flat") ? QSet<QByteArray>{"facePoint"} : QSet<QByteArray>{});
    QVERIFY2((attributes - allowedAttributes).isEmpty(),
             qPrintable(QStringLiteral("unexpected attributes: ") + joined(attributes)));
    QVERIFY2(attributes.contains("position"), "the preset does not read the vertex position");
    phong.destroy();
    preset.destroy();
}

// --- Blinn-Phong ---------------------------------------------------------------

void TestShadingPresets::blinnPhongMatchesReference_data()
{
    QTest::addColumn<QString>("scene");
    QTest::newRow("sphere, one light") << "gl_sphere_one_light";
    QTest::newRow("ellipsoid, non-uniform scale") << "gl_ellipsoid_nonuniform";
}

void TestShadingPresets::blinnPhongMatchesReference()
{
    QFETCH(QString, scene);
    const Scene s = withShading(loadTestScene(scene), ShadingMethod::BlinnPhong);
    verifyMatches(QStringLiteral("blinn-phong ") + scene, checkAgainstReference(s), s);
}

void TestShadingPresets::blinnPhongMistakesFail_data()
{
    QTest::addColumn<QString>("scene");
    QTest::addColumn<QString>("mistake");
    for (const char *scene : {"gl_sphere_one_light", "gl_ellipsoid_nonuniform"}) {
        QTest::addRow("%s, reflect-based specular", scene) << scene << "reflect";
        QTest::addRow("%s, exponent n instead of 4n", scene) << scene << "exponent";
    }
}

void TestShadingPresets::blinnPhongMistakesFail()
{
    QFETCH(QString, scene);
    QFETCH(QString, mistake);
    std::optional<ShaderSource> wrong;
    if (mistake == QLatin1String("reflect")) {
        // Phong's max(0, R.V)^n passed off as Blinn-Phong: the closest
        // look-alike, since the exponents are matched near the peak.
        wrong = shippedShader(QStringLiteral("phong.frag"));
        wrong->name = QStringLiteral("blinn-phong-with-reflect.frag");
    } else {
        // The half vector right, but max(0, N.H)^n: a highlight twice as wide.
        wrong = mutatedShader(QStringLiteral("blinn-phong.frag"),
                              "float exponent = exponentFactor * shininess;",
                              "float exponent = shininess;");
        QVERIFY2(wrong, "the shipped blinn-phong.frag no longer has the line this test changes");
    }

    const Scene s = withShading(loadTestScene(scene), ShadingMethod::BlinnPhong);
    CheckOptions options;
    options.fragment = wrong;
    const RenderCheck check = checkAgainstReference(s, options);
    QVERIFY2(check.error.isEmpty(), qPrintable(check.error));
    report(QStringLiteral("WRONG blinn-phong (%1) %2").arg(mistake, scene), check);
    QVERIFY2(check.comparison.pixelsCompared > 0, "nothing compared");
    QVERIFY2(!check.matches(),
             qPrintable(QStringLiteral("a wrong shader passed: ") + check.comparison.summary()));
}

// --- Normals view --------------------------------------------------------------

void TestShadingPresets::normalsMatchReference_data()
{
    QTest::addColumn<QString>("scene");
    QTest::newRow("sphere") << "gl_sphere_one_light";
    QTest::newRow("ellipsoid, non-uniform scale") << "gl_ellipsoid_nonuniform";
    QTest::newRow("torus") << "gl_torus";
    QTest::newRow("box, non-uniform scale") << "gl_cube";
}

void TestShadingPresets::normalsMatchReference()
{
    QFETCH(QString, scene);
    const Scene s = withShading(loadTestScene(scene), ShadingMethod::Normals);
    verifyMatches(QStringLiteral("normals ") + scene, checkAgainstReference(s), s);
}

void TestShadingPresets::normalsViewShowsWrongNormalMatrix()
{
    // What the normals view is for: normals transformed by the model-view
    // matrix instead of its inverse transpose are visibly wrong under
    // non-uniform scale, with no lighting to muddle the picture.
    const Scene s = withShading(loadTestScene(QStringLiteral("gl_ellipsoid_nonuniform")),
                                ShadingMethod::Normals);
    CheckOptions options;
    options.vertex = testShader(QStringLiteral("shaders/wrong_normal_modelview.vert"));
    const RenderCheck check = checkAgainstReference(s, options);
    QVERIFY2(check.error.isEmpty(), qPrintable(check.error));
    report(QStringLiteral("WRONG normals, model-view normal matrix"), check);
    QVERIFY2(!check.matches(), qPrintable(check.comparison.summary()));
}

// --- Gouraud -------------------------------------------------------------------

void TestShadingPresets::gouraudCloseToPhongOnFineSphere()
{
    // builtin:sphere is 256 slices x 128 stacks: vertices ~1.4 degrees apart,
    // finer than the shininess-32 highlight, so interpolating colours loses
    // little. Measured against the exact per-pixel Phong reference.
    const Scene s =
        withShading(loadTestScene(QStringLiteral("gl_sphere_one_light")), ShadingMethod::Gouraud);
    const RenderCheck gouraud = checkAgainstReference(s);
    QVERIFY2(gouraud.error.isEmpty(), qPrintable(gouraud.error));
    report(QStringLiteral("gouraud, fine sphere vs Phong reference"), gouraud);
    QVERIFY(gouraud.comparison.pixelsCompared > kTestImageSide * kTestImageSide / 10);
    QVERIFY2(gouraud.comparison.psnr >= kGouraudFineMinPsnrDb,
             qPrintable(QStringLiteral("%1, want PSNR >= %2 dB (images in %3)")
                            .arg(gouraud.comparison.summary())
                            .arg(kGouraudFineMinPsnrDb)
                            .arg(saveArtifacts(QStringLiteral("gouraud-fine"), gouraud, s))));
}

void TestShadingPresets::gouraudWorseThanPhongOnCoarseSphere()
{
    // A tight highlight on a coarse sphere: per vertex, the highlight is
    // sampled only where a vertex happens to lie, so Gouraud smears or
    // misses it; per fragment, Phong finds it between the vertices.
    Scene s = loadTestScene(QStringLiteral("gl_sphere_one_light"));
    s.objects.front().material.shininess = kTightShininess;
    CheckOptions options;
    options.meshOverride =
        std::make_shared<const MeshData>(makeUvSphere(kCoarseSlices, kCoarseStacks));
    options.reference = ReferenceShading::Phong;

    const RenderCheck phong = checkAgainstReference(withShading(s, ShadingMethod::Phong), options);
    const RenderCheck gouraud =
        checkAgainstReference(withShading(s, ShadingMethod::Gouraud), options);
    QVERIFY2(phong.error.isEmpty(), qPrintable(phong.error));
    QVERIFY2(gouraud.error.isEmpty(), qPrintable(gouraud.error));
    // Both against the same exact-sphere Phong reference, outside a band
    // wide enough for the coarse outline.
    const ImageComparison phongError =
        compareWithReference(phong.gpu, phong.referenceData, kCoarseBandPx);
    const ImageComparison gouraudError =
        compareWithReference(gouraud.gpu, gouraud.referenceData, kCoarseBandPx);
    qInfo("coarse sphere %dx%d, n = %g, %d px band, vs the Phong reference:", kCoarseSlices,
          kCoarseStacks, kTightShininess, kCoarseBandPx);
    qInfo("  phong   %s", qPrintable(phongError.summary()));
    qInfo("  gouraud %s", qPrintable(gouraudError.summary()));
    QVERIFY(phongError.pixelsCompared > kTestImageSide * kTestImageSide / 10);
    QCOMPARE(gouraudError.pixelsCompared, phongError.pixelsCompared);
    // "Clearly": at least twice Phong's error, overall and inside the
    // highlight alone (where the reference's specular term is visible). The
    // factor pins the direction with room to spare, not this machine's number.
    QVERIFY2(gouraudError.rmse > kClearlyWorse * phongError.rmse,
             qPrintable(QStringLiteral("Gouraud RMSE %1 is not clearly above Phong's %2")
                            .arg(gouraudError.rmse)
                            .arg(phongError.rmse)));
    std::vector<std::uint8_t> highlight(phong.referenceData.color.size(), 0);
    for (std::size_t i = 0; i < highlight.size(); ++i) {
        const glm::dvec3 &sp = phong.referenceData.specular[i];
        highlight[i] = std::max({sp.r, sp.g, sp.b}) >= 4.0 / 255.0;
    }
    const glm::dvec3 bg = s.background;
    const ImageComparison phongHighlight =
        compareOutsideBand(phong.gpu, phong.referenceData, bg, kCoarseBandPx, &highlight).error;
    const ImageComparison gouraudHighlight =
        compareOutsideBand(gouraud.gpu, gouraud.referenceData, bg, kCoarseBandPx, &highlight).error;
    qInfo("  inside the highlight: phong %s", qPrintable(phongHighlight.summary()));
    qInfo("  inside the highlight: gouraud %s", qPrintable(gouraudHighlight.summary()));
    QVERIFY(phongHighlight.pixelsCompared > 100);
    QVERIFY2(gouraudHighlight.rmse > kClearlyWorse * phongHighlight.rmse,
             qPrintable(QStringLiteral(
                            "inside the highlight, Gouraud RMSE %1 is not clearly above Phong's %2")
                            .arg(gouraudHighlight.rmse)
                            .arg(phongHighlight.rmse)));
}

// --- Faceted --------------------------------------------------------------------

void TestShadingPresets::facetedEqualsPhongOnBox()
{
    // The box's vertex normals ARE its face normals, so faceted shading (face
    // normal from screen-space derivatives) must draw what Phong draws.
    const Scene s = loadTestScene(QStringLiteral("gl_cube"));
    const RenderCheck phong = checkAgainstReference(withShading(s, ShadingMethod::Phong));
    const RenderCheck flat = checkAgainstReference(withShading(s, ShadingMethod::Faceted));
    QVERIFY2(phong.error.isEmpty(), qPrintable(phong.error));
    QVERIFY2(flat.error.isEmpty(), qPrintable(flat.error));
    const ImageComparison diff = compareImages(flat.gpu, phong.gpu);
    qInfo("faceted vs Phong render, box: %s", qPrintable(diff.summary()));
    report(QStringLiteral("faceted, box vs Phong reference"), flat);
    QCOMPARE(diff.pixelsCompared, qint64(kTestImageSide) * kTestImageSide);
    QVERIFY2(diff.maxError <= kFacetedBoxMaxSteps, qPrintable(diff.summary()));
    QVERIFY2(flat.matches(), qPrintable(flat.comparison.summary()));
}

void TestShadingPresets::facetedShowsFacetsOnSphere()
{
    // On the sphere the face normal is not the vertex normals' smooth
    // interpolation: every facet is lit as one plane.
    const Scene s = loadTestScene(QStringLiteral("gl_sphere_one_light"));
    const RenderCheck phong = checkAgainstReference(withShading(s, ShadingMethod::Phong));
    const RenderCheck flat = checkAgainstReference(withShading(s, ShadingMethod::Faceted));
    QVERIFY2(phong.error.isEmpty(), qPrintable(phong.error));
    QVERIFY2(flat.error.isEmpty(), qPrintable(flat.error));
    const ImageComparison diff = compareImages(flat.gpu, phong.gpu);
    qInfo("faceted vs Phong render, fine sphere: %s", qPrintable(diff.summary()));
    report(QStringLiteral("faceted, fine sphere vs Phong reference"), flat);
    QVERIFY2(diff.maxError >= kFacetedSphereMinMaxSteps, qPrintable(diff.summary()));
    QVERIFY2(!flat.matches(), qPrintable(flat.comparison.summary()));
}

// --- phonglab render --shading ---------------------------------------------------

void TestShadingPresets::cliRendersGouraudScene()
{
    QVERIFY2(QFileInfo(phonglabExecutable()).isExecutable(),
             qPrintable(phonglabExecutable()
                        + QStringLiteral(": not built (build the phonglab target)")));
    QFile in(QStringLiteral(PHONGLAB_TEST_DATA_DIR "/scenes/gl_sphere_one_light.json"));
    QVERIFY(in.open(QIODevice::ReadOnly));
    QJsonObject root = QJsonDocument::fromJson(in.readAll()).object();
    root.insert(QStringLiteral("shading"), QStringLiteral("gouraud"));
    const QString scenePath = m_dir.filePath(QStringLiteral("gouraud.json"));
    QFile out(scenePath);
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(QJsonDocument(root).toJson());
    out.close();

    const QString png = m_dir.filePath(QStringLiteral("gouraud.png"));
    const ProcessRun r = runPhonglab({QStringLiteral("render"), scenePath, QStringLiteral("-o"),
                                      png, QStringLiteral("--size"), QStringLiteral("96x64")});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QCOMPARE(QImage(png).size(), QSize(96, 64));
}

void TestShadingPresets::cliShadingOverridesScene()
{
    QVERIFY2(QFileInfo(phonglabExecutable()).isExecutable(), qPrintable(phonglabExecutable()));
    // A Phong scene rendered as the normals view: the sphere's centre faces
    // the camera, so it must come out as N = (0, 0, 1) -> (128, 128, 255).
    const QString png = m_dir.filePath(QStringLiteral("normals.png"));
    const ProcessRun r =
        runPhonglab({QStringLiteral("render"),
                     QStringLiteral(PHONGLAB_TEST_DATA_DIR "/scenes/gl_sphere_one_light.json"),
                     QStringLiteral("-o"), png, QStringLiteral("--size"), QStringLiteral("65x65"),
                     QStringLiteral("--shading"), QStringLiteral("normals")});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const QColor centre = QImage(png).pixelColor(32, 32);
    qInfo("--shading normals, centre pixel: (%d, %d, %d)", centre.red(), centre.green(),
          centre.blue());
    QVERIFY(qAbs(centre.red() - 128) <= 1);
    QVERIFY(qAbs(centre.green() - 128) <= 1);
    QVERIFY(centre.blue() >= 254);
}

void TestShadingPresets::cliRejectsUnknownShading()
{
    QVERIFY2(QFileInfo(phonglabExecutable()).isExecutable(), qPrintable(phonglabExecutable()));
    const QString png = m_dir.filePath(QStringLiteral("nosuch.png"));
    const ProcessRun r = runPhonglab(
        {QStringLiteral("render"),
         QStringLiteral(PHONGLAB_TEST_DATA_DIR "/scenes/gl_sphere_one_light.json"),
         QStringLiteral("-o"), png, QStringLiteral("--shading"), QStringLiteral("nosuch")});
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains(QStringLiteral("nosuch")), qPrintable(r.err));
    for (const QString &name : shadingNames())
        QVERIFY2(r.err.contains(name), qPrintable(r.err)); // the message lists the known methods
    QVERIFY(!QFileInfo::exists(png));
}

QTEST_MAIN(TestShadingPresets)
#include "tst_shadingpresets.moc"
