// The editor's check, end to end in the real window: the shipped shader gets
// ✓; a reflect(L, N) typed into it gets ✗ with reflect-incident, and an
// error heatmap that is non-zero where that mistake shows and zero elsewhere;
// the overlay draws it; Ctrl+click inspects a pixel; undoing the mistake
// brings ✓ back. Every shipped scene gets ✓ with the shipped shaders, at two
// window sizes, with the view multisampled as the app's is.
#include "ResultChecks.h"
#include "TestPaths.h"
#include "UiTestWindow.h"
#include "core/check/MistakeSets.h"
#include "core/check/ShaderCheck.h"
#include "core/project/ProjectPrograms.h"
#include "render/gl/QtImages.h"
#include "ui/check/CheckOverlay.h"
#include "ui/check/CheckRunner.h"
#include "ui/check/LiveCheck.h"
#include "ui/check/PixelInspectorDock.h"
#include "ui/shaders/ShaderDock.h"
#include "ui/shaders/ShaderEditor.h"
#include "ui/viewport/Viewport.h"
#include "ui/window/GuiArguments.h"
#include "ui/window/GuiMain.h"
#include "ui/window/MainWindow.h"
#include "ui/window/SceneDocument.h"

#include <QApplication>
#include <QClipboard>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QPushButton>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

using namespace phonglab;
using namespace phonglab::test;

namespace {

constexpr int kCheckTimeoutMs = 30000;
constexpr int kTolerance = kDefaultCheckToleranceSteps;

int maxChannelDifference(QRgb a, QRgb b)
{
    return std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)),
                     std::abs(qBlue(a) - qBlue(b))});
}

} // namespace

class TestLiveCheck : public QObject, public UiTestWindow
{
    Q_OBJECT

private slots:
    void initTestCase() { m_env.isolate(); }
    void cleanup() { m_window.reset(); }

