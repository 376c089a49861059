// The Uniforms dock in the real window on a real GL context (llvmpipe under
// Xvfb): rows come from the linked program after every build; what the scene
// or the renderer sets is read-only; a user uniform is edited through the
// dock, changes the frame, survives a recompile; bad input is refused.
#include "ShaderDockParts.h"
#include "TestPaths.h"
#include "UiTestWindow.h"
#include "ui/shaders/LiveShaderController.h"
#include "ui/shaders/ShaderDock.h"
#include "ui/shaders/ShaderEditor.h"
#include "ui/shaders/ShaderFileSet.h"
#include "ui/uniforms/BindingChoice.h"
#include "ui/uniforms/UniformBoolRow.h"
#include "ui/uniforms/UniformFloatRow.h"
#include "ui/uniforms/UniformIntRow.h"
#include "ui/uniforms/UniformNumberField.h"
#include "ui/uniforms/UniformVectorRow.h"
#include "ui/uniforms/UniformsDock.h"
#include "ui/viewport/Viewport.h"
#include "ui/window/MainWindow.h"
#include "ui/window/SceneDocument.h"

#include <QCheckBox>
#include <QDir>
#include <QLabel>
#include <QLineEdit>
#include <QPointer>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QTemporaryDir>

#include "ResultChecks.h"
#include "core/scene/SceneJson.h"
#include <QTest>
#include <QToolButton>
#include <memory>

using namespace phonglab;
using phonglab::test::sourcePath;

namespace {

} // namespace

class TestUniformsDock : public test::WindowPerTest
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();

    void drivenUniformsAreReadOnly();
    void userUniformIsEditedAndKept();
    void userUniformIsSavedWithTheScene();
    void boundToChoiceIsSavedWithTheScene();
    void badInputIsRefused();
    void optimisedAwayUniformIsFlagged();
    void colourIntAndBoolRows();

private:
    void openWindow();
    void addGain();
    void typeInto(UniformNumberField *field, const QString &text);
    float programValue(const QByteArray &name);
    UniformsDock *dock() const { return m_window->uniformsDock(); }
    UniformFloatRow *gainRow() const
    {
        return qobject_cast<UniformFloatRow *>(dock()->row(QStringLiteral("gain")));
    }
};

void TestUniformsDock::initTestCase()
{
    m_env.isolate();
    QDir(ShaderFileSet::userFolder()).removeRecursively();
}

void TestUniformsDock::init()
{
    m_env.useFreshRecoveryDir(nullptr);
}

void TestUniformsDock::openWindow()
{
    UiTestWindow::openWindow(sourcePath(QStringLiteral("assets/scenes/default.json")), {1000, 700});
    if (QTest::currentTestFailed())
        return;
    dock()->raise();
    QTRY_VERIFY(dock()->row(QStringLiteral("kd")));
}

// `uniform float gain; // @range 0 2` scales the output: 0 (its initial
// value) draws black.
void TestUniformsDock::addGain()
{
    ShaderEditor *editor = fragmentEditor();
    editor->insertAt(QStringLiteral("uniform float gain; // @range 0 2\n"), 1, 0);
    QVERIFY(editor->findFirst(QStringLiteral("vec4(I,"), false, true, false, false, true, 0, 0));
    editor->replace(QStringLiteral("vec4(I * gain,"));
    test::compileAction(m_window->shaderDock())->trigger();
    QVERIFY(waitForApplied());
    QTRY_VERIFY(gainRow());
}

void TestUniformsDock::typeInto(UniformNumberField *field, const QString &text)
{
    field->selectAll();
    QTest::keyClicks(field, text);
    QTest::keyClick(field, Qt::Key_Return);
}

float TestUniformsDock::programValue(const QByteArray &name)
{
    const UniformSnapshot values = programSnapshot();
    const UniformValue *value = values.find(name);
    return value ? value->floats[0] : -1.0f;
}

