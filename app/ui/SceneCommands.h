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
enum class LightField {
    Position,
    Diffuse,
    Specular,
    Attenuation
};
enum class MaterialField {
    Ka,
    Kd,
    Ks,
    Shininess,
    Preset
};
enum class TransformField {
    Translate,
    Rotate,
    Scale
};

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
    SetLightCommand(SceneAccess access, int index, const PointLight &before, const PointLight &after, LightField field,
                    bool merge = true);
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

// Switches a light on or off: an off light stays in the scene (and the file,
// as "enabled": false) but is not sent to the shader. Never merges.
class SetLightEnabledCommand : public SceneCommand
{
public:
    SetLightEnabledCommand(SceneAccess access, int index, bool on);
    void redo() override;
    void undo() override;

private:
    int m_index = 0;
    bool m_on = true;
};

// Renames a light; an empty name shows as "Light N". Never merges.
class RenameLightCommand : public SceneCommand
{
public:
    RenameLightCommand(SceneAccess access, int index, const std::string &before, const std::string &after);
    void redo() override;
    void undo() override;

private:
    int m_index = 0;
    std::string m_before;
    std::string m_after;
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
