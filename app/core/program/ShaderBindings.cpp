#include "core/program/ShaderBindings.h"

#include "core/program/ShaderBindingsAliases.h"
#include "core/support/EnumNames.h"

#include <QCoreApplication>

#include <algorithm>
#include <array>
#include <initializer_list>
#include <utility>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct ShaderBindingsWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::ShaderBindings)
};

namespace {

using M = BindingMeaning;
using bindingnames::splitName;

constexpr std::array kKeys = {
    std::pair{M::Position, "position"},
    std::pair{M::Normal, "normal"},
    std::pair{M::Model, "model"},
    std::pair{M::View, "view"},
    std::pair{M::Projection, "projection"},
    std::pair{M::ModelView, "model-view"},
    std::pair{M::ModelViewProjection, "model-view-projection"},
    std::pair{M::ViewProjection, "view-projection"},
    std::pair{M::NormalMatrix, "normal-matrix"},
    std::pair{M::ModelNormalMatrix, "model-normal-matrix"},
    std::pair{M::Eye, "eye"},
    std::pair{M::LightPosition, "light-position"},
    std::pair{M::LightCount, "light-count"},
    std::pair{M::LightDiffuse, "Id"},
    std::pair{M::LightSpecular, "Is"},
    std::pair{M::Attenuation, "attenuation"},
    std::pair{M::C1, "c1"},
    std::pair{M::C2, "c2"},
    std::pair{M::C3, "c3"},
    std::pair{M::Ambient, "Ia"},
    std::pair{M::Ka, "ka"},
    std::pair{M::Kd, "kd"},
    std::pair{M::Ks, "ks"},
    std::pair{M::Shininess, "shininess"},
    std::pair{M::AmbientProduct, "ambient-product"},
    std::pair{M::DiffuseProduct, "diffuse-product"},
    std::pair{M::SpecularProduct, "specular-product"},
    std::pair{M::LightColor, "light-color"},
    std::pair{M::MaterialColor, "material-color"},
    std::pair{M::LightPositionCamera, "light-position-camera"},
    std::pair{M::Gain, "gain"},
    std::pair{M::LightTerms, "light-terms"},
    std::pair{M::MaterialTerms, "material-terms"},
};

constexpr std::array kDescriptions = {
    std::pair{
        M::Position,
        QT_TRANSLATE_NOOP("phonglab::ShaderBindings", "the vertex position, object coordinates")},
    std::pair{
        M::Normal,
        QT_TRANSLATE_NOOP("phonglab::ShaderBindings", "the vertex normal, object coordinates")},
    std::pair{M::Model,
              QT_TRANSLATE_NOOP("phonglab::ShaderBindings", "the model matrix (object to world)")},
    std::pair{M::View,
              QT_TRANSLATE_NOOP("phonglab::ShaderBindings", "the view matrix (world to camera)")},
    std::pair{
        M::Projection,
        QT_TRANSLATE_NOOP("phonglab::ShaderBindings", "the projection matrix (camera to clip)")},
    std::pair{
        M::ModelView,
        QT_TRANSLATE_NOOP("phonglab::ShaderBindings", "the model-view matrix (object to camera)")},
    std::pair{M::ModelViewProjection,
              QT_TRANSLATE_NOOP("phonglab::ShaderBindings",
                                "the model-view-projection matrix (object to clip)")},
    std::pair{M::ViewProjection,
              QT_TRANSLATE_NOOP("phonglab::ShaderBindings",
                                "the view-projection matrix (world to clip)")},
    std::pair{M::NormalMatrix,
              QT_TRANSLATE_NOOP("phonglab::ShaderBindings",
                                "the normal matrix, inverse transpose of the model-view matrix")},
    std::pair{
        M::ModelNormalMatrix,
        QT_TRANSLATE_NOOP("phonglab::ShaderBindings", "the inverse transpose of the model matrix")},
    std::pair{
        M::Eye,
        QT_TRANSLATE_NOOP("phonglab::ShaderBindings", "the camera's position, world coordinates")},
    std::pair{
        M::LightPosition,
        QT_TRANSLATE_NOOP("phonglab::ShaderBindings", "the light's position, world coordinates")},
    std::pair{M::LightCount, QT_TRANSLATE_NOOP("phonglab::ShaderBindings", "the number of lights")},
    std::pair{M::LightDiffuse,
              QT_TRANSLATE_NOOP("phonglab::ShaderBindings", "the light's diffuse intensity Id")},
    std::pair{M::LightSpecular,
              QT_TRANSLATE_NOOP("phonglab::ShaderBindings", "the light's specular intensity Is")},
    std::pair{M::Attenuation,
              QT_TRANSLATE_NOOP("phonglab::ShaderBindings",
                                "the light's attenuation constants (c1, c2, c3)")},
    std::pair{M::C1, QT_TRANSLATE_NOOP("phonglab::ShaderBindings", "the constant attenuation c1")},
    std::pair{M::C2, QT_TRANSLATE_NOOP("phonglab::ShaderBindings", "the linear attenuation c2")},
    std::pair{M::C3, QT_TRANSLATE_NOOP("phonglab::ShaderBindings", "the quadratic attenuation c3")},
    std::pair{M::Ambient,
              QT_TRANSLATE_NOOP("phonglab::ShaderBindings", "the ambient intensity Ia")},
    std::pair{M::Ka, QT_TRANSLATE_NOOP("phonglab::ShaderBindings", "the ambient reflection ka")},
    std::pair{M::Kd, QT_TRANSLATE_NOOP("phonglab::ShaderBindings", "the diffuse reflection kd")},
    std::pair{M::Ks, QT_TRANSLATE_NOOP("phonglab::ShaderBindings", "the specular reflection ks")},
    std::pair{M::Shininess, QT_TRANSLATE_NOOP("phonglab::ShaderBindings", "the shininess n")},
    std::pair{M::AmbientProduct,
              QT_TRANSLATE_NOOP("phonglab::ShaderBindings", "the ambient product Ia·ka")},
    std::pair{M::DiffuseProduct,
              QT_TRANSLATE_NOOP("phonglab::ShaderBindings", "the light's diffuse product Id·kd")},
    std::pair{M::SpecularProduct,
              QT_TRANSLATE_NOOP("phonglab::ShaderBindings", "the light's specular product Is·ks")},
    std::pair{M::LightColor,
              QT_TRANSLATE_NOOP("phonglab::ShaderBindings", "the light's colour, both Id and Is")},
    std::pair{
        M::MaterialColor,
        QT_TRANSLATE_NOOP("phonglab::ShaderBindings", "the material's colour, both ka and kd")},
    std::pair{
        M::LightPositionCamera,
        QT_TRANSLATE_NOOP("phonglab::ShaderBindings", "the light's position, camera coordinates")},
    std::pair{M::Gain,
              QT_TRANSLATE_NOOP("phonglab::ShaderBindings",
                                "a gain whose term's other factors hold its whole value: 1")},
    std::pair{M::LightTerms,
              QT_TRANSLATE_NOOP("phonglab::ShaderBindings",
                                "Ia, Id and Is of light 0, as a mat3's columns or a vec3[3]")},
    std::pair{M::MaterialTerms,
              QT_TRANSLATE_NOOP("phonglab::ShaderBindings",
                                "ka, kd and ks, as a mat3's columns or a vec3[3]")},
};

bool isOneOf(GlslType type, std::initializer_list<GlslType> types)
{
    return std::find(types.begin(), types.end(), type) != types.end();
}

} // namespace

