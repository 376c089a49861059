#include "GlslLexer.h"

#include "GlslApi.h"

#include <QFontDatabase>
#include <array>

namespace phonglab {

namespace {

// GLSL 3.30 - 4.60 keywords, qualifiers and types (set 1).
const char kKeywords[] =
    "attribute const uniform varying buffer shared coherent volatile restrict readonly writeonly "
    "layout centroid flat smooth noperspective patch sample invariant precise "
    "break continue do for while switch case default if else discard return struct subroutine "
    "in out inout true false lowp mediump highp precision "
    "void bool int uint float double atomic_uint "
    "vec2 vec3 vec4 ivec2 ivec3 ivec4 bvec2 bvec3 bvec4 uvec2 uvec3 uvec4 dvec2 dvec3 dvec4 "
    "mat2 mat3 mat4 mat2x2 mat2x3 mat2x4 mat3x2 mat3x3 mat3x4 mat4x2 mat4x3 mat4x4 "
    "dmat2 dmat3 dmat4 dmat2x2 dmat2x3 dmat2x4 dmat3x2 dmat3x3 dmat3x4 dmat4x2 dmat4x3 dmat4x4 "
    "sampler1D sampler2D sampler3D samplerCube sampler2DRect samplerBuffer sampler2DMS "
    "sampler1DArray sampler2DArray samplerCubeArray sampler2DMSArray "
    "sampler1DShadow sampler2DShadow samplerCubeShadow sampler2DRectShadow "
    "sampler1DArrayShadow sampler2DArrayShadow samplerCubeArrayShadow "
    "isampler1D isampler2D isampler3D isamplerCube isampler2DRect isamplerBuffer isampler2DMS "
    "isampler1DArray isampler2DArray isamplerCubeArray isampler2DMSArray "
    "usampler1D usampler2D usampler3D usamplerCube usampler2DRect usamplerBuffer usampler2DMS "
    "usampler1DArray usampler2DArray usamplerCubeArray usampler2DMSArray "
    "image1D image2D image3D imageCube image2DRect imageBuffer image1DArray image2DArray "
    "iimage2D uimage2D";

// GLSL ES 1.00 (WebGL 1): attribute and varying, no uint, few samplers.
const char kEs100Keywords[] =
    "attribute const uniform varying break continue do for while if else discard return struct "
    "in out inout true false lowp mediump highp precision invariant "
    "void bool int float vec2 vec3 vec4 bvec2 bvec3 bvec4 ivec2 ivec3 ivec4 mat2 mat3 mat4 "
    "sampler2D samplerCube";

// GLSL ES 3.00 (WebGL 2): in/out and layout, no attribute/varying, no doubles.
const char kEs300Keywords[] =
    "const uniform layout centroid flat smooth invariant "
    "break continue do for while switch case default if else discard return struct "
    "in out inout true false lowp mediump highp precision "
    "void bool int uint float vec2 vec3 vec4 ivec2 ivec3 ivec4 bvec2 bvec3 bvec4 uvec2 uvec3 "
    "uvec4 mat2 mat3 mat4 mat2x2 mat2x3 mat2x4 mat3x2 mat3x3 mat3x4 mat4x2 mat4x3 mat4x4 "
    "sampler2D sampler3D samplerCube sampler2DShadow samplerCubeShadow sampler2DArray "
    "sampler2DArrayShadow isampler2D isampler3D isamplerCube isampler2DArray usampler2D "
    "usampler3D usamplerCube usampler2DArray";

QByteArray builtinWords(ShaderDialect dialect)
{
    return GlslApi::builtinNames(dialect).join(QLatin1Char(' ')).toLatin1();
}

bool isComment(int style)
{
    switch (style) {
    case QsciLexerCPP::Comment:
    case QsciLexerCPP::CommentLine:
    case QsciLexerCPP::CommentDoc:
    case QsciLexerCPP::CommentLineDoc:
    case QsciLexerCPP::PreProcessorComment:
    case QsciLexerCPP::PreProcessorCommentLineDoc: return true;
    default: return false;
    }
}

} // namespace

GlslLexer::GlslLexer(QObject *parent)
    : QsciLexerCPP(parent)
{
}

const char *GlslLexer::keywords(int set) const
{
    // Must outlive the returned pointers.
    static const std::array<QByteArray, 3> builtins = {builtinWords(ShaderDialect::Desktop),
                                                       builtinWords(ShaderDialect::Es300),
                                                       builtinWords(ShaderDialect::Es100)};
    switch (set) {
    case 1:
        return m_dialect == ShaderDialect::Es100 ? kEs100Keywords
            : m_dialect == ShaderDialect::Es300  ? kEs300Keywords
                                                 : kKeywords;
    case 2: return builtins[std::size_t(m_dialect)].constData();
    default: return nullptr; // no doc-comment keywords, no global classes
    }
}

QStringList GlslLexer::autoCompletionWordSeparators() const
{
    return {QStringLiteral(".")}; // GLSL has no "::" or "->"
}

QString GlslLexer::description(int style) const
{
    switch (style) {
    case Keyword: return tr("Keyword, qualifier or type");
    case KeywordSet2: return tr("Built-in function or variable");
    default: return QsciLexerCPP::description(style);
    }
}

QColor GlslLexer::defaultColor(int style) const
{
    if (isComment(style))
        return QColor(0x3f, 0x7f, 0x3f);
    switch (style) {
    case Keyword: return QColor(0x00, 0x33, 0xb3);
    case KeywordSet2: return QColor(0x87, 0x10, 0x94);
    case PreProcessor: return QColor(0x9e, 0x5b, 0x00);
    case Number: return QColor(0x09, 0x80, 0x80);
    case Operator: return QColor(0x40, 0x40, 0x40);
    case Default:
    case Identifier: return QColor(0x1f, 0x1f, 0x1f);
    default: return QsciLexerCPP::defaultColor(style);
    }
}

QFont GlslLexer::defaultFont(int style) const
{
    QFont font = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    font.setBold(style == Keyword);
    font.setItalic(isComment(style));
    return font;
}

void GlslLexer::refreshProperties()
{
    QsciLexerCPP::refreshProperties();
    // PhongLab injects #defines the text never shows; greying out #ifdef
    // blocks by what the document defines would mislead.
    emit propertyChanged("lexer.cpp.track.preprocessor", "0");
}

} // namespace phonglab
