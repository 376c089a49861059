#pragma once
#include "core/Scene.h"

#include <QUndoCommand>
#include <functional>
#include <memory>
#include <vector>

namespace phonglab {

// How a command reaches the scene it edits: the window reads and writes the
// viewport's scene (the cheap parameter path), the unit tests a plain Scene.
// write() must only take over lights, ambient, materials and transforms, so
// an undo never moves the camera the user has orbited since.
struct SceneAccess {
    std::function<Scene()> read;
    std::function<void(const Scene &)> write;
};

// Fields a spin-box edit can touch; consecutive edits of the same field of
// the same light / object merge into one undo step.
enum class LightField { Position, Diffuse, Specular, Attenuation };
enum class MaterialField { Ka, Kd, Ks, Shininess, Preset };
enum class TransformField { Translate, Rotate, Scale };

// Base of every dock edit: applies a change to a copy of the scene and
// writes it back. mergeId < 0 never merges (a drag, an add, a preset).
class SceneCommand : public QUndoCommand
{
public:
    int id() const override { return m_mergeId; }

protected:
    SceneCommand(SceneAccess access, const QString &text, int mergeId);
    void change(const std::function<void(Scene &)> &edit) const;

private:
    SceneAccess m_access;
    int m_mergeId = -1;
};

class SetLightCommand : public SceneCommand
{
public:
    // merge: false for a viewport drag, which is one step on its own.
    SetLightCommand(SceneAccess access, int index, const PointLight &before, const PointLight &after,
                    LightField field, bool merge = true);
    void redo() override;
    void undo() override;
    bool mergeWith(const QUndoCommand *other) override;

private:
    int m_index = 0;
    PointLight m_before;
    PointLight m_after;
};

class AddLightCommand : public SceneCommand
{
public:
    AddLightCommand(SceneAccess access, const PointLight &light);
    void redo() override;
    void undo() override;

private:
    PointLight m_light;
};

class RemoveLightCommand : public SceneCommand
{
public:
    RemoveLightCommand(SceneAccess access, int index, const PointLight &light);
    void redo() override;
    void undo() override;

private:
    int m_index = 0;
    PointLight m_light; // put back at m_index on undo
};

// Switched-off lights. The scene format has no "enabled" flag, so a light
// that is off leaves the scene (and the shader) and waits here, in the
// Lights dock, until it is switched on again; it is not saved with the scene.
using LightShelf = std::vector<PointLight>;

class DisableLightCommand : public SceneCommand
{
public:
    DisableLightCommand(SceneAccess access, std::shared_ptr<LightShelf> shelf, int index, const PointLight &light);
    void redo() override;
    void undo() override;

private:
    std::shared_ptr<LightShelf> m_shelf;
    int m_index = 0;
    PointLight m_light;
};

// Puts shelf entry `shelfIndex` back into the scene as its last light.
class EnableLightCommand : public SceneCommand
{
public:
    EnableLightCommand(SceneAccess access, std::shared_ptr<LightShelf> shelf, int shelfIndex);
    void redo() override;
    void undo() override;

private:
    std::shared_ptr<LightShelf> m_shelf;
    int m_shelfIndex = 0;
    PointLight m_light;
};

class SetAmbientCommand : public SceneCommand
{
public:
    SetAmbientCommand(SceneAccess access, const glm::dvec3 &before, const glm::dvec3 &after);
    void redo() override;
    void undo() override;
    bool mergeWith(const QUndoCommand *other) override;

private:
    glm::dvec3 m_before{0.0};
    glm::dvec3 m_after{0.0};
};

class SetMaterialCommand : public SceneCommand
{
public:
    SetMaterialCommand(SceneAccess access, int object, const Material &before, const Material &after,
                       MaterialField field);
    void redo() override;
    void undo() override;
    bool mergeWith(const QUndoCommand *other) override;

private:
    int m_object = 0;
    Material m_before;
    Material m_after;
};

class SetTransformCommand : public SceneCommand
{
public:
    SetTransformCommand(SceneAccess access, int object, const Transform &before, const Transform &after,
                        TransformField field);
    void redo() override;
    void undo() override;
    bool mergeWith(const QUndoCommand *other) override;

private:
    int m_object = 0;
    Transform m_before;
    Transform m_after;
};

} // namespace phonglab