    void wrongShaderGetsCrossAndHeatmap()
    {
        openWindow(sourcePath(QStringLiteral("assets/scenes/check.json")), {900, 600});
        QVERIFY(!QTest::currentTestFailed());
        LiveCheck *check = m_window->liveCheck();
        QVERIFY(waitForVerdict(true));
        QVERIFY2(check->statusLabel()->verdict().startsWith(QStringLiteral("✓")),
                 qPrintable(check->statusLabel()->verdict()));

        replaceInFragment(QStringLiteral("reflect(-L, N)"), QStringLiteral("reflect(L, N)"));
        QVERIFY(waitForVerdict(false));
        const CheckedFrame &result = *check->lastResult();
        const QString status = check->statusLabel()->verdict();
        QVERIFY2(status.startsWith(QStringLiteral("✗"))
                     && status.contains(QStringLiteral("reflect-incident")),
                 qPrintable(status));
        QCOMPARE(result.report().diagnosis.findings.front().key, ShaderMistake::ReflectIncident);

        // Where the mistake shows (its image off the exact one by more than
        // the tolerance) the heatmap is red-to-yellow, elsewhere dark green.
        const CheckReference &reference = *result.reference;
        const QImage mistaken = toQImage(
            std::find_if(reference.mistaken.begin(), reference.mistaken.end(), [](const auto &p) {
                return p.first == MistakeVariant{ShaderMistake::ReflectIncident};
            })->second);
        const std::vector<int> errors = checkErrorSteps(toRgbImage(result.yours), reference);
        qint64 shows = 0, showsAndOff = 0, hidden = 0, hiddenAndExact = 0;
        for (int y = 0; y < result.exact.height(); ++y) {
            for (int x = 0; x < result.exact.width(); ++x) {
                const int error = errors[reference.exact.index(x, y)];
                if (error < 0)
                    continue;
                const bool mistakeShows =
                    maxChannelDifference(mistaken.pixel(x, y), result.exact.pixel(x, y))
                    > kTolerance;
                const QRgb heat = result.heatmap.pixel(x, y);
                if (mistakeShows) {
                    ++shows;
                    showsAndOff += error > kTolerance && qRed(heat) >= 128;
                } else {
                    ++hidden;
                    hiddenAndExact += error <= kTolerance && qRed(heat) < 128;
                }
            }
        }
        QVERIFY2(shows > 1000 && hidden > 1000,
                 qPrintable(QStringLiteral("%1 %2").arg(shows).arg(hidden)));
        QVERIFY2(showsAndOff >= 0.97 * shows,
                 qPrintable(QStringLiteral("%1 of %2").arg(showsAndOff).arg(shows)));
        QVERIFY2(hiddenAndExact >= 0.995 * hidden,
                 qPrintable(QStringLiteral("%1 of %2").arg(hiddenAndExact).arg(hidden)));

        // The overlay draws that heatmap over the view.
        check->setOverlayMode(OverlayMode::Heatmap);
        QVERIFY(check->overlay()->isVisible());
        const QImage overlay = check->overlay()->grab().toImage();
        const QPoint worst = result.report().comparison.worstPixel;
        if (overlay.size() == result.heatmap.size())
            QCOMPARE(overlay.pixel(worst), result.heatmap.pixel(worst));
        // ... into the frame the view presents (drawn over it in GL), and
        // only while it is on.
        QCOMPARE(frame().size(), result.heatmap.size());
        QCOMPARE(frame().pixel(worst), result.heatmap.pixel(worst));
        check->setOverlayMode(OverlayMode::Split);
        check->setOverlayMode(OverlayMode::Off);
        QVERIFY(!check->overlay()->isVisible());
        QVERIFY(frame().pixel(worst) != result.heatmap.pixel(worst));

        // Ctrl+click on the ellipsoid: the exact terms there, copyable.
        const QPoint centre = m_window->viewport()->rect().center() + QPoint(10, 10);
        QTest::mouseClick(m_window->viewport(), Qt::LeftButton, Qt::ControlModifier, centre);
        QTRY_VERIFY_WITH_TIMEOUT(check->inspector()->text().contains(QStringLiteral("f_att")),
                                 kCheckTimeoutMs);
        QVERIFY(check->inspector()->text().contains(QStringLiteral("N·L")));
        // The lights as the Lights dock numbers them, from 1; and
        // the inspector in front, not a tab behind another dock.
        QVERIFY(check->inspector()->text().contains(QStringLiteral("\nlight 1\n")));
        QVERIFY(!check->inspector()->text().contains(QStringLiteral("light 0")));
        QVERIFY(!check->inspector()->visibleRegion().isEmpty());
        QVERIFY(check->overlay()->hasArrows());
        auto *copy = check->inspector()->findChild<QPushButton *>();
        QVERIFY(copy && copy->isEnabled());
        copy->click();
        QCOMPARE(QApplication::clipboard()->text(), check->inspector()->text());

        // Undo the mistake: ✓ again.
        replaceInFragment(QStringLiteral("reflect(L, N)"), QStringLiteral("reflect(-L, N)"));
        QVERIFY(waitForVerdict(true));
        QVERIFY(check->statusLabel()->verdict().startsWith(QStringLiteral("✓")));

        // The headlight changes the frame, not the scene: checked again, with it.
        const quint64 before = check->lastResult()->generation;
        const std::size_t lights = check->lastResult()->scene.lights.size();
        m_window->viewport()->drawing().setHeadlight(true);
        QVERIFY(QTest::qWaitFor(
            [&] {
                return !check->isChecking() && check->lastResult()->generation > before
                    && check->lastResult()->scene.lights.size() == lights + 1;
            },
            kCheckTimeoutMs));
        QVERIFY(check->lastResult()->report().passed());
    }

    // The slide's equation taken literally (no N·L guard on
    // the highlight) is right too; the window says which it matched, and its
    // pictures are of that equation: the heatmap shows no error.
    // The first check of a view makes its exact image: the status says how
    // far it is ("checking… 40 %"), and the check runs niced, never idle.
    void aNewViewSaysHowFarItsCheckIs()
    {
        openWindow(sourcePath(QStringLiteral("assets/scenes/check.json")), {900, 600});
        QVERIFY(!QTest::currentTestFailed());
        LiveCheck *check = m_window->liveCheck();
        QVERIFY(waitForVerdict(true));
        auto *runner = check->findChild<CheckRunner *>();
        QVERIFY(runner);
        QStringList seen;
        connect(runner, &CheckRunner::progressed, this,
                [&] { seen << check->statusLabel()->verdict(); });
        m_window->resize(m_window->width() - 24, m_window->height()); // a new view
        QTRY_VERIFY_WITH_TIMEOUT(!seen.isEmpty(), kCheckTimeoutMs);
        QVERIFY(waitForVerdict(true));
        static const QRegularExpression howFar(QStringLiteral("checking… \\d+ %$"));
        QVERIFY2(std::all_of(seen.begin(), seen.end(),
                             [](const QString &s) { return howFar.match(s).hasMatch(); }),
                 qPrintable(seen.join(QLatin1Char('|'))));
    }

