#include "core/program/UniformOwner.h"

#include <QCoreApplication>

namespace phonglab {

UniformOwner uniformOwner(std::optional<BindingMeaning> meaning)
{
    if (!meaning)
        return UniformOwner::User;
    switch (*meaning) {
    case BindingMeaning::Model:
    case BindingMeaning::View:
    case BindingMeaning::Projection:
    case BindingMeaning::ModelView:
    case BindingMeaning::ModelViewProjection:
    case BindingMeaning::ViewProjection:
    case BindingMeaning::NormalMatrix:
    case BindingMeaning::ModelNormalMatrix:
    case BindingMeaning::Eye: return UniformOwner::Renderer;
    default: return UniformOwner::Scene;
    }
}

QString uniformOwnerNote(UniformOwner owner)
{
    switch (owner) {
    case UniformOwner::Renderer:
        return QCoreApplication::translate("UniformOwner", "set by the renderer");
    case UniformOwner::Scene:
        return QCoreApplication::translate("UniformOwner",
                                           "set by the scene (Material/Lights docks)");
    case UniformOwner::User: break;
    }
    return {};
}

} // namespace phonglab
