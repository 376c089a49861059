#include "core/check/ShaderBindings.h"

#include "core/support/EnumNames.h"
#include "core/support/NearestSpelling.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <algorithm>
#include <array>
#include <climits>
#include <initializer_list>
#include <utility>

namespace phonglab {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct ShaderBindingsWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::ShaderBindings)
};

namespace {

using M = BindingMeaning;

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
};

// Names as students write them, normalised (normalizedName()): lower case,
// no separators, no u/a/in prefix, no "matrix"/"world" suffix. The type
// decides between entries that share a spelling ("n": a float is the
// shininess, a mat3 the normal matrix, a vertex input the normal).
struct Aliases {
    BindingMeaning meaning;
    std::vector<const char *> names;
};
const std::vector<Aliases> &aliasTable()
{
    static const std::vector<Aliases> table = {
        {M::Position,
         {"position", "pos", "vertexposition", "vertexpos", "vertpos", "vertex", "vpos", "p",
          "objectposition", "positionobject", "modelposition", "positionos", "point"}},
        {M::Normal,
         {"normal", "norm", "vertexnormal", "vertnormal", "vnormal", "n", "objectnormal",
          "normalobject", "normalos"}},
        {M::Model, {"model", "world", "modelworld", "objecttoworld", "modeltoworld", "m", "obj"}},
        {M::View,
         {"view", "camera", "cam", "lookat", "worldtoview", "worldtocamera", "v", "viewing"}},
        {M::Projection, {"projection", "proj", "perspective", "persp", "p", "clip"}},
        {M::ModelView, {"modelview", "mv", "worldview", "modelviewing", "objecttocamera"}},
        {M::ModelViewProjection,
         {"modelviewprojection", "mvp", "pvm", "projectionmodelview", "projmodelview",
          "projectionviewmodel", "projviewmodel", "pmv", "wvp", "worldviewprojection",
          "modelviewproj"}},
        {M::ViewProjection,
         {"viewprojection", "vp", "pv", "projectionview", "projview", "viewproj"}},
        {M::NormalMatrix,
         {"normal", "n", "nm", "normalmodelview", "modelviewnormal", "normalmv", "nmv",
          "modelviewinversetranspose", "mvinversetranspose", "mvit", "inversetransposemodelview",
          "inversetransposemv", "normalview", "normalcamera", "normaltransform"}},
        {M::ModelNormalMatrix,
         {"modelnormal", "normalmodel", "normalworld", "worldnormal", "modelinversetranspose",
          "modelit", "mit", "inversetransposemodel", "worldinversetranspose", "normalm",
          "normalobjecttoworld"}},
        {M::Eye,
         {"eye",
          "eyeposition",
          "eyepos",
          "camera",
          "cameraposition",
          "camerapos",
          "campos",
          "camposition",
          "cam",
          "viewposition",
          "viewpos",
          "viewer",
          "viewerposition",
          "viewerpos",
          "eyepoint",
          "viewworldposition",
          "viewworldpos",
          "cameraworldposition",
          "cameraworldpos",
          "eyeworldposition",
          "eyeworldpos"}},
        {M::LightPosition,
         {"light",
          "lightposition",
          "lightpos",
          "lightpositions",
          "lights",
          "lightsposition",
          "lightspositions",
          "lightlocation",
          "lp",
          "lightsource",
          "lightsrc",
          "pointlight",
          "pointlightposition",
          "pointlightpos",
          "lightpoint",
          "lightsourceposition",
          "lightworldposition",
          "lightworldpos",
          "worldlightposition",
          "worldlightpos"}},
        {M::LightCount,
         {"lightcount", "numlights", "nlights", "lightnumber", "numberoflights", "lightscount",
          "countlights", "lightnum", "numlight", "nlight", "activelights", "lightsused", "m",
          "numberlights", "lightsnumber", "lightsnum"}},
        {M::LightDiffuse,
         {"id", "diffuseintensity", "lightdiffuse", "diffuselight", "diffusecolor", "diffusecolour",
          "lightdiffusecolor", "lightdiffusecolour", "lightdiffuseintensity", "diffuselightcolor",
          "diffuselightcolour", "diffuselightintensity", "idiffuse", "intensitydiffuse",
          "lightsdiffuse"}},
        {M::LightSpecular,
         {"is", "specularintensity", "lightspecular", "specularlight", "specularcolor",
          "specularcolour", "lightspecularcolor", "lightspecularcolour", "lightspecularintensity",
          "specularlightcolor", "specularlightcolour", "specularlightintensity", "ispecular",
          "intensityspecular", "lightsspecular"}},
        {M::Attenuation,
         {"attenuation", "att", "atten", "attenuations", "attenuationfactor", "attenuationfactors",
          "attenuationcoefficients", "attenuationcoeffs", "attenuationconstants",
          "attenuationparams", "attenuationparameters", "lightattenuation", "lightatt", "c", "fatt",
          "falloff"}},
        {M::C1,
         {"c1", "constantattenuation", "attenuationconstant", "attconstant", "kc", "constant",
          "attc1", "attenuationc1"}},
        {M::C2,
         {"c2", "linearattenuation", "attenuationlinear", "attlinear", "kl", "linear", "attc2",
          "attenuationc2"}},
        {M::C3,
         {"c3", "quadraticattenuation", "attenuationquadratic", "attquadratic", "kq", "quadratic",
          "attc3", "attenuationc3"}},
        {M::Ambient,
         {"ia", "ambientintensity", "ambientlight", "ambientcolor", "ambientcolour", "lightambient",
          "globalambient", "iambient", "ambientlightcolor", "ambientlightcolour",
          "ambientlightintensity", "intensityambient", "sceneambient"}},
        {M::Ka,
         {"ka", "ambientreflection", "ambientreflectance", "ambientreflectivity",
          "ambientcoefficient", "ambientcoeff", "materialambient", "matambient", "kambient",
          "ambientmaterial", "ambientk", "reflectionambient"}},
        {M::Kd,
         {"kd", "diffusereflection", "diffusereflectance", "diffusereflectivity",
          "diffusecoefficient", "diffusecoeff", "materialdiffuse", "matdiffuse", "kdiffuse",
          "diffusematerial", "diffusek", "reflectiondiffuse", "albedo"}},
        {M::Ks,
         {"ks", "specularreflection", "specularreflectance", "specularreflectivity",
          "specularcoefficient", "specularcoeff", "materialspecular", "matspecular", "kspecular",
          "specularmaterial", "speculark", "reflectionspecular"}},
        {M::Shininess,
         {"shininess", "n", "shine", "shininessexponent", "specularexponent", "exponent",
          "phongexponent", "specularpower", "materialshininess", "matshininess", "glossiness",
          "specexp", "specularshininess", "ns", "specexponent", "phongn", "power"}},
        {M::AmbientProduct, {"ambientproduct", "ambientprod", "productambient"}},
        {M::DiffuseProduct, {"diffuseproduct", "diffuseprod", "productdiffuse"}},
        {M::SpecularProduct, {"specularproduct", "specularprod", "productspecular"}},
        {M::LightColor,
         {"lightcolor", "lightcolors", "lightcolour", "lightcolours", "lightscolor", "lightscolour",
          "lightrgb", "pointlightcolor", "pointlightcolour"}},
        {M::MaterialColor,
         {"materialcolor", "materialcolour", "matcolor", "matcolour", "objectcolor", "objectcolour",
          "surfacecolor", "surfacecolour", "basecolor", "basecolour", "color", "colour",
          "modelcolor", "meshcolor"}},
        {M::LightPositionCamera,
         {"lightposeye", "lightpositioneye", "eyelightpos", "eyelightposition", "lightposview",
          "lightpositionview", "viewlightpos", "viewlightposition", "lightposcamera",
          "lightpositioncamera", "lightposcam", "lightposec", "lightpositionec", "lightposvs",
          "lightpositionvs", "lightposes", "lightpositiones", "lightposcs", "lightpositioncs"}},
    };
    return table;
}

