#pragma once
#include "core/program/ShaderDialect.h"

#include <Qsci/qsciabstractapis.h>

#include <QStringList>
#include <vector>

namespace phonglab {

// One GLSL built-in: a function with its parameters, or a variable with its
// type, and a one-line explanation.
struct GlslBuiltin {
    const char *name;
    const char *signature; // functions: "genType I, genType N"; variables: "vec4"
    const char *doc;
    bool isFunction = true;
};

// Completion and call tips for the shader editor: GLSL's built-in functions
// and variables (with signatures and short docs), its keywords and types
// (taken from the lexer), and the names the program itself declares.
//
// A QsciAbstractAPIs rather than a QsciAPIs: QsciAPIs must re-"prepare" its
// whole word list in a worker thread whenever one entry changes, while the
// program's own names change as the user types; answering from two small
// lists directly is instant and has no preparation to wait for.
class GlslApi : public QsciAbstractAPIs
{
    Q_OBJECT

public:
    explicit GlslApi(QsciLexer *lexer);

    static const std::vector<GlslBuiltin> &builtins();
    static QStringList builtinNames(); // of every dialect
    // What the dialect has: GLSL ES 1.00 has texture2D and gl_FragColor, and
    // no inverse(), transpose() or texture().
    static QStringList builtinNames(ShaderDialect dialect);
    // Completion offers the dialect's built-ins (ShaderEditor follows the
    // text's #version line).
    void setDialect(ShaderDialect dialect) { m_dialect = dialect; }
    ShaderDialect dialect() const { return m_dialect; }
    // "reflect(genType I, genType N)" and its doc wrapped below it; empty for
    // names that are not built-in functions.
    static QString callTip(const QString &name);

    // Names declared in `code`: uniforms, ins, outs, constants, locals,
    // parameters, functions and structs (`uniform vec3 kd;` gives "kd").
    // Comments are ignored. Sorted, without duplicates or GLSL's own words.
    static QStringList parseDeclaredNames(const QString &code);
    void setDeclaredNames(const QStringList &names) { m_declared = names; }
    QStringList declaredNames() const { return m_declared; }

    // QsciAbstractAPIs
    void updateAutoCompletionList(const QStringList &context, QStringList &list) override;
    QStringList callTips(const QStringList &context, int commas, QsciScintilla::CallTipsStyle style,
                         QList<int> &shifts) override;

private:
    QStringList keywords() const;

    QStringList m_declared;
    ShaderDialect m_dialect = ShaderDialect::Desktop;
};

} // namespace phonglab
