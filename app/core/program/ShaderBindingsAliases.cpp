// The names students give their variables, and the meaning each name and
// type gives a variable (automaticMeaning, likelyMeaning). Apart from
// ShaderBindings.cpp, which binds variables by these names or by the
// user's word: the alias tables alone are as long as the rest.
#include "core/program/ShaderBindingsAliases.h"
#include "core/program/ShaderBindings.h"

#include "core/support/NearestSpelling.h"

#include <QRegularExpression>

#include <algorithm>
#include <climits>
#include <vector>

namespace phonglab {

namespace bindingnames {

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

} // namespace bindingnames

namespace {

using M = BindingMeaning;
using bindingnames::NameParts;
using bindingnames::splitName;

// Names as students write them, normalised (normalizedName()): lower case,
// no separators, no u/a/in prefix, no "matrix"/"world" suffix. The type
// decides between entries that share a spelling ("n": a float is the
// shininess, a mat3 the normal matrix, a vertex input the normal).
struct Aliases {
    BindingMeaning meaning;
    std::vector<const char *> names;
};

// Vertex inputs: the attributes of the mesh.
std::vector<Aliases> vertexInputAliases()
{
    return {
        {M::Position,
         {"position", "pos", "vertexposition", "vertexpos", "vertpos", "vertex", "vpos",
          "vposition", "p", "objectposition", "positionobject", "modelposition", "positionos",
          "point"}},
        {M::Normal,
         {"normal", "norm", "vertexnormal", "vertnormal", "vnormal", "n", "objectnormal",
          "normalobject", "normalos"}},
    };
}

// The matrices a scene object and the camera give.
std::vector<Aliases> transformAliases()
{
    return {
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
    };
}

// The camera's position.
std::vector<Aliases> cameraAliases()
{
    return {
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
    };
}

// The lights of the scene, and its ambient light.
std::vector<Aliases> lightAliases()
{
    return {
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
    };
}

// The material of the object.
std::vector<Aliases> materialAliases()
{
    return {
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
    };
}

// What shaders written to other conventions than PhongLab's pass instead:
// light and material premultiplied (ambientProduct = Ia·ka, as in Angel's
// textbook), one colour per light or per material, or the light position
// already in camera space.
std::vector<Aliases> otherConventionAliases()
{
    return {
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
}

// Every alias, in the order lookUp() and likelyMeaning() try them: an
// earlier entry wins a name two entries share.
const std::vector<Aliases> &aliasTable()
{
    static const std::vector<Aliases> table = [] {
        std::vector<Aliases> all;
        for (const std::vector<Aliases> &group :
             {vertexInputAliases(), transformAliases(), cameraAliases(), lightAliases(),
              materialAliases(), otherConventionAliases()})
            all.insert(all.end(), group.begin(), group.end());
        return all;
    }();
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

} // namespace

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

} // namespace phonglab
