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

QString tr(const char *text)
{
    return QCoreApplication::translate("SceneCommands", text);
}

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

SetLightCommand::SetLightCommand(SceneAccess access, int index, const PointLight &before, const PointLight &after,
                                 LightField field, bool merge)
    : SceneCommand(std::move(access), tr("Edit light %1").arg(index + 1), merge ? mergeIdFor(1, index, int(field)) : -1)
    , m_index(index)
    , m_before(before)
    , m_after(after)
{
}

void SetLightCommand::redo()
{
    change([this](Scene &scene) { scene.lights.at(m_index) = m_after; });
}

void SetLightCommand::undo()
{
    change([this](Scene &scene) { scene.lights.at(m_index) = m_before; });
}

bool SetLightCommand::mergeWith(const QUndoCommand *other)
{
    m_after = static_cast<const SetLightCommand *>(other)->m_after;
    return true;
}

AddLightCommand::AddLightCommand(SceneAccess access, const PointLight &light)
    : SceneCommand(std::move(access), tr("Add light"), -1)
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
    : SceneCommand(std::move(access), tr("Remove light %1").arg(index + 1), -1)
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

SetLightEnabledCommand::SetLightEnabledCommand(SceneAccess access, int index, bool on)
    : SceneCommand(std::move(access), (on ? tr("Switch on light %1") : tr("Switch off light %1")).arg(index + 1), -1)
    , m_index(index)
    , m_on(on)
{
}

void SetLightEnabledCommand::redo()
{
    change([this](Scene &scene) { scene.lights.at(m_index).enabled = m_on; });
}

void SetLightEnabledCommand::undo()
{
    change([this](Scene &scene) { scene.lights.at(m_index).enabled = !m_on; });
}

RenameLightCommand::RenameLightCommand(SceneAccess access, int index, const std::string &before,
                                       const std::string &after)
    : SceneCommand(std::move(access), tr("Rename light %1").arg(index + 1), -1)
    , m_index(index)
    , m_before(before)
    , m_after(after)
{
}

void RenameLightCommand::redo()
{
    change([this](Scene &scene) { scene.lights.at(m_index).name = m_after; });
}

void RenameLightCommand::undo()
{
    change([this](Scene &scene) { scene.lights.at(m_index).name = m_before; });
}

SetAmbientCommand::SetAmbientCommand(SceneAccess access, const glm::dvec3 &before, const glm::dvec3 &after)
    : SceneCommand(std::move(access), tr("Edit ambient light"), mergeIdFor(2, 0, 0))
    , m_before(before)
    , m_after(after)
{
}

void SetAmbientCommand::redo()
{
    change([this](Scene &scene) { scene.ambient = m_after; });
}

void SetAmbientCommand::undo()
{
    change([this](Scene &scene) { scene.ambient = m_before; });
}

bool SetAmbientCommand::mergeWith(const QUndoCommand *other)
{
    m_after = static_cast<const SetAmbientCommand *>(other)->m_after;
    return true;
}

SetMaterialCommand::SetMaterialCommand(SceneAccess access, int object, const Material &before, const Material &after,
                                       MaterialField field)
    : SceneCommand(std::move(access), tr("Edit material"),
                   field == MaterialField::Preset ? -1 : mergeIdFor(3, object, int(field)))
    , m_object(object)
    , m_before(before)
    , m_after(after)
{
}

void SetMaterialCommand::redo()
{
    change([this](Scene &scene) { scene.objects.at(m_object).material = m_after; });
}

void SetMaterialCommand::undo()
{
    change([this](Scene &scene) { scene.objects.at(m_object).material = m_before; });
}

bool SetMaterialCommand::mergeWith(const QUndoCommand *other)
{
    m_after = static_cast<const SetMaterialCommand *>(other)->m_after;
    return true;
}

SetTransformCommand::SetTransformCommand(SceneAccess access, int object, const Transform &before,
                                         const Transform &after, TransformField field)
    : SceneCommand(std::move(access), tr("Move object"), mergeIdFor(4, object, int(field)))
    , m_object(object)
    , m_before(before)
    , m_after(after)
{
}

void SetTransformCommand::redo()
{
    change([this](Scene &scene) { scene.objects.at(m_object).transform = m_after; });
}

void SetTransformCommand::undo()
{
    change([this](Scene &scene) { scene.objects.at(m_object).transform = m_before; });
}

bool SetTransformCommand::mergeWith(const QUndoCommand *other)
{
    m_after = static_cast<const SetTransformCommand *>(other)->m_after;
    return true;
}

} // namespace phonglab