QString bindingMeaningKey(BindingMeaning meaning)
{
    return enumName(kKeys, meaning);
}

std::optional<BindingMeaning> bindingMeaningFromKey(const QString &key)
{
    return enumFromName(kKeys, key);
}

QStringList bindingMeaningKeys()
{
    return enumNames(kKeys);
}

QString bindingMeaningDescription(BindingMeaning meaning)
{
    // Marked for lupdate in the table, translated here: the table's
    // entries are constant, the run's language is not.
    for (const auto &[m, text] : kDescriptions)
        if (m == meaning)
            return QCoreApplication::translate("phonglab::ShaderBindings", text);
    return {};
}

bool isPerLight(BindingMeaning meaning)
{
    switch (meaning) {
    case M::LightPosition:
    case M::LightDiffuse:
    case M::LightSpecular:
    case M::Attenuation:
    case M::C1:
    case M::C2:
    case M::C3:
    case M::DiffuseProduct:
    case M::SpecularProduct:
    case M::LightColor:
    case M::LightPositionCamera: return true;
    default: return false;
    }
}

bool isVertexInput(BindingMeaning meaning)
{
    return meaning == M::Position || meaning == M::Normal;
}

GlslType glslTypeOfGlEnum(unsigned glType)
{
    switch (glType) {
    case 0x1406: return GlslType::Float; // GL_FLOAT
    case 0x1404: return GlslType::Int;   // GL_INT
    case 0x1405: return GlslType::UInt;  // GL_UNSIGNED_INT
    case 0x8B56: return GlslType::Bool;  // GL_BOOL
    case 0x8B50: return GlslType::Vec2;  // GL_FLOAT_VEC2
    case 0x8B51: return GlslType::Vec3;  // GL_FLOAT_VEC3
    case 0x8B52: return GlslType::Vec4;  // GL_FLOAT_VEC4
    case 0x8B5B: return GlslType::Mat3;  // GL_FLOAT_MAT3
    case 0x8B5C: return GlslType::Mat4;  // GL_FLOAT_MAT4
    default: return GlslType::Other;
    }
}

