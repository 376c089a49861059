#include "GlslApi.h"

#include <Qsci/qscilexer.h>

#include <QRegularExpression>
#include <QSet>

namespace phonglab {

namespace {

// genType = float, vec2, vec3, vec4 (genIType/genUType/genBType: the int,
// uint, bool forms); mat = any float matrix; bvec/vec = the vector forms.
const std::vector<GlslBuiltin> kBuiltins = {
    // Angles and trigonometry
    {"radians", "genType degrees", "Degrees to radians."},
    {"degrees", "genType radians", "Radians to degrees."},
    {"sin", "genType angle", "Sine; angle in radians."},
    {"cos", "genType angle", "Cosine; angle in radians."},
    {"tan", "genType angle", "Tangent; angle in radians."},
    {"asin", "genType x", "Arc sine in [-pi/2, pi/2]; undefined for |x| > 1."},
    {"acos", "genType x", "Arc cosine in [0, pi]; undefined for |x| > 1."},
    {"atan", "genType y, genType x",
     "Arc tangent of y/x in [-pi, pi], using the signs for the quadrant; atan(y_over_x) also "
     "exists."},
    {"sinh", "genType x", "Hyperbolic sine."},
    {"cosh", "genType x", "Hyperbolic cosine."},
    {"tanh", "genType x", "Hyperbolic tangent."},
    // Exponential
    {"pow", "genType x, genType y",
     "x raised to y; undefined for x < 0, or x = 0 with y <= 0 (guard specular exponents)."},
    {"exp", "genType x", "e raised to x."},
    {"log", "genType x", "Natural logarithm; undefined for x <= 0."},
    {"exp2", "genType x", "2 raised to x."},
    {"log2", "genType x", "Base-2 logarithm; undefined for x <= 0."},
    {"sqrt", "genType x", "Square root; undefined for x < 0."},
    {"inversesqrt", "genType x", "1 / sqrt(x); undefined for x <= 0."},
    // Common
    {"abs", "genType x", "Absolute value."},
    {"sign", "genType x", "1.0, 0.0 or -1.0 by the sign of x."},
    {"floor", "genType x", "Nearest integer <= x."},
    {"ceil", "genType x", "Nearest integer >= x."},
    {"trunc", "genType x", "Nearest integer whose magnitude is <= |x|."},
    {"round", "genType x", "Nearest integer; halves round in an implementation-chosen direction."},
    {"roundEven", "genType x", "Nearest integer; halves round to the even one."},
    {"fract", "genType x", "x - floor(x)."},
    {"mod", "genType x, genType y", "x - y * floor(x / y) (y may be a float)."},
    {"modf", "genType x, out genType i", "Fractional part of x; the integer part goes to i."},
    {"min", "genType x, genType y", "The smaller of x and y, per component (y may be a scalar)."},
    {"max", "genType x, genType y",
     "The larger of x and y, per component; max(0.0, dot(N, L)) clamps back-facing light."},
    {"clamp", "genType x, genType minVal, genType maxVal",
     "min(max(x, minVal), maxVal); undefined if minVal > maxVal."},
    {"mix", "genType x, genType y, genType a",
     "Linear blend x*(1-a) + y*a; with a bvec it selects y where a is true."},
    {"step", "genType edge, genType x", "0.0 where x < edge, else 1.0."},
    {"smoothstep", "genType edge0, genType edge1, genType x",
     "Hermite ramp from 0 at edge0 to 1 at edge1."},
    {"isnan", "genType x", "True where x is NaN."},
    {"isinf", "genType x", "True where x is +/- infinity."},
    {"fma", "genType a, genType b, genType c", "a * b + c as one operation."},
    {"floatBitsToInt", "genType value", "The bits of a float as an int."},
    {"intBitsToFloat", "genIType value", "An int's bits as a float."},
    // Geometric
    {"length", "genType x", "Euclidean length of x."},
    {"distance", "genType p0, genType p1", "length(p0 - p1)."},
    {"dot", "genType x, genType y",
     "Dot product; for unit vectors the cosine of the angle between them."},
    {"cross", "vec3 x, vec3 y", "Cross product, perpendicular to x and y (right-handed)."},
    {"normalize", "genType x",
     "x scaled to length 1; undefined for a zero vector. Renormalize interpolated normals."},
    {"faceforward", "genType N, genType I, genType Nref", "N if dot(Nref, I) < 0, else -N."},
    {"reflect", "genType I, genType N",
     "Reflects I about N: I - 2*dot(N, I)*N. I is the incident vector, pointing toward the "
     "surface, "
     "so for a light direction L pointing away from the surface pass -L: reflect(-L, N). N must be "
     "normalized."},
    {"refract", "genType I, genType N, float eta",
     "Refraction of the incident vector I (pointing toward the surface) through normalized N with "
     "eta = n1/n2; the zero vector on total internal reflection."},
    // Matrices
    {"matrixCompMult", "mat x, mat y", "Component-wise product (x * y is the matrix product)."},
    {"outerProduct", "vec c, vec r", "The matrix c * transpose(r)."},
    {"transpose", "mat m", "Transpose of m."},
    {"determinant", "mat m", "Determinant of a square matrix."},
    {"inverse", "mat m",
     "Inverse of a square matrix; transpose(inverse(mat3(modelView))) transforms normals."},
    // Vector relations
    {"lessThan", "vec x, vec y", "Component-wise x < y, as a bvec."},
    {"lessThanEqual", "vec x, vec y", "Component-wise x <= y, as a bvec."},
    {"greaterThan", "vec x, vec y", "Component-wise x > y, as a bvec."},
    {"greaterThanEqual", "vec x, vec y", "Component-wise x >= y, as a bvec."},
    {"equal", "vec x, vec y", "Component-wise x == y, as a bvec."},
    {"notEqual", "vec x, vec y", "Component-wise x != y, as a bvec."},
    {"any", "bvec x", "True if any component of x is true."},
    {"all", "bvec x", "True if all components of x are true."},
    {"not", "bvec x", "Component-wise logical complement."},
    // Integers
    {"bitfieldExtract", "genIType value, int offset, int bits",
     "Extracts bits [offset, offset + bits) of value."},
    {"bitfieldInsert", "genIType base, genIType insert, int offset, int bits",
     "Inserts the low bits of insert into base."},
    {"bitCount", "genIType value", "Number of one bits."},
    {"findLSB", "genIType value", "Index of the lowest one bit, -1 for zero."},
    {"findMSB", "genIType value", "Index of the highest one bit (sign-aware), -1 if none."},
    // Textures
    {"texture", "gsampler sampler, vec P [, float bias]",
     "Samples the texture at coordinates P (the shadow forms compare against P's last component)."},
    {"textureLod", "gsampler sampler, vec P, float lod", "Samples mip level lod explicitly."},
    {"textureOffset", "gsampler sampler, vec P, ivec offset [, float bias]",
     "Samples with a constant texel offset."},
    {"textureProj", "gsampler sampler, vec P [, float bias]",
     "Samples at P.xy / P.w (projective texturing)."},
    {"textureGrad", "gsampler sampler, vec P, vec dPdx, vec dPdy",
     "Samples with explicit derivatives."},
    {"textureSize", "gsampler sampler, int lod", "Size of mip level lod in texels."},
    {"texelFetch", "gsampler sampler, ivec P, int lod",
     "Reads one texel by integer coordinates, no filtering."},
    {"textureGather", "gsampler2D sampler, vec2 P [, int comp]",
     "The four texels bilinear filtering would use, one component each."},
    {"textureQueryLod", "gsampler sampler, vec P",
     "The mip level (x) and lambda (y) the sampler would use."},
    // Fragment processing
    {"dFdx", "genType p", "Derivative of p along window x (fragment shaders only)."},
    {"dFdy", "genType p", "Derivative of p along window y (fragment shaders only)."},
    {"fwidth", "genType p", "abs(dFdx(p)) + abs(dFdy(p)); handy for anti-aliased edges."},
    {"interpolateAtCentroid", "genType interpolant",
     "The input interpolated at the pixel's covered centroid."},
    {"interpolateAtSample", "genType interpolant, int sample",
     "The input interpolated at a sample."},
    {"interpolateAtOffset", "genType interpolant, vec2 offset",
     "The input interpolated at an offset from the pixel centre."},
    // Geometry shaders
    {"EmitVertex", "", "Emits the current output values as a vertex (geometry shaders)."},
    {"EndPrimitive", "", "Ends the current output primitive (geometry shaders)."},
    // Built-in variables
    {"gl_Position", "vec4",
     "Vertex shader output: clip-space position (projection * view * model * vertex).", false},
    {"gl_PointSize", "float",
     "Vertex shader output: point size in pixels (needs GL_PROGRAM_POINT_SIZE).", false},
    {"gl_ClipDistance", "float[]", "Vertex shader output: distances to user clip planes.", false},
    {"gl_VertexID", "int", "Vertex shader input: index of the vertex being processed.", false},
    {"gl_InstanceID", "int", "Vertex shader input: index of the instance being drawn.", false},
    {"gl_FragCoord", "vec4",
     "Fragment shader input: window coordinates (pixel centre x, y; depth z; 1/w).", false},
    {"gl_FrontFacing", "bool", "Fragment shader input: true for front-facing primitives.", false},
    {"gl_PointCoord", "vec2", "Fragment shader input: position within a point sprite, [0, 1].",
     false},
    {"gl_PrimitiveID", "int", "Index of the current primitive.", false},
    {"gl_SampleID", "int", "Fragment shader input: the sample being processed.", false},
    {"gl_FragDepth", "float", "Fragment shader output: depth to write instead of gl_FragCoord.z.",
     false},
    {"gl_Layer", "int", "Layer of a layered framebuffer to render to.", false},
    {"gl_MaxDrawBuffers", "const int", "Number of fragment outputs available.", false},
    // GLSL ES 1.00 (WebGL 1) only: what texture() and out variables replaced
    {"texture2D", "sampler2D sampler, vec2 P [, float bias]",
     "GLSL ES 1.00: samples a 2D texture (texture() in later GLSL)."},
    {"texture2DProj", "sampler2D sampler, vec3 P [, float bias]",
     "GLSL ES 1.00: samples at P.xy / P.z."},
    {"textureCube", "samplerCube sampler, vec3 P [, float bias]",
     "GLSL ES 1.00: samples a cube map (texture() in later GLSL)."},
    {"gl_FragColor", "vec4",
     "GLSL ES 1.00 fragment shader output: the colour (an `out vec4` in later GLSL).", false},
    {"gl_FragData", "vec4[]", "GLSL ES 1.00 fragment shader outputs, one per draw buffer.", false},
};

// What GLSL ES 1.00 has of the list above (its whole library is small).
const QSet<QString> &es100Names()
{
    static const QSet<QString> names = [] {
        QSet<QString> set;
        for (const char *name :
             {"radians",       "degrees",       "sin",           "cos",
              "tan",           "asin",          "acos",          "atan",
              "pow",           "exp",           "log",           "exp2",
              "log2",          "sqrt",          "inversesqrt",   "abs",
              "sign",          "floor",         "ceil",          "fract",
              "mod",           "min",           "max",           "clamp",
              "mix",           "step",          "smoothstep",    "length",
              "distance",      "dot",           "cross",         "normalize",
              "faceforward",   "reflect",       "refract",       "matrixCompMult",
              "lessThan",      "lessThanEqual", "greaterThan",   "greaterThanEqual",
              "equal",         "notEqual",      "any",           "all",
              "not",           "texture2D",     "texture2DProj", "textureCube",
              "gl_Position",   "gl_PointSize",  "gl_FragCoord",  "gl_FrontFacing",
              "gl_PointCoord", "gl_FragColor",  "gl_FragData",   "gl_MaxDrawBuffers"})
            set.insert(QString::fromLatin1(name));
        return set;
    }();
    return names;
}

bool availableIn(const GlslBuiltin &builtin, ShaderDialect dialect)
{
    const QString name = QString::fromLatin1(builtin.name);
    static const QSet<QString> es100Only{
        QStringLiteral("texture2D"), QStringLiteral("texture2DProj"), QStringLiteral("textureCube"),
        QStringLiteral("gl_FragColor"), QStringLiteral("gl_FragData")};
    static const QSet<QString> desktopOnly{
        QStringLiteral("gl_ClipDistance"), QStringLiteral("gl_PrimitiveID"),
        QStringLiteral("gl_SampleID"), QStringLiteral("gl_Layer")};
    switch (dialect) {
    case ShaderDialect::Es100: return es100Names().contains(name);
    case ShaderDialect::Es300: return !es100Only.contains(name) && !desktopOnly.contains(name);
    case ShaderDialect::Desktop: return !es100Only.contains(name);
    }
    return true;
}

const QSet<QString> &builtinNameSet()
{
    static const QSet<QString> names = [] {
        QSet<QString> set;
        for (const GlslBuiltin &builtin : kBuiltins)
            set.insert(QString::fromLatin1(builtin.name));
        return set;
    }();
    return names;
}

// Call tips are shown as one box; keep it narrow enough for a docked editor.
QString wrapped(const QString &text, int width = 76)
{
    QStringList lines;
    QString line;
    for (const QString &word : text.split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
        if (!line.isEmpty() && line.size() + 1 + word.size() > width) {
            lines << line;
            line.clear();
        }
        line += (line.isEmpty() ? QString() : QStringLiteral(" ")) + word;
    }
    if (!line.isEmpty())
        lines << line;
    return lines.join(QLatin1Char('\n'));
}

QString withoutComments(QString code)
{
    static const QRegularExpression comments(QStringLiteral(R"(//[^\n]*|/\*.*?\*/)"),
                                             QRegularExpression::DotMatchesEverythingOption);
    return code.replace(comments, QStringLiteral(" "));
}

// The names after the first in `type a, b[2], c = f(x, y);`, scanning from
// `from` (just after the first name) to the end of the statement. A comma
// followed by a type and a name starts the next parameter instead.
QStringList followingDeclarators(const QString &text, qsizetype from)
{
    static const QRegularExpression next(QStringLiteral(R"(\G,\s*([A-Za-z_]\w*)(?!\s*\w))"));
    QStringList names;
    int depth = 0;
    for (qsizetype i = from; i < text.size(); ++i) {
        const QChar c = text.at(i);
        if (c == QLatin1Char('(') || c == QLatin1Char('['))
            ++depth;
        else if (c == QLatin1Char(')') || c == QLatin1Char(']'))
            --depth;
        if (depth < 0 || c == QLatin1Char(';') || c == QLatin1Char('{'))
            break;
        if (depth == 0 && c == QLatin1Char(',')) {
            const auto match = next.match(text, i);
            if (match.hasMatch())
                names << match.captured(1);
        }
    }
    return names;
}

} // namespace

GlslApi::GlslApi(QsciLexer *lexer)
    : QsciAbstractAPIs(lexer)
{
}

const std::vector<GlslBuiltin> &GlslApi::builtins()
{
    return kBuiltins;
}

QStringList GlslApi::builtinNames()
{
    QStringList names;
    for (const GlslBuiltin &builtin : kBuiltins)
        names << QString::fromLatin1(builtin.name);
    names.sort();
    return names;
}

QStringList GlslApi::builtinNames(ShaderDialect dialect)
{
    QStringList names;
    for (const GlslBuiltin &builtin : kBuiltins)
        if (availableIn(builtin, dialect))
            names << QString::fromLatin1(builtin.name);
    names.sort();
    return names;
}

QString GlslApi::callTip(const QString &name)
{
    for (const GlslBuiltin &builtin : kBuiltins) {
        if (!builtin.isFunction || name != QLatin1String(builtin.name))
            continue;
        // The signature stays on the first line: QScintilla highlights the
        // current argument by counting commas from the first '('.
        return QStringLiteral("%1(%2)\n%3")
            .arg(name, QString::fromLatin1(builtin.signature),
                 wrapped(QString::fromLatin1(builtin.doc)));
    }
    return {};
}

QStringList GlslApi::parseDeclaredNames(const QString &code)
{
    static const QRegularExpression structNames(QStringLiteral(R"(\bstruct\s+([A-Za-z_]\w*))"));
    const QString text = withoutComments(code);

    QSet<QString> found;
    for (const auto &match : structNames.globalMatch(text))
        found.insert(match.captured(1));
    // A declaration is a type followed by a name; the user's structs are types too.
    QString types = QStringLiteral(
        R"(void|bool|int|uint|float|double|[bdiu]?vec[234]|d?mat[234](?:x[234])?|[iu]?sampler\w+)");
    for (const QString &structName : std::as_const(found))
        types += QLatin1Char('|') + QRegularExpression::escape(structName);
    const QRegularExpression declarations(
        QStringLiteral(R"(\b(%1)\s*(?:\[[^\]]*\])?\s+([A-Za-z_]\w*))").arg(types));

    for (const auto &match : declarations.globalMatch(text)) {
        found.insert(match.captured(2));
        for (const QString &name : followingDeclarators(text, match.capturedEnd(2)))
            found.insert(name);
    }
    QStringList names;
    for (const QString &name : std::as_const(found))
        if (!builtinNameSet().contains(name) && !name.startsWith(QLatin1String("gl_")))
            names << name;
    names.sort();
    return names;
}

QStringList GlslApi::keywords() const
{
    const char *words = lexer() ? lexer()->keywords(1) : nullptr;
    return words ? QString::fromLatin1(words).split(QLatin1Char(' '), Qt::SkipEmptyParts)
                 : QStringList();
}

void GlslApi::updateAutoCompletionList(const QStringList &context, QStringList &list)
{
    // After a '.' come swizzles and struct members, which these lists do not
    // hold; the words of the document still complete them.
    if (context.size() != 1 || context.last().isEmpty())
        return;
    const QString &prefix = context.last();
    const auto addMatching = [&](const QStringList &words) {
        for (const QString &word : words)
            if (word.startsWith(prefix) && !list.contains(word))
                list << word;
    };
    addMatching(m_declared);
    addMatching(builtinNames(m_dialect));
    addMatching(keywords());
}

QStringList GlslApi::callTips(const QStringList &context, int commas,
                              QsciScintilla::CallTipsStyle style, QList<int> &shifts)
{
    Q_UNUSED(commas);
    Q_UNUSED(style);
    Q_UNUSED(shifts); // the tip is shown at the '(' with no context prepended
    // The last element is always empty; the function name comes before it.
    if (context.size() != 2)
        return {};
    const QString tip = callTip(context.first());
    return tip.isEmpty() ? QStringList() : QStringList{tip};
}

} // namespace phonglab
