#include "UniformOwner.h"

#include <QCoreApplication>
#include <QStringList>

namespace phonglab {

UniformOwner uniformOwner(const QString &name)
{
    // Must match what Renderer::drawObjects / uploadLights set.
    static const QStringList renderer = {
        QStringLiteral("modelViewMatrix"), QStringLiteral("normalMatrix"),
        QStringLiteral("projectionMatrix"), QStringLiteral("viewMatrix")};
    static const QStringList scene = {QStringLiteral("Ia"),
                                      QStringLiteral("ka"),
                                      QStringLiteral("kd"),
                                      QStringLiteral("ks"),
                                      QStringLiteral("shininess"),
                                      QStringLiteral("lightCount"),
                                      QStringLiteral("lightPosition"),
                                      QStringLiteral("Id"),
                                      QStringLiteral("Is"),
                                      QStringLiteral("attenuation")};
    if (renderer.contains(name))
        return UniformOwner::Renderer;
    if (scene.contains(name))
        return UniformOwner::Scene;
    return UniformOwner::User;
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
