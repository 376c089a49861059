#pragma once
#include <QByteArray>
#include <QOpenGLContext>
#include <array>
#include <vector>

namespace phonglab {

// The values of a program's active default-block uniforms, one entry per
// array element ("gain", "lights[2]"). Values are kept as the 32-bit words
// glGetUniform{f,i,ui}v returned, which is how glUniform* sets them back.
struct UniformValue {
    enum class Kind {
        Float,
        Int,
        UInt
    };

    QByteArray name; // as glGetUniformLocation takes it
    GLenum type = 0; // GL_FLOAT_VEC3, GL_SAMPLER_2D, ...
    Kind kind = Kind::Float;
    int components = 0; // 1..16
    std::array<GLfloat, 16> floats{};
    std::array<GLint, 16> ints{};
    std::array<GLuint, 16> uints{};
};

struct UniformSnapshot {
    std::vector<UniformValue> values;

    const UniformValue *find(const QByteArray &name) const
    {
        for (const UniformValue &v : values)
            if (v.name == name)
                return &v;
        return nullptr;
    }
};

} // namespace phonglab
