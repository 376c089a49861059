// The window tells a student the same truth as `phonglab check`,
// on the same scene and files, and shows the way to a verdict: what nothing
// places is no mistake of the student's, a found mistake is marked on its
// line, a pass never claims what the scene cannot show, and the status bar
// is a short form of the check's panel, cut at words.
#include "PhonglabProcess.h"
#include "ResultChecks.h"
#include "ShaderDockParts.h"
#include "TestPaths.h"
#include "UiTestWindow.h"
#include "core/check/MistakeSets.h"
#include "ui/check/LiveCheck.h"
#include "ui/check/VerdictDock.h"
#include "ui/check/VerdictLabel.h"
#include "ui/shaders/ShaderDock.h"
#include "ui/shaders/ShaderEditor.h"
#include "ui/uniforms/UniformsDock.h"
#include "ui/viewport/Viewport.h"
#include "ui/window/MainWindow.h"
#include "ui/window/SceneDocument.h"

#include <QComboBox>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QTemporaryDir>
#include <QTest>

using namespace phonglab;
using namespace phonglab::test;

namespace {

constexpr int kCheckTimeoutMs = 30000;

QString writeFile(const QTemporaryDir &dir, const QString &name, const QByteArray &text)
{
    const QString path = dir.filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return {};
    file.write(text);
    return path;
}

QByteArray readFile(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// The course's scene with `edit` applied to its JSON.
template <typename Edit>
QString courseScene(const QTemporaryDir &dir, const QString &name, Edit edit)
{
    QJsonObject scene = QJsonDocument::fromJson(
                            readFile(sourcePath(QStringLiteral("tests/data/course/scene.json"))))
                            .object();
    edit(scene);
    return writeFile(dir, name, QJsonDocument(scene).toJson());
}

} // namespace

class TestVerdict : public QObject, public UiTestWindow
{
    Q_OBJECT

private slots:
    void initTestCase() { m_env.isolate(); }
    void cleanup() { m_window.reset(); }

    // Item 1, "the window and check disagree when the scene has more lights
    // than the shader takes": Angel's shader takes one light, the course's
    // scene has two. Before, the window checked both and failed a correct
    // shader; check checked the first alone.
    void checksTheLightsTheShaderTakesAsCheckDoes()
    {
        QTemporaryDir dir;
        const QString scene = courseScene(dir, QStringLiteral("two-lights.json"), [](auto &) {});
        openSubmission(scene, QStringLiteral("phong.frag"));
        QVERIFY(!QTest::currentTestFailed());
        QVERIFY(waitForChecked());
        // The box above the editor names the student's shader, not "Phong".
        QCOMPARE(test::shadingMethodBox(m_window->shaderDock())->currentText(),
                 QStringLiteral("phong.frag (your shader)"));
        const CheckedFrame &result = *lastResult();
        QVERIFY2(result.hasVerdict(), qPrintable(panelText()));
        // Angel's lightPosition is the light in camera coordinates, which
        // its name does not say: placed as a world one it is light-space.
        QCOMPARE(diagnosisKeys(result).value(0), QStringLiteral("light-space"));
        QCOMPARE(result.scene.lights.size(), std::size_t(2));
        QVERIFY(!result.scene.lights[1].enabled); // checked with the first alone
        QVERIFY2(panelText().contains(QStringLiteral("checked with the first 1 alone")),
                 qPrintable(panelText()));

        const QJsonObject cli = checkOnTheCommandLine(scene, m_vertex, m_fragment);
        QCOMPARE(verdictName(result.outcome.verdict),
                 cli.value(QStringLiteral("verdict")).toString());
        QCOMPARE(diagnosisKeys(result), diagnosisKeys(cli));
        // The view's shape frames the camera its own way in the window (a
        // narrow view keeps the width in sight): the numbers may differ, the
        // verdict may not.
        const QJsonArray notes = cli.value(QStringLiteral("notes")).toArray();
        QVERIFY(std::any_of(notes.begin(), notes.end(), [](const QJsonValue &n) {
            return n.toString().contains(QStringLiteral("checked with the first 1 alone"));
        }));
    }