void TestUniformsDock::drivenUniformsAreReadOnly()
{
    openWindow();
    auto *kd = qobject_cast<UniformVectorRow *>(dock()->row(QStringLiteral("kd")));
    QVERIFY(kd);
    QVERIFY(kd->colorButton());
    QVERIFY(!kd->isEnabled());
    QVERIFY(kd->toolTip().contains(QStringLiteral("set by the scene")));
    // The program holds the material of the object drawn last.
    const glm::dvec3 material = viewport()->currentScene().objects.back().material.kd;
    QCOMPARE(kd->values().value(0), float(material.x));
    QCOMPARE(kd->values().value(2), float(material.z));
    QVERIFY(kd->values().value(0) + kd->values().value(1) + kd->values().value(2) > 0.0f);

    QWidget *matrix = dock()->row(QStringLiteral("modelViewMatrix"));
    QVERIFY(matrix);
    QVERIFY(!matrix->isEnabled());
    QCOMPARE(matrix->toolTip(), QStringLiteral("set by the renderer"));
    QVERIFY(qobject_cast<UniformFloatRow *>(dock()->row(QStringLiteral("shininess"))));
    for (int i = 0; i < 8; ++i) // one row per array element
        QVERIFY(dock()->row(QStringLiteral("Id[%1]").arg(i)));
    QVERIFY(dock()->inactiveNames().isEmpty());
}

void TestUniformsDock::userUniformIsEditedAndKept()
{
    openWindow();
    addGain();
    UniformFloatRow *gain = gainRow();
    QVERIFY(gain->isEnabled());
    QVERIFY(gain->slider()->isVisibleTo(gain));
    QCOMPARE(gain->field()->maximum(), 2.0); // from @range
    QCOMPARE(gain->value(), 0.0f);
    const QImage black = frame();

    typeInto(gain->field(), QStringLiteral("0.5"));
    QCOMPARE(gain->value(), 0.5f);
    QCOMPARE(gain->slider()->value(), gain->slider()->maximum() / 4); // 0.5 of 0..2
    QCOMPARE(programValue("gain"), 0.5f);
    QTRY_VERIFY(frame() != black);
    const QImage withGain = frame();

    QSignalSpy rebuilt(dock(), &UniformsDock::rebuilt);
    const QPointer<UniformFloatRow> before = gainRow();
    fragmentEditor()->append(QStringLiteral("// an unrelated edit\n"));
    test::compileAction(m_window->shaderDock())->trigger();
    QVERIFY(waitForApplied());
    QTRY_VERIFY(rebuilt.count() > 0);
    QVERIFY(gainRow());
    QCOMPARE(gainRow()->value(), 0.5f); // the dock shows the carried value
    QCOMPARE(programValue("gain"), 0.5f);
    QCOMPARE(frame(), withGain);
    // The same uniforms keep the same rows (making them again stalled the
    // GUI thread after every edit); a changed annotation makes them anew.
    QCOMPARE(gainRow(), before.data());
    QVERIFY(fragmentEditor()->findFirst(QStringLiteral("@range 0 2"), false, true, false, false,
                                        true, 0, 0));
    fragmentEditor()->replace(QStringLiteral("@range 0 4"));
    rebuilt.clear();
    test::compileAction(m_window->shaderDock())->trigger();
    QVERIFY(waitForApplied());
    QTRY_VERIFY(rebuilt.count() > 0);
    QVERIFY(gainRow() && gainRow() != before.data());
    QCOMPARE(gainRow()->field()->maximum(), 4.0);
    QCOMPARE(gainRow()->value(), 0.5f);
}