    void slidesEquationGetsCheck()
    {
        openWindow(sourcePath(QStringLiteral("assets/scenes/check.json")), {900, 600});
        QVERIFY(!QTest::currentTestFailed());
        QVERIFY(waitForVerdict(true));
        QVERIFY(typeTheSlidesEquationAndCheck(kCheckTimeoutMs));
        QVERIFY(!QTest::currentTestFailed());
        LiveCheck *check = m_window->liveCheck();
        const CheckedFrame &result = *check->lastResult();
        QVERIFY2(result.report().passed(), qPrintable(check->statusLabel()->verdict()));
        QVERIFY2(check->statusLabel()->verdict().contains(QStringLiteral("slide")),
                 qPrintable(check->statusLabel()->verdict()));
        const std::vector<int> errors =
            checkErrorSteps(toRgbImage(result.yours), *result.reference, PhongEquation::Slide);
        for (std::size_t i = 0; i < errors.size(); ++i) {
            if (errors[i] < 0)
                continue;
            const int x = int(i) % result.heatmap.width(), y = int(i) / result.heatmap.width();
            QVERIFY(errors[i] <= kTolerance);
            QVERIFY(qRed(result.heatmap.pixel(x, y)) < 128); // no yellow or red anywhere
        }
        // The exact picture shown is the slide's: the frame matches it.
        QCOMPARE(result.exact, toQImage(result.reference->slide.toImage(result.scene.background)));
    }

    // The scene's "bindings" name vertex inputs no name gives
    // away, also where the window builds (on its worker thread): the frame
    // the window shows is the one the check drew from the same recipe.
    // Without them Mesa puts the normal, declared first, at location 0 (on a
    // sphere that would not show: there the normal is the position).
    void sceneBindingsPlaceTheInputs()
    {
        QTemporaryDir dir;
        QFile vertexIn(sourcePath(QStringLiteral("assets/shaders/webgl2/phong.vert")));
        QVERIFY(vertexIn.open(QIODevice::ReadOnly));
        QByteArray vertex = vertexIn.readAll();
        QVERIFY(vertex.indexOf("in vec3 aPosition;") < vertex.indexOf("in vec3 aNormal;"));
        vertex.replace("in vec3 aPosition;", "in vec3 NORMAL;")
            .replace("in vec3 aNormal;", "in vec3 zz;")
            .replace("NORMAL", "aa");
        vertex.replace("aPosition", "zz").replace("aNormal", "aa");
        QVERIFY(QFile::copy(sourcePath(QStringLiteral("assets/shaders/webgl2/phong.frag")),
                            dir.filePath(QStringLiteral("f.frag"))));
        QFile vertexOut(dir.filePath(QStringLiteral("v.vert")));
        QVERIFY(vertexOut.open(QIODevice::WriteOnly));
        vertexOut.write(vertex);
        vertexOut.close();
        QFile sceneIn(sourcePath(QStringLiteral("assets/scenes/torus.json")));
        QVERIFY(sceneIn.open(QIODevice::ReadOnly));
        QJsonObject scene = QJsonDocument::fromJson(sceneIn.readAll()).object();
        scene[QStringLiteral("shaders")] = QJsonObject{{QStringLiteral("vertex"), "v.vert"},
                                                       {QStringLiteral("fragment"), "f.frag"}};
        scene[QStringLiteral("bindings")] =
            QJsonObject{{QStringLiteral("zz"), "position"}, {QStringLiteral("aa"), "normal"}};
        QFile sceneOut(dir.filePath(QStringLiteral("bound.json")));
        QVERIFY(sceneOut.open(QIODevice::WriteOnly));
        sceneOut.write(QJsonDocument(scene).toJson());
        sceneOut.close();

        openWindow(sceneOut.fileName(), {900, 600});
        QVERIFY(!QTest::currentTestFailed());
        viewport()->drawing().setShowLightMarkers(false); // the check's frame has none
        QVERIFY(waitForApplied());
        QVERIFY(fragmentEditor()->text().contains(QStringLiteral("uLightPosition")));
        QVERIFY(waitForVerdict(true));
        const QImage yours = m_window->liveCheck()->lastResult()->yours;
        const QImage shown = frame().convertToFormat(yours.format());
        QCOMPARE(shown.size(), yours.size());
        int worst = 0;
        for (int y = 0; y < yours.height(); ++y)
            for (int x = 0; x < yours.width(); ++x)
                worst = std::max(worst, maxChannelDifference(shown.pixel(x, y), yours.pixel(x, y)));
        QVERIFY2(worst <= 1,
                 qPrintable(QStringLiteral("the window's frame is off the check's by "
                                           "%1/255")
                                .arg(worst)));
    }