QString glslTypeSpelling(GlslType type)
{
    switch (type) {
    case GlslType::Float: return QStringLiteral("float");
    case GlslType::Int: return QStringLiteral("int");
    case GlslType::UInt: return QStringLiteral("uint");
    case GlslType::Bool: return QStringLiteral("bool");
    case GlslType::Vec2: return QStringLiteral("vec2");
    case GlslType::Vec3: return QStringLiteral("vec3");
    case GlslType::Vec4: return QStringLiteral("vec4");
    case GlslType::Mat3: return QStringLiteral("mat3");
    case GlslType::Mat4: return QStringLiteral("mat4");
    case GlslType::Other: break;
    }
    return ShaderBindingsWords::tr("another type");
}

bool bindingFits(BindingMeaning meaning, const ShaderVariable &v)
{
    using T = GlslType;
    if (isVertexInput(meaning) != v.isInput)
        return false;
    if (meaning == M::LightTerms || meaning == M::MaterialTerms)
        return (v.type == T::Mat3 && !v.isArray)
            || (v.type == T::Vec3 && v.isArray && v.arraySize == 3);
    if (v.isArray && !isPerLight(meaning))
        return false;
    switch (meaning) {
    case M::Position:
    case M::Normal:
    case M::Eye:
    case M::LightPosition:
    case M::LightDiffuse:
    case M::LightSpecular:
    case M::Ambient:
    case M::Ka:
    case M::Kd:
    case M::Ks:
    case M::AmbientProduct:
    case M::DiffuseProduct:
    case M::SpecularProduct:
    case M::LightColor:
    case M::MaterialColor:
    case M::LightPositionCamera: return isOneOf(v.type, {T::Vec3, T::Vec4});
    case M::Model:
    case M::View:
    case M::Projection:
    case M::ModelView:
    case M::ModelViewProjection:
    case M::ViewProjection: return v.type == T::Mat4;
    case M::NormalMatrix:
    case M::ModelNormalMatrix: return isOneOf(v.type, {T::Mat3, T::Mat4});
    case M::Attenuation: return v.type == T::Vec3;
    case M::C1:
    case M::C2:
    case M::C3: return isOneOf(v.type, {T::Float, T::Int}); // an int where the value is whole
    case M::LightCount: return isOneOf(v.type, {T::Int, T::UInt, T::Float});
    case M::Shininess: return isOneOf(v.type, {T::Float, T::Int});
    case M::Gain: return isOneOf(v.type, {T::Float, T::Vec3, T::Vec4});
    case M::LightTerms:
    case M::MaterialTerms: return false; // above
    }
    return false;
}

std::optional<ParsedBinding> parseBindingArgument(const QString &text, QString *error)
{
    const qsizetype eq = text.indexOf(QLatin1Char('='));
    const QString name = text.left(eq).trimmed();
    const QString key = eq < 0 ? QString() : text.mid(eq + 1).trimmed();
    if (eq < 0 || name.isEmpty() || key.isEmpty()) {
        *error = QStringLiteral("expected NAME=MEANING, got '%1'").arg(text);
        return std::nullopt;
    }
    if (key == kUnboundWord)
        return ParsedBinding{name, std::nullopt};
    const auto meaning = bindingMeaningFromKey(key);
    if (!meaning) {
        *error = ShaderBindingsWords::tr("'%1': unknown meaning '%2' (known: %3, %4)")
                     .arg(text, key, bindingMeaningKeys().join(QStringLiteral(", ")), kUnboundWord);
        return std::nullopt;
    }
    return ParsedBinding{name, meaning};
}