// Members of a struct whose name says "light" or "material": the member's
// name alone is then enough ("uLights[1].diffuse" is Id of light 1).
const std::vector<Aliases> &lightMemberTable()
{
    static const std::vector<Aliases> table = {
        {M::LightPosition, {"position", "pos", "location", "p", "point"}},
        {M::LightDiffuse,
         {"diffuse", "id", "diffuseintensity", "diffusecolor", "diffusecolour", "diff"}},
        {M::LightSpecular,
         {"specular", "is", "specularintensity", "specularcolor", "specularcolour", "spec"}},
        {M::LightColor, {"color", "colour", "col", "rgb", "intensity"}},
        {M::Attenuation, {"attenuation", "att", "atten", "c", "attenuationconstants"}},
        {M::C1, {"constant", "c1", "kc"}},
        {M::C2, {"linear", "c2", "kl"}},
        {M::C3, {"quadratic", "c3", "kq"}},
    };
    return table;
}
const std::vector<Aliases> &materialMemberTable()
{
    static const std::vector<Aliases> table = {
        {M::Ka, {"ambient", "ka", "ambi", "amb"}},
        {M::Kd, {"diffuse", "kd", "diff"}},
        {M::Ks, {"specular", "ks", "spec"}},
        {M::Shininess,
         {"shininess", "n", "exponent", "shine", "ns", "specularexponent", "shiny", "power"}},
        {M::MaterialColor, {"color", "colour", "col", "rgb"}},
    };
    return table;
}