    // `phonglab SCENE.json --vertex FILE --fragment FILE` opens
    // the scene with a student's shaders in the editor, checked live.
    void opensASubmission()
    {
        const GuiArguments both =
            parseGuiArguments({QStringLiteral("s.json"), QStringLiteral("--vertex"),
                               QStringLiteral("a.vert"), QStringLiteral("--fragment=b.frag")});
        QVERIFY2(both.error.isEmpty(), qPrintable(both.error));
        QCOMPARE(both.files, QStringList{QStringLiteral("s.json")});
        QCOMPARE(both.vertexShader, QStringLiteral("a.vert"));
        QCOMPARE(both.fragmentShader, QStringLiteral("b.frag"));
        for (const QStringList &wrong :
             {QStringList{QStringLiteral("a.obj"), QStringLiteral("--vertex"), QStringLiteral("x")},
              QStringList{QStringLiteral("s.json"), QStringLiteral("--vertex")},
              QStringList{QStringLiteral("s.json"), QStringLiteral("--frag"), QStringLiteral("x")},
              QStringList{QStringLiteral("--fragment"), QStringLiteral("x.frag")}})
            QVERIFY2(!parseGuiArguments(wrong).error.isEmpty(), qPrintable(wrong.join(u' ')));
        QCOMPARE(parseGuiArguments({QStringLiteral("--"), QStringLiteral("-odd.json")}).files,
                 QStringList{QStringLiteral("-odd.json")});

        openWindow(sourcePath(QStringLiteral("assets/scenes/default.json")), {900, 600});
        QVERIFY(!QTest::currentTestFailed());
        const QString scene = sourcePath(QStringLiteral("assets/scenes/check.json"));
        const QString vertex = sourcePath(QStringLiteral("assets/shaders/webgl2/phong.vert"));
        const QString fragment = sourcePath(QStringLiteral("assets/shaders/webgl2/phong.frag"));
        QVERIFY(!m_window->document()->openSubmission(scene, QStringLiteral("/no/such/file.vert"),
                                                      fragment));
        QVERIFY_OK(m_window->document()->openSubmission(scene, vertex, fragment));
        QTRY_VERIFY_WITH_TIMEOUT(
            fragmentEditor()->text().contains(QStringLiteral("uLightPosition")), 20000);
        QVERIFY(waitForApplied());
        QVERIFY(waitForVerdict(true));
        QCOMPARE(m_window->liveCheck()->lastResult()->scene.vertexShader,
                 QFileInfo(vertex).absoluteFilePath());
    }