    // Items 1, 2 and 3: a uniform nothing places is an error, as check says,
    // marked in the Uniforms dock and at its declaration, and the status bar
    // leads to its row. Before, the window failed it as "homogeneous-w".
    void anUnplacedUniformLeadsToItsRow()
    {
        QTemporaryDir dir;
        const QString scene = courseScene(dir, QStringLiteral("scene.json"), [](auto &) {});
        QByteArray fragment = readFile(angel(QStringLiteral("phong.frag")));
        fragment.replace("uniform float shininess;",
                         "uniform float shininess;\nuniform vec3 uZork;");
        fragment.replace("fColor.a = 1.0;", "fColor.rgb += uZork;\n    fColor.a = 1.0;");
        const QString zork = writeFile(dir, QStringLiteral("zork.frag"), fragment);
        openSubmission(scene, zork);
        QVERIFY(!QTest::currentTestFailed());
        QVERIFY(waitForChecked());
        const CheckedFrame &result = *lastResult();
        QVERIFY2(!result.hasVerdict(), qPrintable(panelText()));
        QCOMPARE(result.unbound.size(), std::size_t(1));
        const QString status = check()->statusLabel()->verdict();
        QVERIFY2(status.contains(QStringLiteral("choose what uZork means in Uniforms")),
                 qPrintable(status));
        QVERIFY2(!status.contains(QStringLiteral("✗")), qPrintable(status));
        QCOMPARE(checkOnTheCommandLine(scene, m_vertex, zork).value(QStringLiteral("verdict")),
                 QJsonValue(QStringLiteral("error")));

        auto *uniforms = static_cast<UniformsDock *>(m_window->docks().uniforms);
        QTRY_VERIFY(uniforms->findChild<QLabel *>(QStringLiteral("unplaced:uZork")));
        QTRY_VERIFY(
            uniforms->findChild<QLabel *>(QStringLiteral("unplaced:uZork"))->isVisibleTo(uniforms));
        // At its declaration in the editor, as a compile error would be.
        QTRY_COMPARE(fragmentEditor()->checkMarkLines(), QList<int>{7});
        QVERIFY(fragmentEditor()->annotationText(7).contains(QStringLiteral("uZork")));
        // The status bar's click brings its row and its choice.
        uniforms->hide();
        m_window->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
        QTest::mouseClick(check()->statusLabel(), Qt::LeftButton);
        QVERIFY(uniforms->isVisible());
        auto *choice = uniforms->findChild<QComboBox *>(QStringLiteral("boundTo:uZork"));
        QVERIFY(choice);
        QTRY_VERIFY(choice->hasFocus());
        // Each meaning says what it is.
        const int position = choice->findData(QStringLiteral("light-position"));
        QVERIFY(position > 0);
        QVERIFY2(choice->itemText(position).size() > QStringLiteral("light-position").size() + 8,
                 qPrintable(choice->itemText(position)));
    }

