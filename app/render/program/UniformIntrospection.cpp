#include "UniformIntrospection.h"

#include <algorithm>

namespace phonglab {

std::vector<ActiveUniformInfo> activeUniformsOf(QOpenGLExtraFunctions *gl, GLuint program)
{
    std::vector<ActiveUniformInfo> list;
    if (program == 0)
        return list;
    GLint count = 0, maxLength = 0;
    gl->glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
    gl->glGetProgramiv(program, GL_ACTIVE_UNIFORM_MAX_LENGTH, &maxLength);
    QByteArray buffer(std::max(maxLength, 1), '\0');
    for (GLuint i = 0; i < GLuint(count); ++i) {
        GLint block = -1;
        gl->glGetActiveUniformsiv(program, 1, &i, GL_UNIFORM_BLOCK_INDEX, &block);
        ActiveUniformInfo u;
        GLsizei length = 0;
        gl->glGetActiveUniform(program, i, GLsizei(buffer.size()), &length, &u.size, &u.type,
                               buffer.data());
        u.name = QByteArray(buffer.constData(), length);
        if (block != -1 || u.name.startsWith("gl_"))
            continue; // block members and built-ins have no value of their own to set
        u.location = gl->glGetUniformLocation(program, u.name.constData());
        u.isArray = u.name.endsWith("[0]");
        if (u.isArray)
            u.name.chop(3);
        list.push_back(u);
    }
    std::sort(list.begin(), list.end(), [](const ActiveUniformInfo &a, const ActiveUniformInfo &b) {
        return a.name < b.name;
    });
    return list;
}

std::vector<ActiveInputInfo> activeInputsOf(QOpenGLExtraFunctions *gl, GLuint program)
{
    std::vector<ActiveInputInfo> list;
    if (program == 0)
        return list;
    GLint count = 0, maxLength = 0;
    gl->glGetProgramiv(program, GL_ACTIVE_ATTRIBUTES, &count);
    gl->glGetProgramiv(program, GL_ACTIVE_ATTRIBUTE_MAX_LENGTH, &maxLength);
    QByteArray buffer(std::max(maxLength, 1), '\0');
    for (GLuint i = 0; i < GLuint(count); ++i) {
        ActiveInputInfo a;
        GLsizei length = 0;
        GLint size = 0;
        gl->glGetActiveAttrib(program, i, GLsizei(buffer.size()), &length, &size, &a.type,
                              buffer.data());
        a.name = QByteArray(buffer.constData(), length);
        if (a.name.startsWith("gl_"))
            continue;
        a.location = gl->glGetAttribLocation(program, a.name.constData());
        list.push_back(a);
    }
    return list;
}

GlslType glslTypeOf(GLenum type)
{
    return glslTypeOfGlEnum(type);
}

std::vector<ShaderVariable> shaderVariablesOf(QOpenGLExtraFunctions *gl, GLuint program)
{
    std::vector<ShaderVariable> out;
    for (const ActiveInputInfo &a : activeInputsOf(gl, program))
        out.push_back({QString::fromUtf8(a.name), glslTypeOf(a.type), 1, false, true});
    for (const ActiveUniformInfo &u : activeUniformsOf(gl, program))
        out.push_back(
            {QString::fromUtf8(u.name), glslTypeOf(u.type), int(u.size), u.isArray, false});
    return out;
}

QString glslTypeName(GLenum type)
{
    switch (type) {
    case GL_FLOAT: return QStringLiteral("float");
    case GL_FLOAT_VEC2: return QStringLiteral("vec2");
    case GL_FLOAT_VEC3: return QStringLiteral("vec3");
    case GL_FLOAT_VEC4: return QStringLiteral("vec4");
    case GL_INT: return QStringLiteral("int");
    case GL_INT_VEC2: return QStringLiteral("ivec2");
    case GL_INT_VEC3: return QStringLiteral("ivec3");
    case GL_INT_VEC4: return QStringLiteral("ivec4");
    case GL_UNSIGNED_INT: return QStringLiteral("uint");
    case GL_UNSIGNED_INT_VEC2: return QStringLiteral("uvec2");
    case GL_UNSIGNED_INT_VEC3: return QStringLiteral("uvec3");
    case GL_UNSIGNED_INT_VEC4: return QStringLiteral("uvec4");
    case GL_BOOL: return QStringLiteral("bool");
    case GL_BOOL_VEC2: return QStringLiteral("bvec2");
    case GL_BOOL_VEC3: return QStringLiteral("bvec3");
    case GL_BOOL_VEC4: return QStringLiteral("bvec4");
    case GL_FLOAT_MAT2: return QStringLiteral("mat2");
    case GL_FLOAT_MAT3: return QStringLiteral("mat3");
    case GL_FLOAT_MAT4: return QStringLiteral("mat4");
    case GL_FLOAT_MAT2x3: return QStringLiteral("mat2x3");
    case GL_FLOAT_MAT2x4: return QStringLiteral("mat2x4");
    case GL_FLOAT_MAT3x2: return QStringLiteral("mat3x2");
    case GL_FLOAT_MAT3x4: return QStringLiteral("mat3x4");
    case GL_FLOAT_MAT4x2: return QStringLiteral("mat4x2");
    case GL_FLOAT_MAT4x3: return QStringLiteral("mat4x3");
    case GL_SAMPLER_2D: return QStringLiteral("sampler2D");
    case GL_SAMPLER_3D: return QStringLiteral("sampler3D");
    case GL_SAMPLER_CUBE: return QStringLiteral("samplerCube");
    case GL_SAMPLER_2D_SHADOW: return QStringLiteral("sampler2DShadow");
    case GL_SAMPLER_2D_ARRAY: return QStringLiteral("sampler2DArray");
    default: return {};
    }
}

namespace {

// withPrologue's head ends with the first `#line N`: from there on the text
// is the student's, starting at line N.
QByteArray studentLines(const QByteArray &compiled)
{
    qsizetype at = compiled.startsWith("#line ") ? 0 : compiled.indexOf("\n#line ");
    if (at < 0)
        return compiled;
    if (at > 0)
        ++at;
    const qsizetype eol = compiled.indexOf('\n', at);
    if (eol < 0)
        return {};
    const int first = compiled.mid(at + 6, eol - at - 6).trimmed().toInt();
    return QByteArray(std::max(0, first - 1), '\n') + compiled.mid(eol + 1);
}

} // namespace

CompiledStages compiledStagesOf(QOpenGLExtraFunctions *gl, GLuint program)
{
    CompiledStages out;
    GLuint shaders[8] = {};
    GLsizei count = 0;
    gl->glGetAttachedShaders(program, 8, &count, shaders);
    for (GLsizei k = 0; k < count; ++k) {
        GLint type = 0;
        GLint length = 0;
        gl->glGetShaderiv(shaders[k], GL_SHADER_TYPE, &type);
        gl->glGetShaderiv(shaders[k], GL_SHADER_SOURCE_LENGTH, &length);
        if (length <= 1)
            continue;
        QByteArray text(length, '\0');
        gl->glGetShaderSource(shaders[k], length, nullptr, text.data());
        text.truncate(qsizetype(qstrnlen(text.constData(), std::size_t(length))));
        (type == GL_VERTEX_SHADER ? out.vertex : out.fragment) = studentLines(text);
    }
    return out;
}

} // namespace phonglab
