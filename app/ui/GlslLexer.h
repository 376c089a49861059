#pragma once
#include <Qsci/qscilexercpp.h>

namespace phonglab {

// GLSL highlighting on top of Scintilla's C/C++ lexer, which already handles
// comments, numbers, operators and preprocessor lines the way GLSL writes
// them. Keyword set 1 holds GLSL's keywords, qualifiers and types; set 2 its
// built-in functions and variables (from GlslApi), shown in their own colour.
class GlslLexer : public QsciLexerCPP
{
    Q_OBJECT

public:
    explicit GlslLexer(QObject *parent = nullptr);

    const char *language() const override { return "GLSL"; }
    const char *keywords(int set) const override;
    QStringList autoCompletionWordSeparators() const override;
    QString description(int style) const override;
    QColor defaultColor(int style) const override;
    QFont defaultFont(int style) const override;
    void refreshProperties() override;
};

} // namespace phonglab
