#pragma once
#include "core/scene/Scene.h"

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

// One property of the scene set from `before` to `after`; undo sets
// `before` again, and a merge keeps the first `before` and the last `after`.
// `Property` says where the value lives: Property::Value, and
// Property::at(scene, index) giving a reference to it.
template <typename Property> class SetPropertyCommand : public SceneCommand
{
public:
    using Value = typename Property::Value;

    SetPropertyCommand(SceneAccess access, const QString &text, int mergeId, int index,
                       Value before, Value after)
        : SceneCommand(std::move(access), text, mergeId)
        , m_index(index)
        , m_before(std::move(before))
        , m_after(std::move(after))
    {
    }
    void redo() override
    {
        change([this](Scene &scene) { Property::at(scene, m_index) = m_after; });
    }
    void undo() override
    {
        change([this](Scene &scene) { Property::at(scene, m_index) = m_before; });
    }
    // Only offered for the same merge id, which names the command's type.
    bool mergeWith(const QUndoCommand *other) override
    {
        m_after = static_cast<const SetPropertyCommand *>(other)->m_after;
        return true;
    }

private:
    int m_index = 0;
    Value m_before;
    Value m_after;
};

// Where each property the docks edit lives.
struct LightProperty {
    using Value = PointLight;
    static Value &at(Scene &scene, int i) { return scene.lights.at(i); }
};
struct LightEnabledProperty {
    using Value = bool;
    static Value &at(Scene &scene, int i) { return scene.lights.at(i).enabled; }
};
struct LightNameProperty {
    using Value = std::string;
    static Value &at(Scene &scene, int i) { return scene.lights.at(i).name; }
};
struct AmbientProperty {
    using Value = glm::dvec3;
    static Value &at(Scene &scene, int) { return scene.ambient; }
};
struct MaterialProperty {
    using Value = Material;
    static Value &at(Scene &scene, int i) { return scene.objects.at(i).material; }
};
struct TransformProperty {
    using Value = Transform;
    static Value &at(Scene &scene, int i) { return scene.objects.at(i).transform; }
};

// The dock edits by name: each only says its undo text and how it merges.
class SetLightCommand : public SetPropertyCommand<LightProperty>
{
public:
    // merge: false for a viewport drag, which is one step on its own.
    SetLightCommand(SceneAccess access, int index, const PointLight &before,
                    const PointLight &after, LightField field, bool merge = true);
};

// Switches a light on or off: an off light stays in the scene (and the file,
// as "enabled": false) but is not sent to the shader. Never merges.
class SetLightEnabledCommand : public SetPropertyCommand<LightEnabledProperty>
{
public:
    SetLightEnabledCommand(SceneAccess access, int index, bool on);
};

// Renames a light; an empty name shows as "Light N". Never merges.
class RenameLightCommand : public SetPropertyCommand<LightNameProperty>
{
public:
    RenameLightCommand(SceneAccess access, int index, const std::string &before,
                       const std::string &after);
};

class SetAmbientCommand : public SetPropertyCommand<AmbientProperty>
{
public:
    SetAmbientCommand(SceneAccess access, const glm::dvec3 &before, const glm::dvec3 &after);
};

class SetMaterialCommand : public SetPropertyCommand<MaterialProperty>
{
public:
    SetMaterialCommand(SceneAccess access, int object, const Material &before,
                       const Material &after, MaterialField field);
};

class SetTransformCommand : public SetPropertyCommand<TransformProperty>
{
public:
    SetTransformCommand(SceneAccess access, int object, const Transform &before,
                        const Transform &after, TransformField field);
};

// Adding and removing change the list itself.
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

} // namespace phonglab