    // Items 3 and 5: the mistakes found are marked on their lines, each with
    // its text, and the panel holds the whole verdict with its lines as links.
    // Before, only the status bar said "✗ attenuation".
    void foundMistakesAreMarkedOnTheirLines()
    {
        QTemporaryDir dir;
        const QString scene = courseScene(dir, QStringLiteral("one-light.json"), [](auto &s) {
            QJsonArray lights = s.value(QStringLiteral("lights")).toArray();
            lights.removeLast();
            s.insert(QStringLiteral("lights"), lights);
        });
        QByteArray fragment = readFile(angel(QStringLiteral("phong.frag")));
        fragment.replace("ambient + fatt * (diffuse + specular)", "ambient + (diffuse + specular)");
        fragment.replace("reflect(-l, n)", "reflect(l, n)");
        const QString wrong = writeFile(dir, QStringLiteral("two-mistakes.frag"), fragment);
        openSubmission(scene, wrong);
        QVERIFY(!QTest::currentTestFailed());
        QVERIFY(waitForChecked());
        const CheckedFrame &result = *lastResult();
        QCOMPARE(result.outcome.verdict, Verdict::Fail);
        const QJsonObject cli = checkOnTheCommandLine(scene, m_vertex, wrong);
        QCOMPARE(cli.value(QStringLiteral("verdict")).toString(), QStringLiteral("fail"));
        QCOMPARE(diagnosisKeys(result), diagnosisKeys(cli));
        QVERIFY2(diagnosisKeys(result).contains(QStringLiteral("attenuation")),
                 qPrintable(panelText()));

        QTRY_VERIFY(fragmentEditor()->checkMarkLines().size() >= 2);
        const QList<int> lines = fragmentEditor()->checkMarkLines();
        QString marked;
        for (int line : lines)
            marked += fragmentEditor()->annotationText(line) + QLatin1Char('\n');
        QVERIFY2(marked.contains(QStringLiteral("attenuation")), qPrintable(marked));
        QVERIFY2(marked.contains(QStringLiteral("reflect")), qPrintable(marked));
        // In the margin, as an arrow: a marker no margin shows is painted as
        // the line's background, over the code (it hid the marked lines).
        ShaderEditor *editor = fragmentEditor();
        long inMargins = 0;
        for (int margin = 0; margin < editor->margins(); ++margin)
            inMargins |= editor->SendScintilla(QsciScintillaBase::SCI_GETMARGINMASKN, margin);
        const long onLine =
            editor->SendScintilla(QsciScintillaBase::SCI_MARKERGET, lines.front() - 1);
        QVERIFY(onLine != 0);
        QCOMPARE(onLine & ~inMargins, 0L);
        QVERIFY2(panelText().contains(QStringLiteral("two-mistakes.frag:")),
                 qPrintable(panelText()));
        // A line in the panel is a link to the editor's line.
        emit check()->verdictDock()->lineChosen(ShaderStage::Fragment, lines.front());
        int line = 0;
        int index = 0;
        fragmentEditor()->getCursorPosition(&line, &index);
        QCOMPARE(line + 1, lines.front());
        // The status bar's short form: the keys, never a rule cut mid-word.
        const QString status = check()->statusLabel()->verdict();
        QVERIFY2(status.startsWith(QStringLiteral("✗")) && !status.contains(QStringLiteral("N·")),
                 qPrintable(status));
    }

    // Item 4: while the code does not compile, the verdict shown is the last
    // good program's and says so. Before: "✓ PSNR 95.7 dB" beside the error.
    void aCompileErrorShowsTheLastGoodProgramsVerdictAsItsOwn()
    {
        openWindow(sourcePath(QStringLiteral("assets/scenes/check.json")), {900, 600});
        QVERIFY(!QTest::currentTestFailed());
        QVERIFY(waitForChecked());
        QVERIFY(check()->statusLabel()->verdict().startsWith(QStringLiteral("✓")));
        replaceInFragment(QStringLiteral("void main()"), QStringLiteral("void main() oops"));
        QTRY_VERIFY_WITH_TIMEOUT(
            check()->statusLabel()->verdict().startsWith(QStringLiteral("last good program: ✓")),
            20000);
        QVERIFY(panelText().contains(QStringLiteral("does not compile")));
    }