    // webglfundamentals' point-light lesson, with no binding given: the
    // window binds u_specularColor by its use and names the lesson's three
    // deviations, as `phonglab check` does (gl.tst_coursecode), on a scene
    // of the one light the shader takes.
    void namesTheLessonsDeviationsWithNoBinding()
    {
        QFile course(sourcePath(QStringLiteral("tests/data/course/scene.json")));
        QVERIFY(course.open(QIODevice::ReadOnly));
        QJsonObject scene = QJsonDocument::fromJson(course.readAll()).object();
        QJsonArray lights = scene.value(QStringLiteral("lights")).toArray();
        lights.removeLast();
        scene.insert(QStringLiteral("lights"), lights);
        QTemporaryDir dir;
        const QString scenePath = dir.filePath(QStringLiteral("one-light.json"));
        QFile out(scenePath);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(QJsonDocument(scene).toJson());
        out.close();
        openWindow(sourcePath(QStringLiteral("assets/scenes/default.json")), {900, 600});
        QVERIFY(!QTest::currentTestFailed());
        const QString lesson = sourcePath(QStringLiteral("tests/data/course/webglfundamentals/"));
        QVERIFY_OK(m_window->document()->openSubmission(
            scenePath, lesson + QStringLiteral("point-light.vert"),
            lesson + QStringLiteral("point-light.frag")));
        QTRY_VERIFY_WITH_TIMEOUT(
            fragmentEditor()->text().contains(QStringLiteral("u_specularColor")), 20000);
        QVERIFY(waitForApplied());
        QVERIFY(waitForVerdict(false));
        const CheckReport &report = m_window->liveCheck()->lastResult()->report();
        QVERIFY2(report.diagnosis.togetherExplains(), qPrintable(checkSummary(report)));
        QCOMPARE(mistakeSetKeys(report.diagnosis.together),
                 QStringLiteral("attenuation ambient halfway-vector"));
        // The Uniforms dock says why, under the choice the student can change.
        QTRY_VERIFY_WITH_TIMEOUT(
            m_window->findChild<QLabel *>(QStringLiteral("byUse:u_specularColor")), 10000);
        QVERIFY(m_window->findChild<QLabel *>(QStringLiteral("byUse:u_specularColor"))
                    ->text()
                    .contains(QStringLiteral("line 26")));

        // Angel's shadedCube lights per vertex: `gouraud` first, from its
        // code, in the window as in `check` (gl.tst_coursecode).
        const QString angel = sourcePath(QStringLiteral("tests/data/course/angel/"));
        QVERIFY_OK(m_window->document()->openSubmission(scenePath,
                                                        angel + QStringLiteral("shadedCube.vert"),
                                                        angel + QStringLiteral("shadedCube.frag")));
        QTRY_VERIFY_WITH_TIMEOUT(fragmentEditor()->text().contains(QStringLiteral("fColor")),
                                 20000);
        QVERIFY(waitForApplied());
        QTRY_VERIFY_WITH_TIMEOUT(
            m_window->liveCheck()->lastResult()
                && m_window->liveCheck()->lastResult()->scene.vertexShader.endsWith(
                    QLatin1String("shadedCube.vert")),
            kCheckTimeoutMs);
        QVERIFY(waitForVerdict(false));
        const MistakeDiagnosis &cube = m_window->liveCheck()->lastResult()->report().diagnosis;
        QVERIFY(!cube.findings.empty());
        QCOMPARE(cube.findings.front().key, ShaderMistake::Gouraud);
        QVERIFY(cube.findings.front().fromCode);
    }

