#include "BindingConflicts.h"

#include <QCoreApplication>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct BindingConflictsWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::BindingConflicts)
};

namespace {

QString rgb(const glm::dvec3 &c)
{
    return QStringLiteral("(%1, %2, %3)").arg(c.x).arg(c.y).arg(c.z);
}

} // namespace

QStringList bindingConflicts(const ProgramBindings &bindings, const Scene &scene)
{
    QStringList out;
    for (const VariableBinding *b : bindings.bound(BindingMeaning::LightColor)) {
        int light = 0;
        for (const PointLight &l : scene.lights) {
            const bool held =
                b->variable.isArray ? light < b->variable.arraySize : light == b->lightIndex;
            if (l.enabled && held && l.diffuse != l.specular)
                out << BindingConflictsWords::tr(
                           "%1 is one colour for Id and Is (light-color), but light %2 of the "
                           "scene has Id = %3 and Is = %4: give the light one colour in the "
                           "scene, or bind %1 to Id or Is")
                           .arg(b->variable.name)
                           .arg(light)
                           .arg(rgb(l.diffuse), rgb(l.specular));
            if (l.enabled)
                ++light;
        }
    }
    for (const VariableBinding *b : bindings.bound(BindingMeaning::MaterialColor)) {
        for (std::size_t i = 0; i < scene.objects.size(); ++i) {
            const Material &m = scene.objects[i].material;
            if (m.ka != m.kd)
                out << BindingConflictsWords::tr(
                           "%1 is one colour for ka and kd (material-color), but object %2 of "
                           "the scene has ka = %3 and kd = %4: give the material one colour in "
                           "the scene, or bind %1 to ka or kd")
                           .arg(b->variable.name)
                           .arg(i)
                           .arg(rgb(m.ka), rgb(m.kd));
        }
    }
    return out;
}

} // namespace phonglab
