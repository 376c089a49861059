// The scene-editing docks end to end on a real GL context (llvmpipe under
// Xvfb): a material edit changes the frame and still matches the CPU
// reference, a light placed through the dock stays put in world space while
// the camera orbits, undo gives back the exact frame, bad values are refused
// at the field, and a marker drag is one undo step.

#include "RenderCheck.h"
#include "ResultChecks.h"
#include "TestPaths.h"
#include "UiTestWindow.h"
#include "core/reference/MeshRaycaster.h"
#include "core/reference/PhongReference.h"
#include "core/scene/MaterialPresets.h"
#include "render/gl/QtImages.h"
#include "ui/scene/LightsDock.h"
#include "ui/scene/MaterialDock.h"
#include "ui/scene/ObjectDock.h"
#include "ui/scene/SceneEditDockSet.h"
#include "ui/scene/Vec3Field.h"
#include "ui/viewport/Viewport.h"
#include "ui/window/MainWindow.h"
#include "ui/window/SceneDocument.h"
#include "ui/window/WindowImage.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLineEdit>
#include <QListWidget>
#include <QTest>
#include <QUndoStack>
#include <memory>

using namespace phonglab;

namespace {

constexpr int kGridStep = 6;   // pixels compared with the reference, every kGridStep-th
constexpr int kInteriorPx = 2; // skip pixels this near the silhouette

QString sphereScenePath()
{
    return test::testDataPath(QStringLiteral("scenes/gl_sphere_one_light.json"));
}

void type(Vec3Field *field, const glm::dvec3 &value)
{
    for (int axis = 0; axis < 3; ++axis)
        field->component(axis)->setText(QString::number(value[axis], 'g', 17));
    field->commit();
}

bool interior(const ReferenceImage &ref, int x, int y)
{
    for (int dy = -kInteriorPx; dy <= kInteriorPx; ++dy)
        for (int dx = -kInteriorPx; dx <= kInteriorPx; ++dx) {
            const int px = x + dx, py = y + dy;
            if (px < 0 || py < 0 || px >= ref.width || py >= ref.height || !ref.covered(px, py))
                return false;
        }
    return true;
}

// The grabbed viewport against the ray-cast reference of the same scene at
// the same size: covered interior pixels within kMaxErrorSteps. Returns a
// description of the first mismatch, or empty.
QString compareWithReference(const QImage &grab, const Scene &scene)
{
    const auto ref = raycastScene(scene, grab.width(), grab.height());
    if (!ref)
        return QStringLiteral("no reference");
    const QImage expected = toQImage(ref->toImage(scene.background));
    const QImage actual = grab.convertToFormat(QImage::Format_RGB32);
    int compared = 0;
    for (int y = 0; y < ref->height; y += kGridStep)
        for (int x = 0; x < ref->width; x += kGridStep) {
            if (!interior(*ref, x, y))
                continue;
            ++compared;
            const QRgb a = actual.pixel(x, y), e = expected.pixel(x, y);
            const int err = std::max({std::abs(qRed(a) - qRed(e)), std::abs(qGreen(a) - qGreen(e)),
                                      std::abs(qBlue(a) - qBlue(e))});
            if (err > test::kMaxErrorSteps)
                return QStringLiteral("pixel (%1, %2): %3 vs reference %4")
                    .arg(x)
                    .arg(y)
                    .arg(QColor(a).name(), QColor(e).name());
        }
    return compared > 50 ? QString() : QStringLiteral("only %1 pixels compared").arg(compared);
}

} // namespace

class TestLightsDock : public test::WindowPerTest
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();

    void kdEditChangesFrameAndMatchesReference();
    void dockLightStaysFixedInWorldWhileOrbiting();
    void undoRestoresTheExactFrame();
    void badValuesAreRefused();
    void addAndRemoveLights();
    void markerDragIsOneUndoStep();
    void switchedOffLightIsNotRendered();
    void renameLightThroughNameField();
    void shortcutsUndoAndRedo();
    void headlightFollowsTheCamera();
    void presetsAndShininess();
    void exportImageAtAnySize();