    // Item 4: with ks = 0 everywhere no image can tell a Blinn highlight
    // from Phong's: the pass says the specular term was not checked, in the
    // window as in check. Before: "✓ matches the exact image".
    void aPassSaysWhichTermsTheSceneCannotCheck()
    {
        QTemporaryDir dir;
        const QString scene = courseScene(dir, QStringLiteral("no-ks.json"), [](auto &s) {
            QJsonArray objects = s.value(QStringLiteral("objects")).toArray();
            for (qsizetype i = 0; i < objects.size(); ++i) {
                QJsonObject o = objects[i].toObject();
                QJsonObject m = o.value(QStringLiteral("material")).toObject();
                m.insert(QStringLiteral("ks"), QJsonArray{0.0, 0.0, 0.0});
                o.insert(QStringLiteral("material"), m);
                objects[i] = o;
            }
            s.insert(QStringLiteral("objects"), objects);
            // Angel's light is in camera coordinates; his Blinn shader has no
            // attenuation, and the scene has none either.
            s.insert(QStringLiteral("bindings"),
                     QJsonObject{{QStringLiteral("lightPosition"),
                                  QStringLiteral("light-position-camera")}});
            QJsonArray lights = s.value(QStringLiteral("lights")).toArray();
            for (qsizetype i = 0; i < lights.size(); ++i) {
                QJsonObject l = lights[i].toObject();
                l.insert(QStringLiteral("attenuation"), QJsonArray{1.0, 0.0, 0.0});
                lights[i] = l;
            }
            s.insert(QStringLiteral("lights"), lights);
        });
        openSubmission(scene, angel(QStringLiteral("blinn.frag")));
        QVERIFY(!QTest::currentTestFailed());
        QVERIFY(waitForChecked());
        QVERIFY2(lastResult()->report().passed(), qPrintable(panelText()));
        const QString status = check()->statusLabel()->verdict();
        QVERIFY2(status.contains(QStringLiteral("not checked here: specular")), qPrintable(status));
        const QJsonObject cli =
            checkOnTheCommandLine(scene, m_vertex, angel(QStringLiteral("blinn.frag")));
        QCOMPARE(cli.value(QStringLiteral("verdict")).toString(), QStringLiteral("pass"));
        const QJsonArray unchecked = cli.value(QStringLiteral("unchecked_terms")).toArray();
        QCOMPARE(unchecked.size(), 1);
        QCOMPARE(unchecked[0].toObject().value(QStringLiteral("term")).toString(),
                 QStringLiteral("specular"));
        QVERIFY(panelText().contains(QStringLiteral("ks = 0 on every object")));
    }

    // Item 6: a binding chosen for one project's names is not saved into
    // the next project's scene; File opens a shader and a project folder.
    void bindingsBelongToTheirProject()
    {
        openWindow(sourcePath(QStringLiteral("assets/scenes/default.json")), {900, 600});
        QVERIFY(!QTest::currentTestFailed());
        const QString lesson = sourcePath(QStringLiteral("tests/data/course/webglfundamentals/"));
        QVERIFY_OK(
            m_window->document()->openShaderFiles({lesson + QStringLiteral("point-light.vert"),
                                                   lesson + QStringLiteral("point-light.frag")}));
        QVERIFY(waitForApplied());
        m_window->viewport()->program().setBindings(
            {{QStringLiteral("u_specularColor"), BindingMeaning::SpecularProduct}});
        QCOMPARE(m_window->viewport()->currentScene().bindings.size(), std::size_t(1));
        QVERIFY_OK(m_window->document()->openShaderFiles(
            {angel(QStringLiteral("phong.vert")), angel(QStringLiteral("phong.frag"))}));
        QVERIFY(waitForApplied());
        QVERIFY(m_window->viewport()->currentScene().bindings.empty());
        QTemporaryDir dir;
        const QString saved = dir.filePath(QStringLiteral("next.json"));
        QVERIFY_OK(m_window->document()->save(saved));
        QVERIFY(!readFile(saved).contains("u_specularColor"));

        QStringList actions;
        for (QAction *a : m_window->menuBar()->actions().front()->menu()->actions())
            actions << a->text().remove(QLatin1Char('&'));
        QVERIFY2(actions.contains(QStringLiteral("Open Shader…")), qPrintable(actions.join(u'|')));
        QVERIFY2(actions.contains(QStringLiteral("Open Project Folder…")),
                 qPrintable(actions.join(u'|')));
    }

