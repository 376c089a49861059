#include "SceneCommands.h"

#include <QCoreApplication>

namespace phonglab {

namespace {

// Merge ids: one range per command type, then the index and the field, so
// QUndoStack only offers mergeWith() for the same field of the same item.
constexpr int kFieldsPerItem = 8;
constexpr int kItemsPerKind = 1 << 16;

int mergeIdFor(int kind, int index, int field)
{
    return kind * kItemsPerKind * kFieldsPerItem + index * kFieldsPerItem + field;
}

// The undo steps' names, as the Edit menu shows them.
struct CommandWords {
    Q_DECLARE_TR_FUNCTIONS(SceneCommands)
};

} // namespace

SceneCommand::SceneCommand(SceneAccess access, const QString &text, int mergeId)
    : m_access(std::move(access))
    , m_mergeId(mergeId)
{
    setText(text);
}

void SceneCommand::change(const std::function<void(Scene &)> &edit) const
{
    Scene scene = m_access.read();
    edit(scene);
    m_access.write(scene);
}

SetLightCommand::SetLightCommand(SceneAccess access, int index, const PointLight &before,
                                 const PointLight &after, LightField field, bool merge)
    : SetPropertyCommand(std::move(access), CommandWords::tr("Edit light %1").arg(index + 1),
                         merge ? mergeIdFor(1, index, int(field)) : -1, index, before, after)
{
}

SetLightEnabledCommand::SetLightEnabledCommand(SceneAccess access, int index, bool on)
    : SetPropertyCommand(
        std::move(access),
        (on ? CommandWords::tr("Switch on light %1") : CommandWords::tr("Switch off light %1"))
            .arg(index + 1),
        -1, index, !on, on)
{
}

RenameLightCommand::RenameLightCommand(SceneAccess access, int index, const std::string &before,
                                       const std::string &after)
    : SetPropertyCommand(std::move(access), CommandWords::tr("Rename light %1").arg(index + 1), -1,
                         index, before, after)
{
}

SetAmbientCommand::SetAmbientCommand(SceneAccess access, const glm::dvec3 &before,
                                     const glm::dvec3 &after)
    : SetPropertyCommand(std::move(access), CommandWords::tr("Edit ambient light"),
                         mergeIdFor(2, 0, 0), 0, before, after)
{
}

SetMaterialCommand::SetMaterialCommand(SceneAccess access, int object, const Material &before,
                                       const Material &after, MaterialField field)
    : SetPropertyCommand(std::move(access), CommandWords::tr("Edit material"),
                         field == MaterialField::Preset ? -1 : mergeIdFor(3, object, int(field)),
                         object, before, after)
{
}

SetTransformCommand::SetTransformCommand(SceneAccess access, int object, const Transform &before,
                                         const Transform &after, TransformField field)
    : SetPropertyCommand(std::move(access), CommandWords::tr("Move object"),
                         mergeIdFor(4, object, int(field)), object, before, after)
{
}

AddLightCommand::AddLightCommand(SceneAccess access, const PointLight &light)
    : SceneCommand(std::move(access), CommandWords::tr("Add light"), -1)
    , m_light(light)
{
}

void AddLightCommand::redo()
{
    change([this](Scene &scene) { scene.lights.push_back(m_light); });
}

void AddLightCommand::undo()
{
    change([](Scene &scene) { scene.lights.pop_back(); });
}

RemoveLightCommand::RemoveLightCommand(SceneAccess access, int index, const PointLight &light)
    : SceneCommand(std::move(access), CommandWords::tr("Remove light %1").arg(index + 1), -1)
    , m_index(index)
    , m_light(light)
{
}

void RemoveLightCommand::redo()
{
    change([this](Scene &scene) { scene.lights.erase(scene.lights.begin() + m_index); });
}

void RemoveLightCommand::undo()
{
    change([this](Scene &scene) { scene.lights.insert(scene.lights.begin() + m_index, m_light); });
}

} // namespace phonglab