private:
    SceneEditDockSet *docks() const { return m_window->editDocks(); }
    void orbit(QPoint by);
    void verifyMatchesReference();
};

void TestLightsDock::initTestCase()
{
    test::useTestSettingsAndExactFrames();
}

void TestLightsDock::init()
{
    openWindow(sphereScenePath(), {900, 600});
    if (QTest::currentTestFailed())
        return;
    viewport()->drawing().setShowLightMarkers(false); // the reference has no markers
}

void TestLightsDock::orbit(QPoint by)
{
    const QPoint start = viewport()->rect().topLeft() + QPoint(10, 10);
    QTest::mousePress(viewport(), Qt::LeftButton, Qt::NoModifier, start);
    for (int step = 1; step <= 4; ++step)
        QTest::mouseMove(viewport(), start + by * step / 4);
    QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::NoModifier, start + by);
}

void TestLightsDock::verifyMatchesReference()
{
    const Scene scene = viewport()->currentScene();
    const QString mismatch = compareWithReference(frame(), scene);
    QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));
    const test::RenderCheck check = test::checkAgainstReference(scene);
    QVERIFY2(check.matches(),
             qPrintable(check.error
                        + QStringLiteral(" psnr %1 max %2")
                              .arg(check.comparison.psnr)
                              .arg(check.comparison.maxError)));
}

void TestLightsDock::kdEditChangesFrameAndMatchesReference()
{
    const QImage before = frame();
    MaterialDock *panel = docks()->materialDock();
    type(panel->field(MaterialField::Kd), {0.1, 0.8, 0.3});
    QCOMPARE(viewport()->currentScene().objects[0].material.kd, glm::dvec3(0.1, 0.8, 0.3));
    const QImage after = frame();
    QVERIFY(after != before);
    verifyMatchesReference();
    // For a look at the docks: PHONGLAB_TEST_ARTIFACTS=<folder>.
    const QString artifacts = qEnvironmentVariable("PHONGLAB_TEST_ARTIFACTS");
    if (!artifacts.isEmpty() && QDir().mkpath(artifacts)) {
        for (QDockWidget *dock :
             {static_cast<QDockWidget *>(docks()->lightsDock()), static_cast<QDockWidget *>(panel),
              static_cast<QDockWidget *>(docks()->objectDock())}) {
            dock->raise();
            windowImage(*m_window).save(
                QDir(artifacts).filePath(dock->objectName() + QStringLiteral(".png")));
        }
    }
}

void TestLightsDock::dockLightStaysFixedInWorldWhileOrbiting()
{
    LightsDock *dock = docks()->lightsDock();
    dock->selectLight(0);
    const glm::dvec3 placed{-3.0, 2.0, 2.5};
    type(dock->field(LightField::Position), placed);
    QCOMPARE(viewport()->currentScene().lights[0].position, placed);
    verifyMatchesReference();

    const QImage first = frame();
    orbit({120, 30});
    QCOMPARE(viewport()->currentScene().lights[0].position, placed);
    QVERIFY(frame() != first); // the camera did move
    verifyMatchesReference();
    orbit({-260, -10});
    QCOMPARE(viewport()->currentScene().lights[0].position, placed);
    verifyMatchesReference();
}

void TestLightsDock::undoRestoresTheExactFrame()
{
    const QImage original = frame();
    const Scene scene = viewport()->currentScene();
    QUndoStack *stack = docks()->undoStack();
    type(docks()->materialDock()->field(MaterialField::Kd), {0.9, 0.9, 0.1});
    type(docks()->lightsDock()->field(LightField::Diffuse), {0.3, 0.3, 1.0});
    type(docks()->objectDock()->field(TransformField::Scale), {1.5, 0.5, 1.0});
    QCOMPARE(stack->count(), 3);
    const QImage edited = frame();
    QVERIFY(edited != original);
    stack->undo();
    stack->undo();
    stack->undo();
    QCOMPARE(viewport()->currentScene(), scene);
    QVERIFY(frame() == original);
    stack->redo();
    stack->redo();
    stack->redo();
    QVERIFY(frame() == edited);
}