    // Item 5: the status bar is cut at a word, never inside one.
    void theStatusBarIsCutAtWords()
    {
        const QString full = QStringLiteral("✗ PSNR 26.8 dB — attenuation + halfway-vector: N·H "
                                            "with the halfway vector in place of R·V");
        VerdictLabel label;
        label.setVerdict(full);
        label.resize(label.fontMetrics().horizontalAdvance(full.left(40)), 20);
        label.show();
        QVERIFY(QTest::qWaitForWindowExposed(&label));
        const QString shown = label.text();
        QVERIFY2(shown.endsWith(QStringLiteral("…")), qPrintable(shown));
        const QString kept = shown.chopped(2);
        QVERIFY2(full.startsWith(kept), qPrintable(shown));
        QVERIFY2(full.at(kept.size()) == QLatin1Char(' ')
                     || full.mid(kept.size(), 2) == QStringLiteral(": "),
                 qPrintable(shown));
        QCOMPARE(label.toolTip(), full);
        QCOMPARE(wordElided(full, label.fontMetrics(), 10000), full);
    }

private:
    LiveCheck *check() const { return m_window->liveCheck(); }
    const std::optional<CheckedFrame> &lastResult() const { return check()->lastResult(); }
    QString panelText() const { return check()->verdictDock()->text(); }
    static QString angel(const QString &name)
    {
        return sourcePath(QStringLiteral("tests/data/course/angel/") + name);
    }

    void openSubmission(const QString &scene, const QString &fragment)
    {
        openWindow(sourcePath(QStringLiteral("assets/scenes/default.json")), {900, 600});
        QVERIFY(!QTest::currentTestFailed());
        m_vertex = angel(QStringLiteral("phong.vert"));
        m_fragment = fragment.contains(QLatin1Char('/')) ? fragment : angel(fragment);
        m_generation = lastResult() ? lastResult()->generation : 0;
        QVERIFY_OK(m_window->document()->openSubmission(scene, m_vertex, m_fragment));
        const QByteArray text = readFile(m_fragment);
        QTRY_VERIFY_WITH_TIMEOUT(fragmentEditor()->code() == text, 20000);
        QVERIFY(waitForApplied());
    }

    // A check of the code in the editor, after the submission opened.
    bool waitForChecked() const
    {
        return QTest::qWaitFor(
            [&] {
                return !check()->isChecking() && lastResult()
                    && lastResult()->generation > m_generation
                    && lastResult()->scene.fragmentShader
                    == m_window->viewport()->currentScene().fragmentShader
                    && (lastResult()->reference || !lastResult()->unbound.empty());
            },
            kCheckTimeoutMs);
    }

    QSize checkedSize() const
    {
        return m_window->viewport()->size() * m_window->viewport()->devicePixelRatioF();
    }

    QJsonObject checkOnTheCommandLine(const QString &scene, const QString &vertex,
                                      const QString &fragment) const
    {
        const QSize size = checkedSize();
        const ProcessRun run =
            runPhonglab({QStringLiteral("check"), scene, QStringLiteral("--vertex"), vertex,
                         QStringLiteral("--fragment"), fragment, QStringLiteral("--size"),
                         QStringLiteral("%1x%2").arg(size.width()).arg(size.height()),
                         QStringLiteral("--json")});
        return QJsonDocument::fromJson(run.out).object();
    }

    // The keys the verdict names: the set that explains it together, else
    // the findings, in order.
    static QStringList diagnosisKeys(const CheckedFrame &result)
    {
        const MistakeDiagnosis &d = result.report().diagnosis;
        QStringList keys;
        if (d.together.variants.size() > 1 && d.togetherExplains())
            for (MistakeVariant v : d.together.variants)
                keys << shaderMistakeKey(v.key);
        else
            for (const MistakeFinding &f : d.findings)
                keys << shaderMistakeKey(f.key);
        return keys;
    }
    static QStringList diagnosisKeys(const QJsonObject &cli)
    {
        QStringList keys;
        const QJsonValue together = cli.value(QStringLiteral("together"));
        if (together.isObject()
            && together.toObject().value(QStringLiteral("keys")).toArray().size() > 1) {
            for (const QJsonValue &k : together.toObject().value(QStringLiteral("keys")).toArray())
                keys << k.toString();
            return keys;
        }
        for (const QJsonValue &f : cli.value(QStringLiteral("diagnosis")).toArray())
            if (const QString key = f.toObject().value(QStringLiteral("key")).toString();
                key != QStringLiteral("unknown"))
                keys << key;
        return keys;
    }

    QString m_vertex;
    QString m_fragment;
    quint64 m_generation = 0;
};

QTEST_MAIN(TestVerdict)
#include "tst_verdict.moc"
