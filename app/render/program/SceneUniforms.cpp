#include "SceneUniforms.h"

#include "core/program/UniformOwner.h"

namespace phonglab {

namespace {

bool isPlainNumberType(GLenum type)
{
    switch (type) {
    case GL_FLOAT:
    case GL_FLOAT_VEC2:
    case GL_FLOAT_VEC3:
    case GL_FLOAT_VEC4:
    case GL_INT:
    case GL_INT_VEC2:
    case GL_INT_VEC3:
    case GL_INT_VEC4:
    case GL_UNSIGNED_INT:
    case GL_UNSIGNED_INT_VEC2:
    case GL_UNSIGNED_INT_VEC3:
    case GL_UNSIGNED_INT_VEC4:
    case GL_BOOL:
    case GL_BOOL_VEC2:
    case GL_BOOL_VEC3:
    case GL_BOOL_VEC4:
    case GL_FLOAT_MAT2:
    case GL_FLOAT_MAT3:
    case GL_FLOAT_MAT4: return true;
    default: return false;
    }
}

double component(const UniformValue &v, int i)
{
    switch (v.kind) {
    case UniformValue::Kind::Float: return double(v.floats[i]);
    case UniformValue::Kind::Int: return double(v.ints[i]);
    case UniformValue::Kind::UInt: return double(v.uints[i]);
    }
    return 0.0;
}

} // namespace

std::map<QString, std::vector<double>> userUniformValues(const UniformSnapshot &snapshot,
                                                         const ProgramBindings &bindings)
{
    std::map<QString, std::vector<double>> values;
    for (const UniformValue &v : snapshot.values) {
        const QString name = QString::fromUtf8(v.name);
        if (!isPlainNumberType(v.type)
            || uniformOwner(bindings.meaningOf(name)) != UniformOwner::User)
            continue;
        std::vector<double> numbers;
        for (int i = 0; i < v.components; ++i)
            numbers.push_back(component(v, i));
        values[name] = std::move(numbers);
    }
    return values;
}

} // namespace phonglab
