#pragma once
#include "core/scene/Scene.h"

#include <QString>
#include <QStringList>

namespace phonglab {

// The terms of the equation that are zero everywhere in a scene, so that no
// image of it can tell a right term from a wrong one: with ks = 0 on every
// object a Blinn highlight and a Phong one are both black. A check that
// passes says so, rather than a ✓ for what it could not see.
enum class EquationTerm {
    Ambient,
    Diffuse,
    Specular
};

struct SilentTerm {
    EquationTerm term;
    QString why; // "ks = 0 on every object", "no light is on"
};

std::vector<SilentTerm> silentTerms(const Scene &scene);
QString equationTermName(EquationTerm term); // in the run's language
QString silentTermKey(EquationTerm term);    // "ambient", "diffuse", "specular": --json's
// "the specular term (ks = 0 on every object)"; terms joined by "; ".
QString silentTermsText(const std::vector<SilentTerm> &terms);

} // namespace phonglab