// "uModelMatrix" -> "model", "a_position" -> "position", "u_lightPosWorld"
// -> "lightpos": prefixes and suffixes that say where a variable lives or
// that it is a matrix carry no meaning.
QString normalizedName(QString name)
{
    static const QRegularExpression prefix(
        QStringLiteral("^(?:u|a|in|attr|attrib|attribute|uni|uniform|g)(?:_+|(?=[A-Z]))"));
    name.remove(prefix);
    name = name.toLower();
    name.remove(QLatin1Char('_'));
    for (const char *suffix : {"matrix", "mat", "mtx", "transform", "world", "ws", "wc"}) {
        const QLatin1StringView s(suffix);
        if (name.size() > s.size() && name.endsWith(s))
            name.chop(s.size());
    }
    return name;
}

// "uLights[2].diffuse" -> {"uLights", 2, "diffuse"}; "uKd" -> {"", 0, "uKd"}.
struct NameParts {
    QString container;
    int index = 0;
    QString member;
};
NameParts splitName(const QString &name)
{
    const qsizetype dot = name.lastIndexOf(QLatin1Char('.'));
    if (dot < 0)
        return {{}, 0, name};
    NameParts parts;
    parts.member = name.mid(dot + 1);
    QString container = name.left(dot);
    static const QRegularExpression indexed(QStringLiteral(R"(^(.*?)\[(\d+)\]$)"));
    if (const auto m = indexed.match(container); m.hasMatch()) {
        parts.container = m.captured(1);
        parts.index = m.captured(2).toInt();
    } else {
        parts.container = container;
    }
    return parts;
}

std::optional<BindingMeaning> lookUp(const std::vector<Aliases> &table, const QString &normalized,
                                     const ShaderVariable &variable)
{
    for (const Aliases &entry : table)
        for (const char *alias : entry.names)
            if (normalized == QLatin1StringView(alias) && bindingFits(entry.meaning, variable))
                return entry.meaning;
    return std::nullopt;
}

const std::vector<Aliases> *memberTableFor(const QString &container)
{
    const QString c = container.toLower();
    if (c.contains(QLatin1StringView("light")) || c.contains(QLatin1StringView("lamp")))
        return &lightMemberTable();
    if (c.contains(QLatin1StringView("material")) || c.contains(QLatin1StringView("mat"))
        || c.contains(QLatin1StringView("surface")))
        return &materialMemberTable();
    return nullptr;
}

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
    }
    return false;
}

std::optional<BindingMeaning> automaticMeaning(const ShaderVariable &variable)
{
    const NameParts parts = splitName(variable.name);
    if (!parts.container.isEmpty()) {
        if (const std::vector<Aliases> *members = memberTableFor(parts.container))
            if (const auto m = lookUp(*members, normalizedName(parts.member), variable))
                return m;
    }
    return lookUp(aliasTable(), normalizedName(parts.member), variable);
}

std::optional<BindingMeaning> likelyMeaning(const ShaderVariable &variable)
{
    const QString normalized = normalizedName(splitName(variable.name).member);
    std::optional<BindingMeaning> best;
    int bestScore = INT_MAX;
    for (const Aliases &entry : aliasTable()) {
        if (!bindingFits(entry.meaning, variable))
            continue;
        for (const char *alias : entry.names) {
            const QString a = QString::fromLatin1(alias);
            // A name holding a telling alias ("lightpos2") is closer than
            // any spelling distance; one-letter aliases tell nothing there.
            const int score = a.size() > 2 && normalized.contains(a)
                ? 0
                : int(editDistance(normalized, a)) * 10 / int(std::max<qsizetype>(a.size(), 1));
            if (score < bestScore) {
                bestScore = score;
                best = entry.meaning;
            }
        }
    }
    return bestScore <= 4 ? best : std::nullopt;
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
