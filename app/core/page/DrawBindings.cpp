#include "DrawBindings.h"

namespace phonglab {

ProgramBindings drawBindings(const CapturedOp &draw, const ExplicitBindings &explicitBindings)
{
    std::vector<ShaderVariable> variables;
    for (const CapturedAttribute &a : draw.attributes)
        variables.push_back({a.name, glslTypeOfGlEnum(a.glType), 1, false, true});
    for (const CapturedUniform &u : draw.uniforms)
        variables.push_back({u.name, glslTypeOfGlEnum(u.glType), u.size, u.isArray, false});
    return bindVariables(variables, explicitBindings);
}

const CapturedUniform *uniformMeaning(const CapturedOp &draw, const ProgramBindings &bindings,
                                      BindingMeaning meaning)
{
    for (const VariableBinding *b : bindings.bound(meaning))
        if (!b->variable.isInput)
            if (const CapturedUniform *u = draw.uniform(b->variable.name))
                return u;
    return nullptr;
}

const CapturedAttribute *attributeMeaning(const CapturedOp &draw, const ProgramBindings &bindings,
                                          BindingMeaning meaning)
{
    for (const VariableBinding *b : bindings.bound(meaning))
        if (b->variable.isInput)
            if (const CapturedAttribute *a = draw.attribute(b->variable.name))
                return a;
    return nullptr;
}

std::optional<glm::dmat4> uniformMatrix(const CapturedUniform &uniform)
{
    if (uniform.values.empty())
        return std::nullopt;
    const std::vector<double> &v = uniform.values.front();
    const int n = v.size() == 16 ? 4 : v.size() == 9 ? 3 : 0;
    if (n == 0)
        return std::nullopt;
    glm::dmat4 m(1.0);
    for (int column = 0; column < n; ++column)
        for (int row = 0; row < n; ++row)
            m[column][row] = v[std::size_t(column * n + row)];
    return m;
}

} // namespace phonglab