void TestLightsDock::badValuesAreRefused()
{
    const Scene scene = savedScene();
    QUndoStack *stack = docks()->undoStack();
    struct Case {
        Vec3Field *field;
        glm::dvec3 value;
    };
    const double nan = std::nan(""), inf = INFINITY;
    const QList<Case> cases = {
        {docks()->lightsDock()->field(LightField::Position), {nan, 0, 0}},
        {docks()->materialDock()->field(MaterialField::Kd), {0.5, inf, 0.5}},
        {docks()->materialDock()->field(MaterialField::Ks), {-0.1, 0.5, 0.5}}, // out of range
        {docks()->objectDock()->field(TransformField::Scale), {1.0, 0.0, 1.0}},
        {docks()->lightsDock()->field(LightField::Attenuation), {0.0, 0.0, 0.0}},
        {docks()->lightsDock()->ambientField(), {0.2, -inf, 0.2}},
    };
    for (const Case &c : cases) {
        const glm::dvec3 shown = c.field->value();
        type(c.field, c.value);
        QVERIFY2(!c.field->errorText().isEmpty(), "no reason shown");
        QCOMPARE(c.field->value(), shown); // the last valid value stays...
        QCOMPARE(c.field->component(1)->text(),
                 QLocale().toString(shown.y, 'g', 6)); // ...in the field too
        QCOMPARE(stack->count(), 0);
        QCOMPARE(savedScene(), scene); // a reason shown may narrow the view, not change the scene
    }
    // A good value afterwards is taken and clears the reason.
    Vec3Field *attenuation = docks()->lightsDock()->field(LightField::Attenuation);
    type(attenuation, {1.0, 0.0, 0.1});
    QVERIFY(attenuation->errorText().isEmpty());
    QCOMPARE(viewport()->currentScene().lights[0].attenuation, glm::dvec3(1.0, 0.0, 0.1));
}

void TestLightsDock::addAndRemoveLights()
{
    LightsDock *dock = docks()->lightsDock();
    for (int i = 1; i < kMaxLights + 2; ++i)
        dock->addLight();
    QCOMPARE(int(viewport()->currentScene().lights.size()), kMaxLights); // no more than 8
    dock->selectLight(2);
    dock->removeSelectedLight();
    QCOMPARE(int(viewport()->currentScene().lights.size()), kMaxLights - 1);
    while (docks()->undoStack()->canUndo())
        docks()->undoStack()->undo();
    QCOMPARE(int(viewport()->currentScene().lights.size()), 1);
}

void TestLightsDock::markerDragIsOneUndoStep()
{
    viewport()->drawing().setShowLightMarkers(true);
    // The file's light sits level with the eye (view depth 0): bring it into view first.
    type(docks()->lightsDock()->field(LightField::Position), {1.5, 1.0, 1.0});
    const int stepsBefore = docks()->undoStack()->count();
    const Scene scene = viewport()->currentScene();
    const Camera camera = viewport()->camera();
    const glm::dvec3 light = scene.lights[0].position;
    const double aspect = double(viewport()->width()) / viewport()->height();
    const glm::dvec4 clip =
        camera.projectionMatrix(aspect) * camera.viewMatrix() * glm::dvec4(light, 1.0);
    const QPoint marker(qRound((clip.x / clip.w + 1) * 0.5 * viewport()->width()),
                        qRound((1 - clip.y / clip.w) * 0.5 * viewport()->height()));
    QTest::mousePress(viewport(), Qt::LeftButton, Qt::NoModifier, marker);
    for (int step = 1; step <= 5; ++step)
        QTest::mouseMove(viewport(), marker + QPoint(-8 * step, 6 * step));
    QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::NoModifier, marker + QPoint(-40, 30));

    QCOMPARE(viewport()->camera(), camera); // grabbing a marker does not orbit
    QCOMPARE(docks()->undoStack()->count(), stepsBefore + 1);
    const glm::dvec3 moved = viewport()->currentScene().lights[0].position;
    QVERIFY(glm::length(moved - light) > 0.1);
    // Parallel to the view plane: the depth along the view direction is kept.
    const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
    QVERIFY(std::abs(glm::dot(moved - light, forward)) < 1e-6 * glm::length(light));
    QCOMPARE(docks()->lightsDock()->field(LightField::Position)->value(), moved);
    docks()->undoStack()->undo();
    QCOMPARE(viewport()->currentScene(), scene);
}

