#pragma once
#include "core/program/ShaderDialect.h"
#include "render/program/ShaderDiagnostic.h"

#include <Qsci/qsciscintilla.h>

#include <QList>
#include <vector>

class QTimer;

namespace phonglab {

class GlslApi;
class GlslLexer;

// A GLSL source editor: highlighting, line numbers, brace matching,
// auto-indent, completion of built-ins and of the program's own names, call
// tips, and compiler diagnostics shown where they point: a margin marker
// (red circle for errors, orange triangle for warnings), a boxed message
// under the line and a squiggle under the word at the reported column.
class ShaderEditor : public QsciScintilla
{
    Q_OBJECT

public:
    explicit ShaderEditor(QWidget *parent = nullptr);

    // The text as bytes, and replacing it without an undo step: the
    // document is left unmodified (its save point is the new text).
    QByteArray code() const;
    void setCode(const QByteArray &code);

    // Replaces all markers, annotations and squiggles. Diagnostics without
    // a line are left to the diagnostic list; lines past the end go on the
    // last line.
    void setDiagnostics(const std::vector<ShaderDiagnostic> &diagnostics);
    void clearDiagnostics();
    // What the check found on these lines (ui/check/CheckMarks): a purple
    // arrow and a box under the line, beside the compiler's own; replaces
    // the check's marks before.
    void setCheckMarks(const std::vector<ShaderDiagnostic> &marks);
    QList<int> checkMarkLines() const;

    // For tests and tools: 1-based lines holding a marker of `severity`,
    // the annotation under 1-based `line`, and the text a diagnostic
    // squiggle covers on that line (empty if none).
    QList<int> markerLines(ShaderDiagnostic::Severity severity) const;
    QString annotationText(int line) const;
    QString underlinedText(int line) const;
    int markerNumber(ShaderDiagnostic::Severity severity) const;

    // Puts the cursor on 1-based `line` and `column` (0 = line start), scrolls
    // there and takes the focus.
    void goTo(int line, int column);

    // Room for `columns` characters of code: the text, the margins, the
    // vertical scroll bar and the frame (pixels).
    int widthForColumns(int columns) const;
    // Whole characters of code the editor shows across at its present width.
    int visibleColumns() const;
    // Room for kPreferredColumns: what the dock holding the editor asks for.
    QSize sizeHint() const override;
    static constexpr int kPreferredColumns = 80;
    static constexpr int kPreferredLines = 30;

    GlslLexer *glslLexer() const { return m_lexer; }
    GlslApi *api() const { return m_api; }
    // Re-reads the names the program declares for completion. Runs by itself
    // shortly after typing pauses; call it to have them at once.
    void refreshDeclaredNames();

protected:
    // The line being typed stays in view when the editor shrinks (the error
    // list appearing under it) or grows, if it was in view before.
    void resizeEvent(QResizeEvent *event) override;

private:
    // Whether 0-based `line` is among the lines shown when `shownLines` fit.
    bool lineInView(int line, long shownLines) const;
    int cursorLine() const;
    void followDialect(ShaderDialect dialect);
    double characterWidth() const;
    int textAreaOffset() const; // margins and padding left and right of the text
    void setUpAppearance();
    void setUpMargins();
    void setUpDiagnosticStyles();
    void setUpEditing();
    void addShortcuts();
    void showMarks();
    QList<int> linesWithMarker(int marker) const;
    void underline(int line, int column, int indicator);
    void clearIndicator(int indicator);
    int indicatorFor(ShaderDiagnostic::Severity severity) const;

    GlslLexer *m_lexer = nullptr;
    GlslApi *m_api = nullptr;
    QTimer *m_declarationTimer = nullptr;
    int m_errorMarker = -1;
    int m_warningMarker = -1;
    int m_checkMarker = -1;
    std::vector<ShaderDiagnostic> m_diagnostics; // the compiler's
    std::vector<ShaderDiagnostic> m_checkMarks;
    int m_errorIndicator = -1;
    int m_warningIndicator = -1;
};

} // namespace phonglab
