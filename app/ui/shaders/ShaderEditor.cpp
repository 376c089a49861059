#include "ShaderEditor.h"

#include "GlslApi.h"
#include "GlslLexer.h"

#include <Qsci/qscistyle.h>
#include <Qsci/qscistyledtext.h>

#include <QFontDatabase>
#include <QImage>
#include <QPainter>
#include <QPainterPath>
#include <QResizeEvent>
#include <QScrollBar>
#include <QShortcut>
#include <QTimer>
#include <algorithm>
#include <cmath>
#include <map>

namespace phonglab {

namespace {

// Style numbers for the annotation boxes, clear of the C++ lexer's styles
// (0-27, 32-39 predefined, 64-91 inactive code).
constexpr int kErrorAnnotationStyle = 120;
constexpr int kWarningAnnotationStyle = 121;
constexpr int kCheckAnnotationStyle = 122;
const QColor kCheckColor(0x6a, 0x1b, 0x9a);
constexpr int kLineNumberMargin = 0;
constexpr int kMarkerMargin = 1;
constexpr int kDeclarationRefreshMs = 400;

const QColor kErrorColor(0xd7, 0x26, 0x26);
const QColor kWarningColor(0xe8, 0x8a, 0x00);

// Scintilla has no upward triangle, so the warning marker is painted.
QImage warningTriangle(int size)
{
    QImage image(size, size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    const qreal m = size * 0.1;
    QPainterPath triangle;
    triangle.moveTo(size / 2.0, m);
    triangle.lineTo(size - m, size - m);
    triangle.lineTo(m, size - m);
    triangle.closeSubpath();
    painter.fillPath(triangle, kWarningColor);
    painter.setPen(QPen(Qt::white, std::max(1.0, size / 8.0), Qt::SolidLine, Qt::RoundCap));
    painter.drawLine(QPointF(size / 2.0, size * 0.38), QPointF(size / 2.0, size * 0.62));
    painter.drawPoint(QPointF(size / 2.0, size * 0.76));
    return image;
}

QString annotationLine(const ShaderDiagnostic &diagnostic)
{
    return (diagnostic.isError() ? QStringLiteral("error: ") : QStringLiteral("warning: "))
        + diagnostic.message;
}

} // namespace

ShaderEditor::ShaderEditor(QWidget *parent)
    : QsciScintilla(parent)
    , m_lexer(new GlslLexer(this))
    , m_api(new GlslApi(m_lexer))
    , m_declarationTimer(new QTimer(this))
{
    setUtf8(true);
    setLexer(m_lexer); // applies the lexer's fonts and colours to every style
    setUpAppearance();
    setUpMargins();
    setUpDiagnosticStyles();
    setUpEditing();
    addShortcuts();

    // Parsing the whole text per keystroke would tax typing in long shaders;
    // the names are only needed once the user pauses.
    m_declarationTimer->setSingleShot(true);
    m_declarationTimer->setInterval(kDeclarationRefreshMs);
    connect(m_declarationTimer, &QTimer::timeout, this, &ShaderEditor::refreshDeclaredNames);
    connect(this, &QsciScintilla::textChanged, m_declarationTimer, qOverload<>(&QTimer::start));
}

void ShaderEditor::setUpAppearance()
{
    setCaretLineVisible(true);
    setCaretLineBackgroundColor(QColor(0xf3, 0xf6, 0xfb));
    setMatchedBraceBackgroundColor(QColor(0xd8, 0xe8, 0xd0));
    setUnmatchedBraceForegroundColor(kErrorColor);
    setAnnotationDisplay(AnnotationBoxed);
}

// Measured over a hundred characters: a character's advance is fractional,
// and 80 of them rounded one by one can be off by two columns.
double ShaderEditor::characterWidth() const
{
    const QByteArray hundred(100, '0');
    // Style 0 is the lexer's plain text, in the font the code is drawn with.
    const long width =
        SendScintilla(SCI_TEXTWIDTH, static_cast<unsigned long>(0), hundred.constData());
    return std::max(1.0, double(width) / double(hundred.size()));
}

int ShaderEditor::textAreaOffset() const
{
    int width = int(SendScintilla(SCI_GETMARGINLEFT) + SendScintilla(SCI_GETMARGINRIGHT));
    for (int margin = 0; margin < margins(); ++margin)
        width += marginWidth(margin);
    return width;
}

int ShaderEditor::widthForColumns(int columns) const
{
    return textAreaOffset() + int(std::ceil(columns * characterWidth()))
        + verticalScrollBar()->sizeHint().width() + 2 * frameWidth();
}

int ShaderEditor::visibleColumns() const
{
    return int(std::max(0, viewport()->width() - textAreaOffset()) / characterWidth());
}

QSize ShaderEditor::sizeHint() const
{
    const int lineHeight = int(SendScintilla(SCI_TEXTHEIGHT, 0));
    return {widthForColumns(kPreferredColumns), kPreferredLines * std::max(1, lineHeight)};
}

void ShaderEditor::setUpMargins()
{
    const QFont fixed = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    setMarginsFont(fixed);
    setMarginType(kLineNumberMargin, NumberMargin);
    setMarginLineNumbers(kLineNumberMargin, true);
    setMarginWidth(kLineNumberMargin, QStringLiteral("00000"));

    m_errorMarker = markerDefine(Circle);
    setMarkerBackgroundColor(kErrorColor, m_errorMarker);
    setMarkerForegroundColor(kErrorColor.darker(130), m_errorMarker);
    const int lineHeight = QFontMetrics(fixed).height();
    m_warningMarker = markerDefine(warningTriangle(std::max(10, lineHeight - 2)));
    m_checkMarker = markerDefine(RightArrow);
    setMarkerBackgroundColor(kCheckColor, m_checkMarker);
    setMarkerForegroundColor(kCheckColor.darker(130), m_checkMarker);

    setMarginType(kMarkerMargin, SymbolMargin);
    setMarginWidth(kMarkerMargin, lineHeight + 4);
    setMarginMarkerMask(kMarkerMargin,
                        (1 << m_errorMarker) | (1 << m_warningMarker) | (1 << m_checkMarker));
}

void ShaderEditor::setUpDiagnosticStyles()
{
    QFont font = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    font.setPointSizeF(font.pointSizeF() * 0.9);
    QsciStyle(kErrorAnnotationStyle, tr("Error annotation"), QColor(0x8b, 0x0d, 0x0d),
              QColor(0xfd, 0xe8, 0xe8), font)
        .apply(this);
    QsciStyle(kWarningAnnotationStyle, tr("Warning annotation"), QColor(0x7a, 0x4a, 0x00),
              QColor(0xfd, 0xf3, 0xdc), font)
        .apply(this);
    QsciStyle(kCheckAnnotationStyle, tr("Check annotation"), kCheckColor.darker(120),
              QColor(0xf3, 0xe5, 0xf5), font)
        .apply(this);

    m_errorIndicator = indicatorDefine(SquiggleIndicator);
    setIndicatorForegroundColor(kErrorColor, m_errorIndicator);
    m_warningIndicator = indicatorDefine(SquiggleIndicator);
    setIndicatorForegroundColor(kWarningColor, m_warningIndicator);
}

void ShaderEditor::setUpEditing()
{
    setTabWidth(4);
    setIndentationsUseTabs(false);
    setIndentationWidth(4);
    setAutoIndent(true);
    setBackspaceUnindents(true);
    setBraceMatching(SloppyBraceMatch);
    setEolMode(EolUnix);

    setAutoCompletionSource(AcsAll);
    setAutoCompletionThreshold(2);
    setAutoCompletionCaseSensitivity(true);
    setAutoCompletionUseSingle(AcusNever);
    setCallTipsStyle(CallTipsNoContext);
    setCallTipsVisible(0); // all matching tips
    setCallTipsPosition(CallTipsBelowText);
}

void ShaderEditor::addShortcuts()
{
    auto *complete =
        new QShortcut(QKeySequence(tr("Ctrl+Space")), this, nullptr, nullptr, Qt::WidgetShortcut);
    connect(complete, &QShortcut::activated, this, [this] {
        refreshDeclaredNames();
        autoCompleteFromAll();
    });
    auto *tip = new QShortcut(QKeySequence(tr("Ctrl+Shift+Space")), this, nullptr, nullptr,
                              Qt::WidgetShortcut);
    connect(tip, &QShortcut::activated, this, &ShaderEditor::callTip);
}

QByteArray ShaderEditor::code() const
{
    const int size = length();
    QByteArray text = bytes(0, size);
    // bytes() hands back Scintilla's buffer with its terminating NUL.
    if (text.size() == size + 1)
        text.chop(1);
    return text;
}

void ShaderEditor::setCode(const QByteArray &code)
{
    SendScintilla(SCI_SETTEXT, code.constData());
    SendScintilla(SCI_EMPTYUNDOBUFFER);
    setModified(false);
    refreshDeclaredNames();
}

void ShaderEditor::refreshDeclaredNames()
{
    m_declarationTimer->stop();
    const QString code = text();
    m_api->setDeclaredNames(GlslApi::parseDeclaredNames(code));
    followDialect(shaderDialectOf(code.toUtf8()));
}

// Highlighting and completion follow the #version line: a WebGL 1 shader
// sees attribute, varying, texture2D and gl_FragColor as GLSL's own words.
void ShaderEditor::followDialect(ShaderDialect dialect)
{
    if (dialect == m_lexer->dialect())
        return;
    m_lexer->setDialect(dialect);
    m_api->setDialect(dialect);
    for (int set = 1; set <= 2; ++set) // Scintilla counts keyword sets from 0
        SendScintilla(SCI_SETKEYWORDS, set - 1, m_lexer->keywords(set));
    SendScintilla(SCI_COLOURISE, 0, -1);
}

void ShaderEditor::clearDiagnostics()
{
    m_diagnostics.clear();
    showMarks();
}

void ShaderEditor::setDiagnostics(const std::vector<ShaderDiagnostic> &diagnostics)
{
    m_diagnostics = diagnostics;
    showMarks();
}

int ShaderEditor::cursorLine() const
{
    int line = 0;
    int index = 0;
    getCursorPosition(&line, &index);
    return line;
}

// In display lines, which count the boxes under lines and folded lines.
bool ShaderEditor::lineInView(int line, long shownLines) const
{
    const long display = SendScintilla(SCI_VISIBLEFROMDOCLINE, line);
    const long first = SendScintilla(SCI_GETFIRSTVISIBLELINE);
    return display >= first && display < first + std::max(shownLines, 1L);
}

void ShaderEditor::resizeEvent(QResizeEvent *event)
{
    // The event is the text area's own, which already has its new height:
    // the lines it showed before are those of its old height.
    const int lineHeight = std::max(1, textHeight(0));
    const int line = cursorLine();
    const bool wasInView =
        event->oldSize().isValid() && lineInView(line, event->oldSize().height() / lineHeight);
    QsciScintilla::resizeEvent(event);
    if (wasInView && !lineInView(line, SendScintilla(SCI_LINESONSCREEN)))
        ensureLineVisible(line);
}

void ShaderEditor::setCheckMarks(const std::vector<ShaderDiagnostic> &marks)
{
    m_checkMarks = marks;
    showMarks();
}

QList<int> ShaderEditor::checkMarkLines() const
{
    return linesWithMarker(m_checkMarker);
}

// The compiler's diagnostics and the check's marks, each line's messages in
// one box under it: errors, warnings, then what the check found.
void ShaderEditor::showMarks()
{
    for (int marker : {m_errorMarker, m_warningMarker, m_checkMarker})
        markerDeleteAll(marker);
    clearAnnotations();
    clearIndicator(m_errorIndicator);
    clearIndicator(m_warningIndicator);
    const int lastLine = std::max(0, lines() - 1);
    std::map<int, QList<QsciStyledText>> byLine;
    const auto add = [&](const ShaderDiagnostic &d, int marker, int style) {
        if (d.line <= 0)
            return;
        const int line = std::min(d.line - 1, lastLine);
        const QString text = marker == m_checkMarker ? d.message : annotationLine(d);
        QList<QsciStyledText> &texts = byLine[line];
        if (std::any_of(texts.begin(), texts.end(),
                        [&](const QsciStyledText &t) { return t.text().trimmed() == text; }))
            return; // drivers repeat some messages verbatim
        texts << QsciStyledText(text, style);
        markerAdd(line, marker);
        if (d.column > 0 && d.line - 1 <= lastLine && marker != m_checkMarker)
            underline(line, d.column, indicatorFor(d.severity));
    };
    for (const ShaderDiagnostic &d : m_diagnostics)
        add(d, d.isError() ? m_errorMarker : m_warningMarker,
            d.isError() ? kErrorAnnotationStyle : kWarningAnnotationStyle);
    for (const ShaderDiagnostic &d : m_checkMarks)
        add(d, m_checkMarker, kCheckAnnotationStyle);
    for (auto &[line, texts] : byLine) {
        for (qsizetype i = 0; i + 1 < texts.size(); ++i)
            texts[i] = QsciStyledText(texts[i].text() + QLatin1Char('\n'), texts[i].style());
        annotate(line, texts);
    }
}

void ShaderEditor::underline(int line, int column, int indicator)
{
    const long lineEnd = SendScintilla(SCI_GETLINEENDPOSITION, line);
    long start = std::min<long>(positionFromLineIndex(line, column - 1), lineEnd);
    long end = SendScintilla(SCI_WORDENDPOSITION, start, 1L);
    if (end <= start) {
        // Not on a word (an operator, or past the text): mark one character.
        if (start == lineEnd && start > SendScintilla(SCI_POSITIONFROMLINE, line))
            start = SendScintilla(SCI_POSITIONBEFORE, start);
        end = SendScintilla(SCI_POSITIONAFTER, start);
    }
    SendScintilla(SCI_SETINDICATORCURRENT, indicator);
    SendScintilla(SCI_INDICATORFILLRANGE, start, end - start);
}

void ShaderEditor::clearIndicator(int indicator)
{
    SendScintilla(SCI_SETINDICATORCURRENT, indicator);
    SendScintilla(SCI_INDICATORCLEARRANGE, 0UL, length());
}

int ShaderEditor::indicatorFor(ShaderDiagnostic::Severity severity) const
{
    return severity == ShaderDiagnostic::Severity::Error ? m_errorIndicator : m_warningIndicator;
}

int ShaderEditor::markerNumber(ShaderDiagnostic::Severity severity) const
{
    return severity == ShaderDiagnostic::Severity::Error ? m_errorMarker : m_warningMarker;
}

QList<int> ShaderEditor::markerLines(ShaderDiagnostic::Severity severity) const
{
    return linesWithMarker(markerNumber(severity));
}

QList<int> ShaderEditor::linesWithMarker(int marker) const
{
    QList<int> result;
    const unsigned mask = 1u << marker;
    for (int line = markerFindNext(0, mask); line >= 0; line = markerFindNext(line + 1, mask))
        result << line + 1;
    return result;
}

QString ShaderEditor::annotationText(int line) const
{
    return annotation(line - 1);
}

QString ShaderEditor::underlinedText(int line) const
{
    const long start = SendScintilla(SCI_POSITIONFROMLINE, line - 1);
    const long end = SendScintilla(SCI_GETLINEENDPOSITION, line - 1);
    QByteArray covered;
    for (long pos = start; pos < end; ++pos) {
        const bool marked = SendScintilla(SCI_INDICATORVALUEAT, m_errorIndicator, pos)
            || SendScintilla(SCI_INDICATORVALUEAT, m_warningIndicator, pos);
        if (marked)
            covered += static_cast<char>(SendScintilla(SCI_GETCHARAT, pos));
    }
    return QString::fromUtf8(covered);
}

void ShaderEditor::goTo(int line, int column)
{
    const int target = std::clamp(line - 1, 0, std::max(0, lines() - 1));
    // Columns past the end would run on into the next line.
    const int lineChars =
        int(text(target).remove(QLatin1Char('\n')).remove(QLatin1Char('\r')).size());
    setCursorPosition(target, std::clamp(column - 1, 0, lineChars));
    ensureLineVisible(target);
    setFocus(Qt::OtherFocusReason);
}

} // namespace phonglab