void TestLightsDock::exportImageAtAnySize()
{
    const QString path = QDir::temp().filePath(QStringLiteral("phonglab-export-test.png"));
    QString error;
    QVERIFY_OK(m_window->document()->exportImage(path, {333, 211}));
    const QImage image(path);
    QCOMPARE(image.size(), QSize(333, 211));
    QFile::remove(path);
    const QString mismatch = compareWithReference(image, viewport()->currentScene());
    QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));
}

void TestLightsDock::switchedOffLightIsNotRendered()
{
    const QImage lit = frame();
    LightsDock *dock = docks()->lightsDock();
    QVERIFY(dock->setLightEnabled(0, false));
    QCOMPARE(viewport()->currentScene().lights.size(), size_t(1)); // stays in the scene...
    QVERIFY(!viewport()->currentScene().lights[0].enabled);        // ...switched off
    QCOMPARE(dock->switchedOffCount(), 1);
    QVERIFY(frame() != lit);
    verifyMatchesReference();                  // ambient only: the CPU reference skips it too
    QVERIFY(!dock->setLightEnabled(0, false)); // already off
    QVERIFY(dock->setLightEnabled(0, true));
    QVERIFY(frame() == lit);
    docks()->undoStack()->undo();
    QCOMPARE(dock->switchedOffCount(), 1);
    docks()->undoStack()->undo();
    QVERIFY(frame() == lit);
    QCOMPARE(dock->switchedOffCount(), 0);

    // The list's check box is the same switch, and the list shows names.
    auto *list = dock->findChild<QListWidget *>();
    QVERIFY(list);
    list->item(0)->setCheckState(Qt::Unchecked);
    QVERIFY(!viewport()->currentScene().lights[0].enabled);
    QVERIFY(dock->renameLight(0, QStringLiteral("Key")));
    QCOMPARE(list->item(0)->text(), QStringLiteral("Key"));
    QCOMPARE(list->item(0)->checkState(), Qt::Unchecked);
    docks()->undoStack()->undo();
    docks()->undoStack()->undo();
    QCOMPARE(list->item(0)->text(), QStringLiteral("Light 1"));
    QCOMPARE(list->item(0)->checkState(), Qt::Checked);

    // One light on, one off: the image is that of the enabled one alone.
    dock->addLight();
    QVERIFY(frame() != lit);
    QVERIFY(dock->setLightEnabled(1, false));
    QVERIFY(frame() == lit);
    verifyMatchesReference();

    // The 8-light limit counts switched-off lights too.
    for (int i = 2; i < kMaxLights; ++i)
        dock->addLight();
    QCOMPARE(int(viewport()->currentScene().lights.size()), kMaxLights);
    dock->addLight();
    QCOMPARE(int(viewport()->currentScene().lights.size()), kMaxLights);
}

void TestLightsDock::renameLightThroughNameField()
{
    LightsDock *dock = docks()->lightsDock();
    dock->selectLight(0);
    QCOMPARE(dock->displayName(0), QStringLiteral("Light 1"));
    QLineEdit *name = dock->nameField();
    name->setText(QStringLiteral("Key light"));
    emit name->editingFinished();
    QCOMPARE(viewport()->currentScene().lights[0].name, std::string("Key light"));
    QCOMPARE(dock->displayName(0), QStringLiteral("Key light"));
    docks()->undoStack()->undo();
    QVERIFY(viewport()->currentScene().lights[0].name.empty());
    QCOMPARE(dock->displayName(0), QStringLiteral("Light 1"));
    QVERIFY(name->text().isEmpty());
    docks()->undoStack()->redo();
    QCOMPARE(name->text(), QStringLiteral("Key light"));
}