void TestUniformsDock::userUniformIsSavedWithTheScene()
{
    openWindow();
    addGain();
    typeInto(gainRow()->field(), QStringLiteral("0.5"));
    QCOMPARE(programValue("gain"), 0.5f);

    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("with-gain.json"));
    QString error;
    QVERIFY_OK(m_window->document()->save(path));
    const SceneLoadResult saved = loadSceneFile(path);
    QVERIFY2(saved.ok(), qPrintable(saved.error));
    QCOMPARE(saved.scene->uniforms.size(),
             std::size_t(1)); // only the user's: not kd, not the matrices
    QCOMPARE(saved.scene->uniforms.at(QStringLiteral("gain")), std::vector<double>{0.5});

    // Away, change it, and back: the reopened scene sets the saved value.
    QVERIFY_OK(
        m_window->document()->openAndWait(sourcePath(QStringLiteral("assets/scenes/torus.json"))));
    QTRY_VERIFY_WITH_TIMEOUT(gainRow(), 10000);
    typeInto(gainRow()->field(), QStringLiteral("1.5"));
    QCOMPARE(programValue("gain"), 1.5f);
    QVERIFY_OK(m_window->document()->openAndWait(path));
    QTRY_VERIFY_WITH_TIMEOUT(gainRow() && programValue("gain") == 0.5f, 10000);
}

// The dock's "bound to" choice binds a uniform to a meaning
// whatever its name, goes into the scene's "bindings", and comes back with it.
void TestUniformsDock::boundToChoiceIsSavedWithTheScene()
{
    openWindow();
    addGain();
    auto *choice = dock()->findChild<BindingChoice *>(QStringLiteral("boundTo:gain"));
    QVERIFY(choice);
    QCOMPARE(choice->currentText(), QStringLiteral("automatic: your own"));
    QVERIFY(choice->findData(QStringLiteral("kd")) < 0); // a float cannot hold kd
    const int shininess = choice->findData(QStringLiteral("shininess"));
    QVERIFY(shininess > 0);
    choice->setCurrentIndex(shininess);
    emit choice->activated(shininess);
    const double n = viewport()->currentScene().objects.back().material.shininess;
    QTRY_VERIFY(gainRow() && !gainRow()->isEnabled()); // set by the scene now
    QTRY_COMPARE(programValue("gain"), float(n));
    QCOMPARE(viewport()->currentScene().bindings.at(QStringLiteral("gain")),
             std::optional(BindingMeaning::Shininess));

    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("bound.json"));
    QVERIFY_OK(m_window->document()->save(path));
    const SceneLoadResult saved = loadSceneFile(path);
    QVERIFY2(saved.ok(), qPrintable(saved.error));
    QCOMPARE(saved.scene->bindings.size(), std::size_t(1));
    QCOMPARE(saved.scene->bindings.at(QStringLiteral("gain")),
             std::optional(BindingMeaning::Shininess));
    QVERIFY(!saved.scene->uniforms.contains(QStringLiteral("gain"))); // not the user's now

    // A new window on the saved scene: the same choice, the same binding.
    UiTestWindow::openWindow(path, {1000, 700});
    QVERIFY(!QTest::currentTestFailed());
    dock()->raise();
    QTRY_VERIFY_WITH_TIMEOUT(
        dock()->findChild<BindingChoice *>(QStringLiteral("boundTo:gain")) && gainRow(), 10000);
    choice = dock()->findChild<BindingChoice *>(QStringLiteral("boundTo:gain"));
    QCOMPARE(choice->currentData().toString(), QStringLiteral("shininess"));
    QVERIFY(!gainRow()->isEnabled());
    QTRY_COMPARE(programValue("gain"), float(n));

    // Back to "your own": the dock edits it again, and the scene says so.
    const int own = choice->findData(QStringLiteral("none"));
    choice->setCurrentIndex(own);
    emit choice->activated(own);
    QTRY_VERIFY(gainRow() && gainRow()->isEnabled());
    QCOMPARE(viewport()->currentScene().bindings.at(QStringLiteral("gain")),
             std::optional<BindingMeaning>());
}

