#include "SilentTerms.h"

#include <QCoreApplication>

#include <algorithm>

namespace phonglab {

namespace {

struct SilentTermsWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::SilentTerms)
};

bool isZero(const glm::dvec3 &v)
{
    return v.x == 0.0 && v.y == 0.0 && v.z == 0.0;
}

// Why `term` is zero in the whole scene, or empty where it is not.
QString whySilent(const Scene &scene, EquationTerm term)
{
    const auto everyObject = [&](auto zero) {
        return !scene.objects.empty()
            && std::all_of(scene.objects.begin(), scene.objects.end(),
                           [&](const SceneObject &o) { return zero(o.material); });
    };
    if (term == EquationTerm::Ambient) {
        if (isZero(scene.ambient))
            return SilentTermsWords::tr("Ia = 0");
        if (everyObject([](const Material &m) { return isZero(m.ka); }))
            return SilentTermsWords::tr("ka = 0 on every object");
        return {};
    }
    const bool diffuse = term == EquationTerm::Diffuse;
    std::vector<const PointLight *> on;
    for (const PointLight &l : scene.lights)
        if (l.enabled)
            on.push_back(&l);
    if (on.empty())
        return SilentTermsWords::tr("no light is on");
    if (std::all_of(on.begin(), on.end(), [&](const PointLight *l) {
            return isZero(diffuse ? l->diffuse : l->specular);
        }))
        return diffuse ? SilentTermsWords::tr("Id = 0 for every light")
                       : SilentTermsWords::tr("Is = 0 for every light");
    if (everyObject([&](const Material &m) { return isZero(diffuse ? m.kd : m.ks); }))
        return diffuse ? SilentTermsWords::tr("kd = 0 on every object")
                       : SilentTermsWords::tr("ks = 0 on every object");
    return {};
}

} // namespace

std::vector<SilentTerm> silentTerms(const Scene &scene)
{
    std::vector<SilentTerm> out;
    for (EquationTerm term : {EquationTerm::Ambient, EquationTerm::Diffuse, EquationTerm::Specular})
        if (const QString why = whySilent(scene, term); !why.isEmpty())
            out.push_back({term, why});
    return out;
}

QString equationTermName(EquationTerm term)
{
    switch (term) {
    case EquationTerm::Ambient: return SilentTermsWords::tr("ambient");
    case EquationTerm::Diffuse: return SilentTermsWords::tr("diffuse");
    case EquationTerm::Specular: return SilentTermsWords::tr("specular");
    }
    return {};
}

QString silentTermKey(EquationTerm term)
{
    switch (term) {
    case EquationTerm::Ambient: return QStringLiteral("ambient");
    case EquationTerm::Diffuse: return QStringLiteral("diffuse");
    case EquationTerm::Specular: return QStringLiteral("specular");
    }
    return {};
}

QString silentTermsText(const std::vector<SilentTerm> &terms)
{
    QStringList parts;
    for (const SilentTerm &t : terms)
        parts << SilentTermsWords::tr("the %1 term (%2)").arg(equationTermName(t.term), t.why);
    return parts.join(QStringLiteral("; "));
}

} // namespace phonglab