void TestLightsDock::shortcutsUndoAndRedo()
{
    const QImage original = frame();
    type(docks()->materialDock()->field(MaterialField::Ks), {0.1, 0.1, 0.1});
    const QImage edited = frame();
    QVERIFY(edited != original);
    // Xvfb has no window manager to activate the window, so key presses do
    // not reach window shortcuts: find the Edit menu's actions by their keys.
    QAction *undo = nullptr, *redo = nullptr;
    for (QAction *action : m_window->findChildren<QAction *>()) {
        if (action->shortcut() == QKeySequence(QStringLiteral("Ctrl+Z")))
            undo = action;
        if (action->shortcut() == QKeySequence(QStringLiteral("Ctrl+Shift+Z")))
            redo = action;
    }
    QVERIFY(undo && redo);
    undo->trigger();
    QVERIFY(frame() == original);
    redo->trigger();
    QVERIFY(frame() == edited);
}

// The headlight is drawn at the eye wherever the camera goes, yet never
// enters the scene model.
void TestLightsDock::headlightFollowsTheCamera()
{
    const Scene scene = viewport()->currentScene();
    const QImage without = frame();
    docks()->lightsDock()->headlightBox()->setChecked(true);
    QCOMPARE(viewport()->currentScene(), scene);
    QVERIFY(frame() != without);
    for (const QPoint by : {QPoint(0, 0), QPoint(150, 40)}) {
        orbit(by);
        const Scene rendered = viewport()->renderedScene();
        QCOMPARE(int(rendered.lights.size()), 2);
        QCOMPARE(rendered.lights.back().position, viewport()->camera().eye);
        const QString mismatch = compareWithReference(frame(), rendered);
        QVERIFY2(mismatch.isEmpty(), qPrintable(mismatch));
    }
    docks()->lightsDock()->headlightBox()->setChecked(false);
    QCOMPARE(int(viewport()->renderedScene().lights.size()), 1);
}

// A preset is one step; shininess steps merge; a saved preset comes back
// (QSettings in test mode) and applies the material it was saved from.
void TestLightsDock::presetsAndShininess()
{
    MaterialDock *panel = docks()->materialDock();
    QUndoStack *stack = docks()->undoStack();
    const Material original = viewport()->currentScene().objects[0].material;
    const QList<MaterialPreset> builtins = builtinMaterialPresets();
    const int chalk = panel->presetBox()->findText(QStringLiteral("Chalk"));
    QVERIFY(chalk >= 0);
    panel->applyMaterialPreset(chalk);
    QCOMPARE(viewport()->currentScene().objects[0].material, builtins[chalk].material);
    for (double n : {5.0, 6.0, 7.0})
        panel->shininessBox()->setValue(n);
    QCOMPARE(viewport()->currentScene().objects[0].material.shininess, 7.0);
    QCOMPARE(stack->count(), 2);
    panel->saveAsPreset(QStringLiteral("test chalk 7"));
    stack->undo();
    stack->undo();
    QCOMPARE(viewport()->currentScene().objects[0].material, original);
    const int saved = panel->presetBox()->findText(QStringLiteral("test chalk 7"));
    QVERIFY(saved >= int(builtins.size()));
    panel->applyMaterialPreset(saved);
    QCOMPARE(viewport()->currentScene().objects[0].material.shininess, 7.0);
    QCOMPARE(viewport()->currentScene().objects[0].material.kd, builtins[chalk].material.kd);
}

QTEST_MAIN(TestLightsDock)
#include "tst_lightsdock.moc"
