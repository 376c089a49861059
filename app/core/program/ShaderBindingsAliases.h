#pragma once
// Internal to ShaderBindings*.cpp: a variable's name in its parts
// ("uLights[1].diffuse"), read both where a variable is bound
// (ShaderBindings.cpp: the light a member holds) and where its name is
// matched against the aliases (ShaderBindingsAliases.cpp).
#include <QString>

namespace phonglab::bindingnames {

// "uLights[2].diffuse" -> {"uLights", 2, "diffuse"}; "uKd" -> {"", 0, "uKd"}.
struct NameParts {
    QString container;
    int index = 0;
    QString member;
};
NameParts splitName(const QString &name);

} // namespace phonglab::bindingnames