void TestUniformsDock::badInputIsRefused()
{
    openWindow();
    addGain();
    UniformNumberField *field = gainRow()->field();
    typeInto(field, QStringLiteral("0.5"));
    QCOMPARE(programValue("gain"), 0.5f);

    typeInto(field, QStringLiteral("nan"));
    QTRY_VERIFY(!field->refusal().isEmpty());
    QCOMPARE(field->value(), 0.5);
    QVERIFY(field->toolTip().contains(QStringLiteral("Refused")));
    QVERIFY(field->styleSheet().contains(QStringLiteral("border")));
    QVERIFY(gainRow()->refusalLabel()->isVisibleTo(gainRow()));
    QCOMPARE(programValue("gain"), 0.5f);

    typeInto(field, QStringLiteral("5"));
    QTRY_VERIFY(field->refusal().contains(QStringLiteral("outside the range")));
    QCOMPARE(field->value(), 0.5);
    QCOMPARE(programValue("gain"), 0.5f);

    typeInto(field, QStringLiteral("1.5")); // a good value clears the mark
    QCOMPARE(field->value(), 1.5);
    QVERIFY(field->refusal().isEmpty());
    QVERIFY(!gainRow()->refusalLabel()->isVisibleTo(gainRow()));
    QCOMPARE(programValue("gain"), 1.5f);
}

void TestUniformsDock::optimisedAwayUniformIsFlagged()
{
    openWindow();
    fragmentEditor()->insertAt(QStringLiteral("uniform float unusedGain; // @range 0 1\n"), 1, 0);
    test::compileAction(m_window->shaderDock())->trigger();
    QVERIFY(waitForApplied());
    QTRY_VERIFY(dock()->inactiveNames().contains(QStringLiteral("unusedGain")));
    QWidget *row = dock()->row(QStringLiteral("unusedGain"));
    QVERIFY(row);
    bool explained = false;
    for (const QLabel *label : row->findChildren<QLabel *>())
        explained |=
            label->text() == QStringLiteral("declared but optimised away: not used by the program");
    QVERIFY(explained);
    QVERIFY(!qobject_cast<UniformFloatRow *>(row));
}

void TestUniformsDock::colourIntAndBoolRows()
{
    openWindow();
    ShaderEditor *editor = fragmentEditor();
    editor->insertAt(
        QStringLiteral("uniform vec3 tint; // @color\nuniform int steps; // @range 0 8\n"
                       "uniform bool flip;\n"),
        1, 0);
    QVERIFY(editor->findFirst(QStringLiteral("vec4(I,"), false, true, false, false, true, 0, 0));
    editor->replace(QStringLiteral("vec4(I * tint * float(steps) * (flip ? 0.5 : 1.0),"));
    test::compileAction(m_window->shaderDock())->trigger();
    QVERIFY(waitForApplied());
    QTRY_VERIFY(dock()->row(QStringLiteral("tint")));

    auto *tint = qobject_cast<UniformVectorRow *>(dock()->row(QStringLiteral("tint")));
    QVERIFY(tint);
    QVERIFY(tint->isEnabled());
    QVERIFY(tint->colorButton());             // @color on a vec3 that is not named like one
    QCOMPARE(tint->field(0)->maximum(), 1e6); // no @range: any finite number
    typeInto(tint->field(1), QStringLiteral("0.25"));
    const UniformSnapshot values = programSnapshot();
    QCOMPARE(values.find("tint")->floats[1], 0.25f);

    auto *steps = qobject_cast<UniformIntRow *>(dock()->row(QStringLiteral("steps")));
    QVERIFY(steps);
    QCOMPARE(steps->spinBox()->maximum(), 8);
    steps->spinBox()->setValue(3);
    auto *flip = qobject_cast<UniformBoolRow *>(dock()->row(QStringLiteral("flip")));
    QVERIFY(flip);
    flip->checkBox()->setChecked(true);
    const UniformSnapshot after = programSnapshot();
    QCOMPARE(after.find("steps")->ints[0], 3);
    QCOMPARE(after.find("flip")->ints[0], 1);
}

QTEST_MAIN(TestUniformsDock)
#include "tst_uniformsdock.moc"
