#pragma once
#include "core/program/ShaderStage.h"

#include <QString>
#include <QStringList>

#include <cstddef>
#include <map>
#include <optional>
#include <vector>

namespace phonglab {

// What each uniform and vertex input of a user's program means to PhongLab.
// Students name their variables as their course does (`uModelMatrix`,
// `aPosition`, `u_lightPos[2]`, `Kd`); PhongLab binds each to one meaning,
// by name and type, or by the user's explicit word (--bind, the scene's
// "bindings", the Uniforms dock). A variable bound to no meaning is the
// user's own: the Uniforms dock edits it. The meanings' keys are an
// interface (CLI, scene files, JSON): never renamed.
enum class BindingMeaning {
    Position, // vertex input, object coordinates
    Normal,   // vertex input, object coordinates
    Model,
    View,
    Projection,
    ModelView,
    ModelViewProjection,
    ViewProjection,
    NormalMatrix,      // inverse transpose of model-view (mat3, or mat4)
    ModelNormalMatrix, // inverse transpose of model
    Eye,               // the camera's position, world coordinates
    LightPosition,     // world coordinates
    LightCount,
    LightDiffuse,  // Id
    LightSpecular, // Is
    Attenuation,   // vec3 (c1, c2, c3)
    C1,
    C2,
    C3,
    Ambient, // Ia
    Ka,
    Kd,
    Ks,
    Shininess, // the slide's n
    // What courses pass pre-multiplied or shared (Angel & Shreiner's
    // products, one colour for two terms), and the light already moved:
    AmbientProduct,      // Ia·ka
    DiffuseProduct,      // Id·kd, per light
    SpecularProduct,     // Is·ks, per light
    LightColor,          // one colour for Id and Is of a light (they must be equal)
    MaterialColor,       // one colour for ka and kd (they must be equal)
    LightPositionCamera, // the light's position, camera coordinates
    // A factor of a term whose other factors already hold its whole value
    // (a scalar `ka` beside a colour given Ia·ka): 1 (a float, or a vector
    // of ones). Bound by use only.
    Gain,
    // The three terms' parts in one uniform, as a mat3's columns or a
    // vec3[3]'s elements, in the equation's order (ambient, diffuse,
    // specular): Ia, Id, Is of light 0, or ka, kd, ks.
    LightTerms,
    MaterialTerms,
};
// How many meanings there are (the last one + 1): a table indexed by them.
inline constexpr std::size_t kBindingMeaningCount = std::size_t(BindingMeaning::MaterialTerms) + 1;

QString bindingMeaningKey(BindingMeaning meaning);
std::optional<BindingMeaning> bindingMeaningFromKey(const QString &key);
QStringList bindingMeaningKeys(); // in the order of the enum
// A few words for a person, in the run's language ("the light's position,
// world coordinates").
QString bindingMeaningDescription(BindingMeaning meaning);
bool isPerLight(BindingMeaning meaning); // one value per light (LightCount is not)
bool isVertexInput(BindingMeaning meaning);

// The GLSL types bindings care about; the GL layer maps its enums here.
enum class GlslType {
    Float,
    Int,
    UInt,
    Bool,
    Vec2,
    Vec3,
    Vec4,
    Mat3,
    Mat4,
    Other,
};
QString glslTypeSpelling(GlslType type);
// An OpenGL (or WebGL) type enum as bindings see it (GlslType::Other for
// samplers, int vectors, ...): the driver's, or one a page's capture holds.
GlslType glslTypeOfGlEnum(unsigned glType);

// One active uniform or vertex input as the driver reports it. An array is
// one variable named without "[0]"; a member of a struct array is its own
// variable ("uLights[1].position").
struct ShaderVariable {
    QString name;
    GlslType type = GlslType::Other;
    int arraySize = 1;
    bool isArray = false;
    bool isInput = false; // a vertex input (attribute); else a uniform
};

// The user's word, by variable name: a meaning, or nullopt for "none" (the
// user's own, never bound automatically). Written "NAME=MEANING" (--bind) and
// {"NAME": "MEANING"} (the scene's "bindings"); "none" is the word for nullopt.
using ExplicitBindings = std::map<QString, std::optional<BindingMeaning>>;
inline const QString kUnboundWord = QStringLiteral("none");
// "NAME=MEANING" read, or why not ("--bind uFoo=modle: unknown meaning ...").
struct ParsedBinding {
    QString name;
    std::optional<BindingMeaning> meaning;
};
std::optional<ParsedBinding> parseBindingArgument(const QString &text, QString *error);

// Why a variable no name rule decided means what it does: its use in the
// shader (core/program/BindingsByUse), where.
struct UseEvidence {
    ShaderStage stage = ShaderStage::Fragment;
    int line = 0;
    QString reason; // in the run's language ("the exponent of pow")
};

struct VariableBinding {
    ShaderVariable variable;
    std::optional<BindingMeaning> meaning;
    bool isExplicit = false;
    std::optional<UseEvidence> byUse; // bound by its use, not its name
    // For a per-light meaning on a variable that is no array: the light it
    // holds (a member of "uLights[1]" is light 1; a plain uniform light 0).
    int lightIndex = 0;
};

struct ProgramBindings {
    std::vector<VariableBinding> variables; // every active one, in the order given
    // Explicit bindings that cannot hold, each in a sentence.
    QStringList problems;
    // Explicit bindings that name no active variable (a typo, or a variable
    // the compiler dropped as unused).
    QStringList notes;

    // How many lights the program takes: the fewest any per-light meaning
    // has room for (an array's size; light index + 1 otherwise); nullopt
    // when no per-light meaning is bound.
    std::optional<int> lightCapacity() const;
    std::vector<const VariableBinding *> bound(BindingMeaning meaning) const;
    // The meaning of the variable named `name` ("tint[1]" finds "tint"),
    // nullopt where it has none or the program has no such variable.
    std::optional<BindingMeaning> meaningOf(const QString &name) const;
    std::vector<const VariableBinding *> unboundUniforms() const;
};

// Whether a variable of this type and shape can hold the meaning.
bool bindingFits(BindingMeaning meaning, const ShaderVariable &variable);
// The meaning a variable's name and type give it, if any.
std::optional<BindingMeaning> automaticMeaning(const ShaderVariable &variable);
// For a variable bound to nothing: the meaning its name is closest to that
// its type could hold (for a message: "uLightPos2, probably the light position").
std::optional<BindingMeaning> likelyMeaning(const ShaderVariable &variable);
// The user's word on the variable where it holds, else its automatic meaning.
std::optional<BindingMeaning> boundMeaning(const ShaderVariable &variable,
                                           const ExplicitBindings &explicitBindings);
// Every variable bound: explicitly where the user said, else automatically.
ProgramBindings bindVariables(const std::vector<ShaderVariable> &variables,
                              const ExplicitBindings &explicitBindings);

} // namespace phonglab