    // A WebGL project's program opens from its page, is
    // checked live, and saves back into the page with only its bytes changed;
    // a shader built from several strings offers Save As instead.
    void opensAWebGlProject()
    {
        const GuiArguments args =
            parseGuiArguments({QStringLiteral("s.json"), QStringLiteral("--project"),
                               QStringLiteral("lab3"), QStringLiteral("--program=phong")});
        QVERIFY2(args.error.isEmpty(), qPrintable(args.error));
        QCOMPARE(args.project, QStringLiteral("lab3"));
        QCOMPARE(args.program, QStringLiteral("phong"));
        QVERIFY(args.hasShaders());
        QVERIFY(!parseGuiArguments(
                     {QStringLiteral("s.json"), QStringLiteral("--program"), QStringLiteral("x")})
                     .error.isEmpty());

        QTemporaryDir dir;
        const auto readAll = [](const QString &path) {
            QFile f(path);
            return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
        };
        const QByteArray vertex =
            readAll(sourcePath(QStringLiteral("assets/shaders/webgl2/phong.vert")));
        const QByteArray fragment =
            readAll(sourcePath(QStringLiteral("assets/shaders/webgl2/phong.frag")));
        const QByteArray page = "<!DOCTYPE html>\n<html><body>\n<script>\nconst vsSource = `"
            + vertex + "`;\nconst fsSource = `" + fragment
            + "`;\nconst program = initShaderProgram(gl, vsSource, fsSource);\n</script>\n"
              "</body></html>\n";
        const QString pagePath = dir.filePath(QStringLiteral("index.html"));
        {
            QFile f(pagePath);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(page);
        }
        const Result<ProjectProgram> chosen = chooseProgram(readProject(dir.path()), {});
        QVERIFY2(chosen, qPrintable(chosen.error()));
        openWindow(sourcePath(QStringLiteral("assets/scenes/default.json")), {900, 600});
        QVERIFY(!QTest::currentTestFailed());
        QVERIFY_OK(m_window->document()->openSubmission(
            sourcePath(QStringLiteral("assets/scenes/check.json")), shaderLocator(chosen->vertex),
            shaderLocator(chosen->fragment)));
        // The editor shows the shader as written in the page, and it is checked.
        QTRY_VERIFY_WITH_TIMEOUT(fragmentEditor()->text().toUtf8() == fragment, 20000);
        QVERIFY(waitForApplied());
        QVERIFY(waitForVerdict(true));
        // An edit saved goes into the page: every other byte stays.
        replaceInFragment(QStringLiteral("void main()"), QStringLiteral("/* edited */ "));
        ShaderDock *dock = m_window->shaderDock();
        QVERIFY_OK(dock->save(ShaderStage::Fragment));
        const QByteArray saved = readAll(pagePath);
        const qsizetype at = page.indexOf(fragment);
        QVERIFY(saved.startsWith(page.left(at)));
        QVERIFY(saved.endsWith(page.mid(at + fragment.size())));
        QCOMPARE(saved.mid(at, saved.size() - page.size() + fragment.size()),
                 fragmentEditor()->text().toUtf8());

        // Pieces: Save says why, with Save As as the way out.
        const QString pieces = dir.filePath(QStringLiteral("pieces.js"));
        {
            QFile f(pieces);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("var fs = 'precision highp float;\\n' +\n"
                    "  'void main() { gl_FragColor = vec4(1); }\\n';\n");
        }
        QVERIFY_OK(dock->openFiles({pieces + QStringLiteral("#fs")}));
        replaceInFragment(QStringLiteral("vec4(1)"), QStringLiteral(" "));
        const Result<> refused = dock->save(ShaderStage::Fragment);
        QVERIFY(!refused);
        QVERIFY2(refused.error().contains(QStringLiteral("Save As")), qPrintable(refused.error()));
        QVERIFY_OK(
            dock->openFiles({sourcePath(QStringLiteral("assets/shaders/webgl2/phong.frag"))}));
    }

    // The view's 4 samples blend each silhouette with the
    // background; a check of that frame said ✗ (57 dB) at first launch.
    void shippedScenesPassAsTheAppDraws_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QSize>("size");
        const QDir scenes(sourcePath(QStringLiteral("assets/scenes")));
        const QStringList files = scenes.entryList({QStringLiteral("*.json")}, QDir::Files);
        QVERIFY(files.size() >= 5);
        for (const QString &file : files)
            for (const QSize size : {QSize(900, 600), QSize(1260, 940)})
                QTest::addRow("%s %dx%d", qPrintable(file), size.width(), size.height())
                    << scenes.filePath(file) << size;
    }

    void shippedScenesPassAsTheAppDraws()
    {
        QFETCH(QString, scene);
        QFETCH(QSize, size);
        openWindow(scene, size, kViewportSamples);
        QVERIFY(!QTest::currentTestFailed());
        QVERIFY2(viewport()->frames().framebufferSamples() > 1,
                 qPrintable(QStringLiteral("the view draws with %1 samples")
                                .arg(viewport()->frames().framebufferSamples())));
        LiveCheck *check = m_window->liveCheck();
        QVERIFY(QTest::qWaitFor(
            [&] {
                return !check->isChecking() && check->lastResult()
                    && check->lastResult()->reference;
            },
            kCheckTimeoutMs));
        const QString status = check->statusLabel()->verdict();
        QVERIFY2(status.startsWith(QStringLiteral("✓")), qPrintable(status));
        // What was checked is the view as it is: its size and its scene.
        QCOMPARE(check->lastResult()->yours.size(),
                 viewport()->size() * viewport()->devicePixelRatioF());
        qInfo("%s", qPrintable(status));
    }

private:
    // Waits for a finished check of the current frame with this verdict.
    bool waitForVerdict(bool passed)
    {
        LiveCheck *check = m_window->liveCheck();
        return QTest::qWaitFor(
            [&] {
                return !check->isChecking() && check->lastResult() && check->lastResult()->reference
                    && check->lastResult()->report().passed() == passed;
            },
            kCheckTimeoutMs);
    }
};

QTEST_MAIN(TestLiveCheck)
#include "tst_livecheck.moc"
