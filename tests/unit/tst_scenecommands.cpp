// The dock edits as QUndoCommands on a plain Scene (no GL, no widgets): each
// redo applies exactly its change, each undo restores the exact Scene, and
// consecutive edits of the same field merge into one step.

#include "ui/scene/SceneCommands.h"

#include <QTest>
#include <QUndoStack>

using namespace phonglab;

namespace {

Scene sampleScene()
{
    Scene scene;
    SceneObject sphere;
    sphere.mesh = QStringLiteral("builtin:sphere");
    SceneObject torus;
    torus.mesh = QStringLiteral("builtin:torus");
    torus.transform.translate = {1.5, 0.0, 0.0};
    scene.objects = {sphere, torus};
    PointLight a;
    a.position = {3, 3, 4};
    PointLight b;
    b.position = {-2, 1, 0};
    b.diffuse = {0.2, 0.4, 1.0};
    scene.lights = {a, b};
    return scene;
}

} // namespace

class TestSceneCommands : public QObject
{
    Q_OBJECT

private:
    Scene m_scene = sampleScene();
    QUndoStack m_stack;

    SceneAccess access()
    {
        return {[this] { return m_scene; }, [this](const Scene &s) { m_scene = s; }};
    }

    // Pushes (redo), checks the result, undoes and redoes: exact round trip.
    void roundTrip(QUndoCommand *command, const std::function<void(Scene &)> &expectedChange)
    {
        const Scene before = m_scene;
        Scene expected = before;
        expectedChange(expected);
        m_stack.push(command);
        QVERIFY(m_scene == expected);
        m_stack.undo();
        QVERIFY(m_scene == before);
        m_stack.redo();
        QVERIFY(m_scene == expected);
    }

private slots:
    void init()
    {
        m_stack.clear();
        m_scene = sampleScene();
    }

    void setLight()
    {
        PointLight after = m_scene.lights[1];
        after.attenuation = {1.0, 0.1, 0.01};
        roundTrip(
            new SetLightCommand(access(), 1, m_scene.lights[1], after, LightField::Attenuation),
            [&](Scene &s) { s.lights[1] = after; });
    }

    void addAndRemoveLight()
    {
        PointLight added;
        added.position = {0, 5, 0};
        roundTrip(new AddLightCommand(access(), added),
                  [&](Scene &s) { s.lights.push_back(added); });
        roundTrip(new RemoveLightCommand(access(), 0, m_scene.lights[0]),
                  [](Scene &s) { s.lights.erase(s.lights.begin()); });
        m_stack.undo();
        m_stack.undo();
        QVERIFY(m_scene == sampleScene());
    }

    // Switching off keeps the light in the scene, flagged; undo switches it back on.
    void switchLightsOffAndOn()
    {
        roundTrip(new SetLightEnabledCommand(access(), 0, false),
                  [](Scene &s) { s.lights[0].enabled = false; });
        QCOMPARE(m_scene.lights.size(), sampleScene().lights.size());
        roundTrip(new SetLightEnabledCommand(access(), 0, true),
                  [](Scene &s) { s.lights[0].enabled = true; });
        m_stack.undo();
        m_stack.undo();
        QVERIFY(m_scene == sampleScene());
        m_stack.redo();
        QVERIFY(!m_scene.lights[0].enabled);
        m_stack.redo();
        QVERIFY(m_scene == sampleScene());
    }

    void renameLight()
    {
        roundTrip(new RenameLightCommand(access(), 0, "", "Key light"),
                  [](Scene &s) { s.lights[0].name = "Key light"; });
        roundTrip(new RenameLightCommand(access(), 0, "Key light", ""),
                  [](Scene &s) { s.lights[0].name.clear(); });
        QCOMPARE(m_stack.count(), 2); // renames never merge
        m_stack.undo();
        QCOMPARE(m_scene.lights[0].name, std::string("Key light"));
        m_stack.undo();
        QVERIFY(m_scene == sampleScene());
    }

