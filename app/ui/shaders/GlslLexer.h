#pragma once
#include "core/program/ShaderDialect.h"

#include <Qsci/qscilexercpp.h>

namespace phonglab {

// GLSL highlighting on top of Scintilla's C/C++ lexer, which already handles
// comments, numbers, operators and preprocessor lines the way GLSL writes
// them. Keyword set 1 holds GLSL's keywords, qualifiers and types; set 2 its
// built-in functions and variables (from GlslApi), shown in their own colour.
// Both sets follow the dialect: GLSL ES 1.00 has attribute,
// varying, texture2D and gl_FragColor, GLSL ES 3.00 and desktop GLSL do not.
class GlslLexer : public QsciLexerCPP
{
    Q_OBJECT

public:
    explicit GlslLexer(QObject *parent = nullptr);

    const char *language() const override { return "GLSL"; }
    // Takes effect when the editor sets the keywords again (ShaderEditor).
    void setDialect(ShaderDialect dialect) { m_dialect = dialect; }
    ShaderDialect dialect() const { return m_dialect; }
    const char *keywords(int set) const override;
    QStringList autoCompletionWordSeparators() const override;
    QString description(int style) const override;
    QColor defaultColor(int style) const override;
    QFont defaultFont(int style) const override;
    void refreshProperties() override;

private:
    ShaderDialect m_dialect = ShaderDialect::Desktop;
};

} // namespace phonglab