std::optional<int> ProgramBindings::lightCapacity() const
{
    // Per meaning: an array has room for its size; members of a struct
    // array ("uLights[1].position") or a plain uniform, for the highest
    // light index + 1. The program takes as many lights as its tightest
    // meaning has room for.
    std::map<BindingMeaning, int> room;
    for (const VariableBinding &b : variables) {
        if (!b.meaning || !isPerLight(*b.meaning))
            continue;
        const int r = b.variable.isArray ? b.variable.arraySize : b.lightIndex + 1;
        room[*b.meaning] = std::max(room[*b.meaning], r);
    }
    // The terms' parts in one uniform hold light 0's alone.
    if (!bound(M::LightTerms).empty())
        room[M::LightTerms] = 1;
    std::optional<int> capacity;
    for (const auto &[meaning, r] : room)
        capacity = capacity ? std::min(*capacity, r) : r;
    return capacity;
}

std::vector<const VariableBinding *> ProgramBindings::bound(BindingMeaning meaning) const
{
    std::vector<const VariableBinding *> out;
    for (const VariableBinding &b : variables)
        if (b.meaning == meaning)
            out.push_back(&b);
    return out;
}

std::optional<BindingMeaning> ProgramBindings::meaningOf(const QString &name) const
{
    const QString base = name.endsWith(QLatin1Char(']')) && !name.contains(QLatin1Char('.'))
        ? name.section(QLatin1Char('['), 0, 0)
        : name;
    for (const VariableBinding &b : variables)
        if (b.variable.name == base || b.variable.name == name)
            return b.meaning;
    return std::nullopt;
}

std::optional<BindingMeaning> boundMeaning(const ShaderVariable &variable,
                                           const ExplicitBindings &explicitBindings)
{
    if (const auto it = explicitBindings.find(variable.name); it != explicitBindings.end())
        return it->second && bindingFits(*it->second, variable) ? it->second : std::nullopt;
    return automaticMeaning(variable);
}

std::vector<const VariableBinding *> ProgramBindings::unboundUniforms() const
{
    std::vector<const VariableBinding *> out;
    for (const VariableBinding &b : variables)
        if (!b.meaning && !b.variable.isInput)
            out.push_back(&b);
    return out;
}

ProgramBindings bindVariables(const std::vector<ShaderVariable> &variables,
                              const ExplicitBindings &explicitBindings)
{
    ProgramBindings out;
    for (const ShaderVariable &v : variables) {
        VariableBinding b;
        b.variable = v;
        b.lightIndex = splitName(v.name).index;
        if (const auto it = explicitBindings.find(v.name); it != explicitBindings.end()) {
            b.isExplicit = true;
            if (it->second && !bindingFits(*it->second, v)) {
                out.problems << ShaderBindingsWords::tr(
                                    "%1=%2: %1 is a %3%4 %5, which cannot hold %6")
                                    .arg(v.name, bindingMeaningKey(*it->second),
                                         glslTypeSpelling(v.type),
                                         v.isArray ? ShaderBindingsWords::tr(" array") : QString(),
                                         v.isInput ? ShaderBindingsWords::tr("input")
                                                   : ShaderBindingsWords::tr("uniform"),
                                         bindingMeaningDescription(*it->second));
            } else {
                b.meaning = it->second;
            }
        } else {
            b.meaning = automaticMeaning(v);
        }
        out.variables.push_back(std::move(b));
    }
    for (const auto &entry : explicitBindings) {
        const QString &name = entry.first;
        if (std::none_of(variables.begin(), variables.end(),
                         [&](const ShaderVariable &v) { return v.name == name; }))
            out.notes << ShaderBindingsWords::tr(
                             "%1=%2: the program has no active uniform or input %1 "
                             "(not declared, or unused and optimised away)")
                             .arg(name,
                                  entry.second ? bindingMeaningKey(*entry.second) : kUnboundWord);
    }
    return out;
}

} // namespace phonglab