    void setAmbient()
    {
        roundTrip(new SetAmbientCommand(access(), m_scene.ambient, {0.05, 0.1, 0.2}), [](Scene &s) {
            s.ambient = {0.05, 0.1, 0.2};
        });
    }

    void setMaterial()
    {
        Material after = m_scene.objects[1].material;
        after.kd = {0.9, 0.1, 0.1};
        roundTrip(new SetMaterialCommand(access(), 1, m_scene.objects[1].material, after,
                                         MaterialField::Kd),
                  [&](Scene &s) { s.objects[1].material = after; });
    }

    void setTransform()
    {
        Transform after = m_scene.objects[0].transform;
        after.scale = {2.0, 0.5, 1.0}; // non-uniform is fine
        roundTrip(new SetTransformCommand(access(), 0, m_scene.objects[0].transform, after,
                                          TransformField::Scale),
                  [&](Scene &s) { s.objects[0].transform = after; });
    }

    // Three position edits of the same light are one undo step; an edit of
    // another field or another light is not merged into it.
    void consecutiveEditsOfOneFieldMerge()
    {
        const Scene original = m_scene;
        for (double x : {1.0, 2.0, 3.0}) {
            PointLight after = m_scene.lights[0];
            after.position.x = x;
            m_stack.push(
                new SetLightCommand(access(), 0, m_scene.lights[0], after, LightField::Position));
        }
        QCOMPARE(m_stack.count(), 1);
        QCOMPARE(m_scene.lights[0].position.x, 3.0);
        PointLight other = m_scene.lights[1];
        other.position.x = 7.0;
        m_stack.push(
            new SetLightCommand(access(), 1, m_scene.lights[1], other, LightField::Position));
        PointLight colour = m_scene.lights[0];
        colour.diffuse = {1, 0, 0};
        m_stack.push(
            new SetLightCommand(access(), 0, m_scene.lights[0], colour, LightField::Diffuse));
        QCOMPARE(m_stack.count(), 3);
        m_stack.undo();
        m_stack.undo();
        m_stack.undo();
        QVERIFY(m_scene == original);
    }

    // A viewport drag is one step of its own, even right after a field edit.
    void dragsDoNotMerge()
    {
        PointLight moved = m_scene.lights[0];
        moved.position.y = 9.0;
        m_stack.push(new SetLightCommand(access(), 0, m_scene.lights[0], moved,
                                         LightField::Position, false));
        moved.position.y = 10.0;
        m_stack.push(new SetLightCommand(access(), 0, m_scene.lights[0], moved,
                                         LightField::Position, false));
        QCOMPARE(m_stack.count(), 2);
    }

    void materialPresetsDoNotMerge()
    {
        Material a = m_scene.objects[0].material;
        a.shininess = 5.0;
        m_stack.push(new SetMaterialCommand(access(), 0, m_scene.objects[0].material, a,
                                            MaterialField::Preset));
        a.shininess = 50.0;
        m_stack.push(new SetMaterialCommand(access(), 0, m_scene.objects[0].material, a,
                                            MaterialField::Preset));
        QCOMPARE(m_stack.count(), 2);
        m_stack.push(new SetMaterialCommand(access(), 0, m_scene.objects[0].material, a,
                                            MaterialField::Shininess));
        a.shininess = 60.0;
        m_stack.push(new SetMaterialCommand(access(), 0, m_scene.objects[0].material, a,
                                            MaterialField::Shininess));
        QCOMPARE(m_stack.count(), 3);
        m_stack.undo();
        QCOMPARE(m_scene.objects[0].material.shininess, 50.0);
    }

    // An undo writes only its own part: a camera moved since stays.
    void undoKeepsTheCamera()
    {
        m_stack.push(new SetAmbientCommand(access(), m_scene.ambient, {0.5, 0.5, 0.5}));
        m_scene.camera.eye = {10, 0, 0};
        m_stack.undo();
        QCOMPARE(m_scene.camera.eye.x, 10.0);
        QCOMPARE(m_scene.ambient, sampleScene().ambient);
    }
};

QTEST_GUILESS_MAIN(TestSceneCommands)
#include "tst_scenecommands.moc"
