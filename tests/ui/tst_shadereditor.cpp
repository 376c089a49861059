// The shader dock and its editor without a GL context: GLSL highlighting,
// diagnostics in the margin, under the line and in the list, completion and
// call tips, and the file rules: shipped shaders are never written, edits go
// to user copies, and changes made on disk by others are reloaded or kept.

#include "ResultChecks.h"
#include "ShaderDockParts.h"
#include "ui/shaders/DiagnosticList.h"
#include "ui/shaders/GlslApi.h"
#include "ui/shaders/GlslLexer.h"
#include "ui/shaders/ShaderDock.h"
#include "ui/shaders/ShaderEditor.h"
#include "ui/shaders/ShaderFileSet.h"

#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QMessageBox>
#include <QPushButton>
#include <QSaveFile>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

using namespace phonglab;
using Severity = ShaderDiagnostic::Severity;

namespace {

QByteArray readAll(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// The way many editors save: a new file renamed over the old one.
void writeExternally(const QString &path, const QByteArray &code)
{
    QSaveFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(code);
    QVERIFY(file.commit());
}

ShaderDiagnostic diagnostic(BuildStep step, Severity severity, int line, int column,
                            const QString &message)
{
    ShaderDiagnostic d;
    d.step = step;
    d.severity = severity;
    d.file = QStringLiteral("/somewhere/phong.frag");
    d.line = line;
    d.column = column;
    d.message = message;
    return d;
}

int styleAt(ShaderEditor &editor, int line, int index)
{
    editor.SendScintilla(QsciScintilla::SCI_COLOURISE, 0, -1);
    return int(editor.SendScintilla(QsciScintilla::SCI_GETSTYLEAT,
                                    editor.positionFromLineIndex(line, index)));
}

// Whether the cursor's line is among those the editor shows, counted as
// Scintilla counts them (a box under a line takes lines of its own).
bool cursorLineInView(ShaderEditor &editor)
{
    int line = 0;
    int index = 0;
    editor.getCursorPosition(&line, &index);
    const long display = editor.SendScintilla(QsciScintilla::SCI_VISIBLEFROMDOCLINE, line);
    const long first = editor.SendScintilla(QsciScintilla::SCI_GETFIRSTVISIBLELINE);
    const long shown = editor.SendScintilla(QsciScintilla::SCI_LINESONSCREEN);
    return display >= first && display < first + shown;
}

QString currentCompletion(ShaderEditor &editor)
{
    QByteArray buffer(256, '\0');
    const long size =
        editor.SendScintilla(QsciScintilla::SCI_AUTOCGETCURRENTTEXT, 0UL, buffer.data());
    return QString::fromUtf8(buffer.left(size));
}

const QByteArray kSmallShader = "#version 330 core\n"                    // 1
                                "// lighting\n"                          // 2
                                "uniform vec3 kd;\n"                     // 3
                                "in vec3 normalCam;\n"                   // 4
                                "out vec4 fragColor;\n"                  // 5
                                "void main()\n"                          // 6
                                "{\n"                                    // 7
                                "    vec3 N = normalize(normalCam);\n"   // 8
                                "    fragColor = vec4(kd * N.z, 1.0);\n" // 9
                                "}\n";                                   // 10

} // namespace

class TestShaderEditor : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();

    void lexerColoursKeywordsBuiltinsAndComments();
    void errorMarksOnlyItsLine();
    void warningUsesItsOwnMarker();
    void diagnosticsWithoutLineOnlyInList();
    void linkErrorsGoToFragmentEditor();
    void clickingADiagnosticMovesTheCursor();
    void completionOffersBuiltinsAndDeclaredNames();
    void highlightingAndCompletionFollowTheDialect();
    void typingOpensCompletionList();
    void callTipExplainsIncidentVector();
    void declaredNamesCoverDeclarationForms();

    void editingShippedShaderWritesUserCopy();
    void userCopiesGetNumberedNames();
    void saveAsRefusesShippedFolder();
    void dirtyMarkerFollowsEditsAndSaves();
    void externalChangeReloadsCleanBuffer();
    void externalChangeKeepsDirtyBuffer();
    void externalChangeReloadPolicy();
    void externalChangeAsksTheUser();
    void openPairAssignsStagesByName();
    void openFileTakesTheStageItIsGiven();
    void toolBarFileButtonsAreRequests();
    void f5AndPresetBoxEmitRequests();
    void dockShowsErrorAnnotation();
    void cursorLineStaysInViewAsTheErrorListComesAndGoes();

private:
    QString shippedPath(const QString &name) const
    {
        return m_dir.filePath(QStringLiteral("shipped/") + name);
    }
    QString ownPath(const QString &name) const
    {
        return m_dir.filePath(QStringLiteral("own/") + name);
    }
    // A dock that treats the temporary "shipped" folder as PhongLab's own.
    void configure(ShaderDock &dock) const;
    void loadShipped(ShaderDock &dock) const;

    QTemporaryDir m_dir;
};

void TestShaderEditor::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true); // user copies go to ~/.qttest, not the real profile
    QVERIFY(m_dir.isValid());
    QVERIFY(QDir().mkpath(m_dir.filePath(QStringLiteral("shipped"))));
    QVERIFY(QDir().mkpath(m_dir.filePath(QStringLiteral("own"))));
    for (const char *name : {"phong.vert", "phong.frag"}) {
        const QString source =
            QStringLiteral(PHONGLAB_SOURCE_DIR "/shaders/") + QLatin1String(name);
        QVERIFY(QFile::copy(source, shippedPath(QLatin1String(name))));
    }
}

void TestShaderEditor::init()
{
    // Test mode: this is ~/.qttest/share/<test>/shaders, private to this test.
    QDir(ShaderFileSet::userFolder()).removeRecursively();
}

void TestShaderEditor::configure(ShaderDock &dock) const
{
    dock.files()->setShippedFolders({m_dir.filePath(QStringLiteral("shipped"))});
}

void TestShaderEditor::loadShipped(ShaderDock &dock) const
{
    configure(dock);
    dock.setSources(ShaderSource::fromFile(shippedPath(QStringLiteral("phong.vert"))).value(),
                    ShaderSource::fromFile(shippedPath(QStringLiteral("phong.frag"))).value());
}

void TestShaderEditor::lexerColoursKeywordsBuiltinsAndComments()
{
    ShaderEditor editor;
    editor.setCode(kSmallShader);
    QCOMPARE(QString::fromLatin1(editor.glslLexer()->language()), QStringLiteral("GLSL"));

    const int keyword = styleAt(editor, 2, 0);   // "uniform"
    const int type = styleAt(editor, 2, 8);      // "vec3"
    const int builtin = styleAt(editor, 7, 13);  // "normalize"
    const int comment = styleAt(editor, 1, 3);   // "// lighting"
    const int directive = styleAt(editor, 0, 1); // "#version"
    QCOMPARE(keyword, int(QsciLexerCPP::Keyword));
    QCOMPARE(type, int(QsciLexerCPP::Keyword));
    QCOMPARE(builtin, int(QsciLexerCPP::KeywordSet2));
    QCOMPARE(comment, int(QsciLexerCPP::CommentLine));
    QCOMPARE(directive, int(QsciLexerCPP::PreProcessor));
    QCOMPARE(styleAt(editor, 8, 21), int(QsciLexerCPP::Identifier)); // "kd": the user's own

    // Blocks behind #ifdef stay coloured: PhongLab injects #defines the
    // document does not show, so the lexer cannot know what is inactive.
    editor.setCode("#ifdef FLAT_SHADING\nuniform vec3 kd;\n#endif\n");
    QCOMPARE(styleAt(editor, 1, 0), int(QsciLexerCPP::Keyword));

    const GlslLexer *lexer = editor.glslLexer();
    const QList<QColor> colours = {lexer->color(keyword), lexer->color(builtin),
                                   lexer->color(comment), lexer->color(directive),
                                   lexer->color(QsciLexerCPP::Identifier)};
    for (qsizetype i = 0; i < colours.size(); ++i)
        for (qsizetype j = i + 1; j < colours.size(); ++j)
            QVERIFY2(colours[i] != colours[j],
                     qPrintable(QStringLiteral("styles %1 and %2 share a colour").arg(i).arg(j)));
}

void TestShaderEditor::errorMarksOnlyItsLine()
{
    ShaderEditor editor;
    editor.setCode(kSmallShader);
    editor.setDiagnostics({diagnostic(BuildStep::CompileFragment, Severity::Error, 8, 14,
                                      QStringLiteral("no function 'normalize' for ivec3"))});

    QCOMPARE(editor.markerLines(Severity::Error), QList<int>{8});
    QVERIFY(editor.markerLines(Severity::Warning).isEmpty());
    QCOMPARE(editor.annotationText(8), QStringLiteral("error: no function 'normalize' for ivec3"));
    QCOMPARE(editor.underlinedText(8), QStringLiteral("normalize"));
    for (int line = 1; line <= editor.lines(); ++line) {
        if (line == 8)
            continue;
        QVERIFY2(editor.annotationText(line).isEmpty(), qPrintable(QString::number(line)));
        QVERIFY2(editor.underlinedText(line).isEmpty(), qPrintable(QString::number(line)));
    }
    QCOMPARE(editor.annotationDisplay(), QsciScintilla::AnnotationBoxed);

    editor.setDiagnostics({});
    QVERIFY(editor.markerLines(Severity::Error).isEmpty());
    QVERIFY(editor.annotationText(8).isEmpty());
    QVERIFY(editor.underlinedText(8).isEmpty());
}

void TestShaderEditor::warningUsesItsOwnMarker()
{
    ShaderEditor editor;
    editor.setCode(kSmallShader);
    QVERIFY(editor.markerNumber(Severity::Error) != editor.markerNumber(Severity::Warning));
    editor.setDiagnostics(
        {diagnostic(BuildStep::CompileFragment, Severity::Warning, 4, 0,
                    QStringLiteral("unused input")),
         diagnostic(BuildStep::CompileFragment, Severity::Error, 9, 0, QStringLiteral("bad")),
         diagnostic(BuildStep::CompileFragment, Severity::Warning, 9, 0,
                    QStringLiteral("also odd"))});
    QCOMPARE(editor.markerLines(Severity::Warning), (QList<int>{4, 9}));
    QCOMPARE(editor.markerLines(Severity::Error), QList<int>{9});
    QCOMPARE(editor.annotationText(4), QStringLiteral("warning: unused input"));
    QCOMPARE(editor.annotationText(9), QStringLiteral("error: bad\nwarning: also odd"));
    QVERIFY(editor.underlinedText(4).isEmpty()); // no column, no squiggle

    // Replacing the diagnostics drops the old ones.
    editor.setDiagnostics(
        {diagnostic(BuildStep::CompileFragment, Severity::Error, 2, 0, QStringLiteral("x"))});
    QCOMPARE(editor.markerLines(Severity::Error), QList<int>{2});
    QVERIFY(editor.markerLines(Severity::Warning).isEmpty());
    QVERIFY(editor.annotationText(9).isEmpty());
}

void TestShaderEditor::diagnosticsWithoutLineOnlyInList()
{
    ShaderDock dock;
    dock.setSources({QStringLiteral("a.vert"), "void main() {}\n"},
                    {QStringLiteral("a.frag"), kSmallShader});
    dock.showDiagnostics({diagnostic(BuildStep::CompileFragment, Severity::Error, 0, 0,
                                     QStringLiteral("out of memory"))});
    QVERIFY(dock.editor(ShaderStage::Fragment)->markerLines(Severity::Error).isEmpty());
    QCOMPARE(test::diagnosticList(&dock)->count(), 1);
    QCOMPARE(test::diagnosticList(&dock)->item(0)->text(),
             QStringLiteral("phong.frag: error: out of memory"));
}

void TestShaderEditor::linkErrorsGoToFragmentEditor()
{
    ShaderDock dock;
    dock.setSources({QStringLiteral("a.vert"), kSmallShader},
                    {QStringLiteral("a.frag"), kSmallShader});
    dock.showDiagnostics(
        {diagnostic(BuildStep::Link, Severity::Error, 0, 0, QStringLiteral("no main")),
         diagnostic(BuildStep::Link, Severity::Error, 4, 0, QStringLiteral("type mismatch")),
         diagnostic(BuildStep::CompileVertex, Severity::Warning, 3, 0, QStringLiteral("unused"))});
    QCOMPARE(test::diagnosticList(&dock)->count(), 3);
    QCOMPARE(test::diagnosticList(&dock)->errorCount(), 2);
    QCOMPARE(dock.editor(ShaderStage::Fragment)->markerLines(Severity::Error), QList<int>{4});
    QVERIFY(dock.editor(ShaderStage::Vertex)->markerLines(Severity::Error).isEmpty());
    QCOMPARE(dock.editor(ShaderStage::Vertex)->markerLines(Severity::Warning), QList<int>{3});
}

void TestShaderEditor::clickingADiagnosticMovesTheCursor()
{
    ShaderDock dock;
    dock.resize(600, 500);
    dock.setSources({QStringLiteral("a.vert"), kSmallShader},
                    {QStringLiteral("a.frag"), kSmallShader});
    test::shaderTabs(&dock)->setCurrentIndex(0);
    dock.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dock));
    dock.showDiagnostics(
        {diagnostic(BuildStep::CompileVertex, Severity::Warning, 3, 2, QStringLiteral("w")),
         diagnostic(BuildStep::CompileFragment, Severity::Error, 9, 17, QStringLiteral("e"))});
    QSignalSpy spy(test::diagnosticList(&dock), &DiagnosticList::diagnosticActivated);

    DiagnosticList *list = test::diagnosticList(&dock);
    const QRect rect = list->visualItemRect(list->item(1));
    QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, rect.center());

    QCOMPARE(spy.count(), 1);
    QCOMPARE(spy.first().at(0).value<ShaderStage>(), ShaderStage::Fragment);
    QCOMPARE(spy.first().at(1).toInt(), 9);
    QCOMPARE(spy.first().at(2).toInt(), 17);
    QCOMPARE(test::shaderTabs(&dock)->currentWidget(), dock.editor(ShaderStage::Fragment));
    int line = -1;
    int index = -1;
    dock.editor(ShaderStage::Fragment)->getCursorPosition(&line, &index);
    QCOMPARE(line, 8);
    QCOMPARE(index, 16);

    dock.goTo(ShaderStage::Vertex, 3, 99); // a column past the end stays on its line
    QCOMPARE(test::shaderTabs(&dock)->currentWidget(), dock.editor(ShaderStage::Vertex));
    dock.editor(ShaderStage::Vertex)->getCursorPosition(&line, &index);
    QCOMPARE(line, 2);
    QCOMPARE(index, int(qstrlen("uniform vec3 kd;")));
}

// A WebGL 1 shader (no #version line) is GLSL ES 1.00, whose
// own words are attribute, varying, texture2D and gl_FragColor; a WebGL 2
// one (#version 300 es) has texture() and inverse(), and no attribute.
void TestShaderEditor::highlightingAndCompletionFollowTheDialect()
{
    const auto completions = [](ShaderEditor &editor, const QString &prefix) {
        QStringList list;
        editor.api()->updateAutoCompletionList({prefix}, list);
        return list;
    };
    ShaderEditor editor;
    editor.setCode("precision mediump float;\n"
                   "varying vec3 vNormal;\n"
                   "void main() { gl_FragColor = vec4(normalize(vNormal), 1.0); }\n");
    QCOMPARE(editor.glslLexer()->dialect(), ShaderDialect::Es100);
    QCOMPARE(styleAt(editor, 1, 0), int(QsciLexerCPP::Keyword));      // "varying"
    QCOMPARE(styleAt(editor, 2, 14), int(QsciLexerCPP::KeywordSet2)); // "gl_FragColor"
    QVERIFY(completions(editor, QStringLiteral("textu")).contains(QStringLiteral("texture2D")));
    QVERIFY(!completions(editor, QStringLiteral("textu")).contains(QStringLiteral("texture")));
    QVERIFY(!completions(editor, QStringLiteral("inv")).contains(QStringLiteral("inverse")));
    QVERIFY(completions(editor, QStringLiteral("attr")).contains(QStringLiteral("attribute")));

    editor.setCode("#version 300 es\n"
                   "precision mediump float;\n"
                   "in vec3 vNormal;\n"
                   "out vec4 color;\n"
                   "void main() { color = texture(tex, vec2(0.0)); }\n");
    QCOMPARE(editor.glslLexer()->dialect(), ShaderDialect::Es300);
    QVERIFY(completions(editor, QStringLiteral("textu")).contains(QStringLiteral("texture")));
    QVERIFY(!completions(editor, QStringLiteral("textu")).contains(QStringLiteral("texture2D")));
    QVERIFY(completions(editor, QStringLiteral("inv")).contains(QStringLiteral("inverse")));
    QVERIFY(!completions(editor, QStringLiteral("attr")).contains(QStringLiteral("attribute")));
    QVERIFY(
        completions(editor, QStringLiteral("gl_Frag")).contains(QStringLiteral("gl_FragCoord")));
    QVERIFY(
        !completions(editor, QStringLiteral("gl_Frag")).contains(QStringLiteral("gl_FragColor")));

    editor.setCode(kSmallShader); // #version 330 core
    QCOMPARE(editor.glslLexer()->dialect(), ShaderDialect::Desktop);
    QVERIFY(!completions(editor, QStringLiteral("textu")).contains(QStringLiteral("texture2D")));
}

void TestShaderEditor::completionOffersBuiltinsAndDeclaredNames()
{
    ShaderEditor editor;
    editor.setCode(kSmallShader);
    QStringList list;
    editor.api()->updateAutoCompletionList({QStringLiteral("refl")}, list);
    QCOMPARE(list, QStringList{QStringLiteral("reflect")});

    list.clear();
    editor.api()->updateAutoCompletionList({QStringLiteral("k")}, list);
    QVERIFY2(list.contains(QStringLiteral("kd")), qPrintable(list.join(u' ')));

    list.clear();
    editor.api()->updateAutoCompletionList({QStringLiteral("vec")}, list);
    QVERIFY(list.contains(QStringLiteral("vec3"))); // types come from the lexer's keywords

    list.clear();
    editor.api()->updateAutoCompletionList({QStringLiteral("N"), QStringLiteral("x")}, list);
    QVERIFY(list.isEmpty()); // after '.', swizzles are not ours to offer

    // Names typed later arrive once typing pauses.
    editor.append(QStringLiteral("uniform float roughness;\n"));
    QVERIFY(!editor.api()->declaredNames().contains(QStringLiteral("roughness")));
    QTRY_VERIFY(editor.api()->declaredNames().contains(QStringLiteral("roughness")));
}

void TestShaderEditor::typingOpensCompletionList()
{
    ShaderEditor editor;
    editor.resize(500, 300);
    editor.setCode(kSmallShader);
    editor.show();
    editor.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&editor));
    editor.setCursorPosition(10, 0); // the empty last line
    QTest::keyClicks(&editor, QStringLiteral("refl"));
    QVERIFY(editor.isListActive());
    QCOMPARE(currentCompletion(editor), QStringLiteral("reflect"));
    editor.cancelList();

    QTest::keyClick(&editor, Qt::Key_Return);
    QTest::keyClicks(&editor, QStringLiteral("k"));
    QVERIFY(!editor.isListActive()); // below the threshold of 2
    QTest::keyClick(&editor, Qt::Key_Space, Qt::ControlModifier);
    QVERIFY(editor.isListActive());
    editor.SendScintilla(QsciScintilla::SCI_AUTOCSELECT, 0UL, "kd");
    QCOMPARE(currentCompletion(editor), QStringLiteral("kd"));
    editor.cancelList();

    QTest::keyClick(&editor, Qt::Key_Return);
    QTest::keyClicks(&editor, QStringLiteral("reflect("));
    editor.cancelList();
    QVERIFY(editor.isCallTipActive());
}

void TestShaderEditor::callTipExplainsIncidentVector()
{
    const QString tip = GlslApi::callTip(QStringLiteral("reflect"));
    QVERIFY(tip.startsWith(QStringLiteral("reflect(genType I, genType N)\n")));
    QVERIFY(tip.contains(QStringLiteral("incident vector")));
    QVERIFY(tip.contains(QStringLiteral("toward the surface")));
    QVERIFY(tip.contains(QStringLiteral("-L")));

    ShaderEditor editor;
    QList<int> shifts;
    const QStringList tips = editor.api()->callTips({QStringLiteral("reflect"), QString()}, 0,
                                                    QsciScintilla::CallTipsNoContext, shifts);
    QCOMPARE(tips, QStringList{tip});
    QVERIFY(editor.api()
                ->callTips({QStringLiteral("kd"), QString()}, 0, QsciScintilla::CallTipsNoContext,
                           shifts)
                .isEmpty());
}

void TestShaderEditor::declaredNamesCoverDeclarationForms()
{
    const QString code = QStringLiteral(
        "// uniform vec3 commentedOut;\n"
        "struct Light { vec3 position; float power; };\n"
        "uniform Light lights[4];\n"
        "layout(location = 0) in vec3 positionModel;\n"
        "uniform mat4 modelMatrix, viewMatrix;\n"
        "const int MAX_LIGHTS = 8;\n"
        "float shade(vec3 N, in vec3 L) { float a = 1.0, b = max(a, 2.0); return a * b; }\n");
    const QStringList names = GlslApi::parseDeclaredNames(code);
    for (const char *name : {"Light", "position", "power", "lights", "positionModel", "modelMatrix",
                             "viewMatrix", "MAX_LIGHTS", "shade", "N", "L", "a", "b"})
        QVERIFY2(names.contains(QLatin1String(name)), name);
    QVERIFY(!names.contains(QStringLiteral("commentedOut")));
    QVERIFY(!names.contains(QStringLiteral("max")));
    QVERIFY(!names.contains(QStringLiteral("vec3")));
}

void TestShaderEditor::editingShippedShaderWritesUserCopy()
{
    ShaderDock dock;
    loadShipped(dock);
    const QString shipped = shippedPath(QStringLiteral("phong.frag"));
    const QByteArray original = readAll(shipped);
    QCOMPARE(dock.filePath(ShaderStage::Fragment), shipped);
    QSignalSpy filesChanged(&dock, &ShaderDock::filesChanged);

    ShaderEditor *editor = dock.editor(ShaderStage::Fragment);
    editor->insertAt(QStringLiteral("// my tweak\n"), 1, 0);

    const QString copy = QDir(ShaderFileSet::userFolder()).filePath(QStringLiteral("phong.frag"));
    QCOMPARE(dock.filePath(ShaderStage::Fragment), copy);
    QCOMPARE(filesChanged.count(), 1);
    QCOMPARE(readAll(copy), original); // the copy starts as the shipped text; the edit is unsaved
    QCOMPARE(readAll(shipped), original);
    QVERIFY(dock.isDirty(ShaderStage::Fragment));

    QString error;
    QVERIFY_OK(dock.save(ShaderStage::Fragment));
    QVERIFY(readAll(copy).contains("// my tweak"));
    QCOMPARE(readAll(copy), dock.text(ShaderStage::Fragment));
    QCOMPARE(readAll(shipped), original);

    // A clean shipped stage moves to its user copy on the first save.
    QCOMPARE(dock.filePath(ShaderStage::Vertex), shippedPath(QStringLiteral("phong.vert")));
    QVERIFY(dock.save(ShaderStage::Vertex));
    QCOMPARE(dock.filePath(ShaderStage::Vertex),
             QDir(ShaderFileSet::userFolder()).filePath(QStringLiteral("phong.vert")));
    QCOMPARE(readAll(shippedPath(QStringLiteral("phong.vert"))),
             readAll(dock.filePath(ShaderStage::Vertex)));

    // Embedded resources are shipped too.
    QVERIFY(dock.files()->isShipped(QStringLiteral(":/shaders/phong.frag")));
}

void TestShaderEditor::userCopiesGetNumberedNames()
{
    ShaderDock dock;
    const QDir user(ShaderFileSet::userFolder());
    for (const char *expected : {"phong.frag", "phong-1.frag", "phong-2.frag"}) {
        loadShipped(dock);
        dock.editor(ShaderStage::Fragment)->insertAt(QStringLiteral("// x\n"), 0, 0);
        QCOMPARE(dock.filePath(ShaderStage::Fragment), user.filePath(QLatin1String(expected)));
    }
}

void TestShaderEditor::saveAsRefusesShippedFolder()
{
    ShaderDock dock;
    loadShipped(dock);
    const QByteArray original = readAll(shippedPath(QStringLiteral("phong.frag")));
    dock.editor(ShaderStage::Fragment)->insertAt(QStringLiteral("// x\n"), 0, 0);
    const Result<> overShipped =
        dock.saveAs(ShaderStage::Fragment, shippedPath(QStringLiteral("phong.frag")));
    QVERIFY(!overShipped);
    QVERIFY(overShipped.error().contains(QStringLiteral("never overwritten")));
    QVERIFY(!dock.saveAs(ShaderStage::Fragment, shippedPath(QStringLiteral("other.frag"))));
    QCOMPARE(readAll(shippedPath(QStringLiteral("phong.frag"))), original);
    QVERIFY(!QFile::exists(shippedPath(QStringLiteral("other.frag"))));

    QVERIFY_OK(dock.saveAs(ShaderStage::Fragment, ownPath(QStringLiteral("mine.frag"))));
    QCOMPARE(dock.filePath(ShaderStage::Fragment), ownPath(QStringLiteral("mine.frag")));
    QVERIFY(!dock.isDirty(ShaderStage::Fragment));
}

void TestShaderEditor::dirtyMarkerFollowsEditsAndSaves()
{
    const QString path = ownPath(QStringLiteral("dirty.frag"));
    writeExternally(path, kSmallShader);
    ShaderDock dock;
    configure(dock);
    dock.setSources({QStringLiteral("a.vert"), kSmallShader}, ShaderSource::fromFile(path).value());
    QTabWidget *tabs = test::shaderTabs(&dock);
    const int tab = tabs->indexOf(dock.editor(ShaderStage::Fragment));
    QCOMPARE(tabs->tabText(tab), QStringLiteral("dirty.frag"));
    QSignalSpy edited(&dock, &ShaderDock::textEdited);

    dock.editor(ShaderStage::Fragment)->insertAt(QStringLiteral("x"), 10, 0);
    QCOMPARE(tabs->tabText(tab), QStringLiteral("dirty.frag*"));
    QCOMPARE(edited.count(), 1);
    QCOMPARE(edited.first().at(0).value<ShaderStage>(), ShaderStage::Fragment);

    // Undoing back to the saved text is clean again.
    dock.editor(ShaderStage::Fragment)->undo();
    QCOMPARE(tabs->tabText(tab), QStringLiteral("dirty.frag"));

    dock.editor(ShaderStage::Fragment)->insertAt(QStringLiteral("y"), 10, 0);
    QString error;
    QVERIFY(dock.save(ShaderStage::Fragment));
    QCOMPARE(tabs->tabText(tab), QStringLiteral("dirty.frag"));
    QCOMPARE(readAll(path), kSmallShader + "y");
    QCOMPARE(dock.filePath(ShaderStage::Fragment), path); // not shipped: saved in place
}

void TestShaderEditor::externalChangeReloadsCleanBuffer()
{
    const QString path = ownPath(QStringLiteral("clean.frag"));
    writeExternally(path, kSmallShader);
    ShaderDock dock;
    configure(dock);
    dock.setSources({QStringLiteral("a.vert"), kSmallShader}, ShaderSource::fromFile(path).value());
    QSignalSpy edited(&dock, &ShaderDock::textEdited);

    const QByteArray changed = kSmallShader + "// changed elsewhere\n";
    writeExternally(path, changed);
    QTRY_COMPARE(dock.text(ShaderStage::Fragment), changed);
    QVERIFY(!dock.isDirty(ShaderStage::Fragment));
    QVERIFY(edited.count() >= 1); // so the owner recompiles
}

void TestShaderEditor::externalChangeKeepsDirtyBuffer()
{
    const QString path = ownPath(QStringLiteral("keep.frag"));
    writeExternally(path, kSmallShader);
    ShaderDock dock;
    configure(dock);
    dock.files()->setExternalChangePolicy(ShaderFileSet::ExternalChangePolicy::Keep);
    dock.setSources({QStringLiteral("a.vert"), kSmallShader}, ShaderSource::fromFile(path).value());
    dock.editor(ShaderStage::Fragment)->insertAt(QStringLiteral("// mine\n"), 0, 0);
    const QByteArray mine = dock.text(ShaderStage::Fragment);
    QSignalSpy handled(dock.files(), &ShaderFileSet::externalChangeHandled);

    writeExternally(path, "// theirs\n");
    QVERIFY(handled.wait());
    QCOMPARE(handled.first().at(1).toBool(), false);
    QCOMPARE(dock.text(ShaderStage::Fragment), mine);
    QVERIFY(dock.isDirty(ShaderStage::Fragment));
    QCOMPARE(readAll(path), QByteArray("// theirs\n"));

    QString error;
    QVERIFY(dock.save(ShaderStage::Fragment));
    QCOMPARE(readAll(path), mine);
    QVERIFY(!handled.wait(500)); // our own save is not an external change
}

void TestShaderEditor::externalChangeReloadPolicy()
{
    const QString path = ownPath(QStringLiteral("reload.frag"));
    writeExternally(path, kSmallShader);
    ShaderDock dock;
    configure(dock);
    dock.files()->setExternalChangePolicy(ShaderFileSet::ExternalChangePolicy::Reload);
    dock.setSources({QStringLiteral("a.vert"), kSmallShader}, ShaderSource::fromFile(path).value());
    dock.editor(ShaderStage::Fragment)->insertAt(QStringLiteral("// mine\n"), 0, 0);
    QSignalSpy handled(dock.files(), &ShaderFileSet::externalChangeHandled);

    writeExternally(path, "// theirs\n");
    QVERIFY(handled.wait());
    QCOMPARE(handled.first().at(1).toBool(), true);
    QCOMPARE(dock.text(ShaderStage::Fragment), QByteArray("// theirs\n"));
    QVERIFY(!dock.isDirty(ShaderStage::Fragment));
}

void TestShaderEditor::externalChangeAsksTheUser()
{
    const QString path = ownPath(QStringLiteral("ask.frag"));
    writeExternally(path, kSmallShader);
    ShaderDock dock;
    configure(dock);
    QCOMPARE(dock.files()->externalChangePolicy(), ShaderFileSet::ExternalChangePolicy::Ask);
    dock.setSources({QStringLiteral("a.vert"), kSmallShader}, ShaderSource::fromFile(path).value());
    dock.editor(ShaderStage::Fragment)->insertAt(QStringLiteral("// mine\n"), 0, 0);
    const QByteArray mine = dock.text(ShaderStage::Fragment);
    QSignalSpy handled(dock.files(), &ShaderFileSet::externalChangeHandled);

    QString question;
    QTimer answer;
    connect(&answer, &QTimer::timeout, this, [&] {
        auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
        if (!box)
            return;
        question = box->text();
        for (QAbstractButton *button : box->buttons())
            if (button->text() == QStringLiteral("Keep mine"))
                button->click();
    });
    answer.start(20);
    writeExternally(path, "// theirs\n");
    QVERIFY(handled.wait());
    QVERIFY(question.contains(QStringLiteral("ask.frag")));
    QCOMPARE(handled.first().at(1).toBool(), false);
    QCOMPARE(dock.text(ShaderStage::Fragment), mine);
}

void TestShaderEditor::openPairAssignsStagesByName()
{
    const QString vert = ownPath(QStringLiteral("pair.vert"));
    const QString frag = ownPath(QStringLiteral("pair.frag"));
    writeExternally(vert, "// vertex\n");
    writeExternally(frag, "// fragment\n");
    ShaderDock dock;
    configure(dock);
    QSignalSpy filesChanged(&dock, &ShaderDock::filesChanged);
    QString error;
    QVERIFY_OK(dock.openFiles({frag, vert}));
    QCOMPARE(dock.text(ShaderStage::Vertex), QByteArray("// vertex\n"));
    QCOMPARE(dock.text(ShaderStage::Fragment), QByteArray("// fragment\n"));
    QCOMPARE(dock.filePath(ShaderStage::Vertex), vert);
    QVERIFY(!dock.isDirty(ShaderStage::Vertex));
    QCOMPARE(filesChanged.count(), 1);

    QVERIFY(!dock.openFiles({frag, frag}));
    QVERIFY(!dock.openFiles({ownPath(QStringLiteral("missing.frag"))}));
    QCOMPARE(dock.filePath(ShaderStage::Fragment), frag); // failures change nothing
}

// A scene's shaders.vertex may be any file: it goes to the vertex stage
// whatever its suffix says, and the tab shown does not decide.
void TestShaderEditor::openFileTakesTheStageItIsGiven()
{
    const QString odd = ownPath(QStringLiteral("lighting.frag"));
    writeExternally(odd, "// really a vertex shader\n");
    ShaderDock dock;
    configure(dock);
    dock.setSources({QStringLiteral("a.vert"), kSmallShader},
                    {QStringLiteral("a.frag"), kSmallShader});
    QCOMPARE(dock.currentStage(), ShaderStage::Fragment);
    QSignalSpy edited(&dock, &ShaderDock::textEdited);
    QVERIFY_OK(dock.openFile(ShaderStage::Vertex, odd));
    QCOMPARE(dock.text(ShaderStage::Vertex), QByteArray("// really a vertex shader\n"));
    QCOMPARE(dock.text(ShaderStage::Fragment), kSmallShader);
    QCOMPARE(dock.filePath(ShaderStage::Vertex), odd);
    QCOMPARE(dock.currentStage(), ShaderStage::Vertex);
    QCOMPARE(edited.count(), 1);
    QVERIFY(!dock.openFile(ShaderStage::Vertex, ownPath(QStringLiteral("missing.vert"))));
    QCOMPARE(dock.filePath(ShaderStage::Vertex), odd); // a failure changes nothing
}

// The dock opens no dialog: its Open…, Save and Save As… ask whoever owns
// it (the File menu and ShaderFileDialogs in the window).
void TestShaderEditor::toolBarFileButtonsAreRequests()
{
    ShaderDock dock;
    configure(dock);
    QSignalSpy open(&dock, &ShaderDock::openRequested);
    QSignalSpy save(&dock, &ShaderDock::saveRequested);
    QSignalSpy saveAs(&dock, &ShaderDock::saveAsRequested);
    const auto trigger = [&dock](const QString &text) {
        for (QAction *action : dock.findChildren<QAction *>())
            if (action->text() == text)
                return action->trigger(), true;
        return false;
    };
    QVERIFY(trigger(QStringLiteral("Open…")));
    QVERIFY(trigger(QStringLiteral("Save")));
    QVERIFY(trigger(QStringLiteral("Save As…")));
    QCOMPARE(open.count(), 1);
    QCOMPARE(save.count(), 1);
    QCOMPARE(saveAs.count(), 1);
    QVERIFY(QApplication::activeModalWidget() == nullptr);
}

void TestShaderEditor::f5AndPresetBoxEmitRequests()
{
    ShaderDock dock;
    dock.setSources({QStringLiteral("a.vert"), kSmallShader},
                    {QStringLiteral("a.frag"), kSmallShader});
    dock.show();
    dock.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&dock));
    QSignalSpy compile(&dock, &ShaderDock::compileRequested);
    dock.editor(ShaderStage::Fragment)->setFocus();
    QTest::keyClick(dock.editor(ShaderStage::Fragment), Qt::Key_F5);
    QCOMPARE(compile.count(), 1);
    QCOMPARE(dock.text(ShaderStage::Fragment), kSmallShader); // F5 typed nothing

    QSignalSpy preset(&dock, &ShaderDock::shadingMethodRequested);
    QComboBox *box = test::shadingMethodBox(&dock);
    // Each method, and the shaders in the editor by their file (it said
    // "Phong" for a student's own).
    QCOMPARE(box->count(), shadingNames().size() + 1);
    QCOMPARE(box->currentText(), QStringLiteral("a.frag (your shader)"));
    dock.selectShadingMethod(ShadingMethod::Phong);
    QCOMPARE(preset.count(), 0); // only the user's choices are requests
    emit box->activated(box->findData(QStringLiteral("phong")));
    QCOMPARE(preset.count(), 1);
    QCOMPARE(preset.first().at(0).value<ShadingMethod>(), ShadingMethod::Phong);
}

void TestShaderEditor::dockShowsErrorAnnotation()
{
    ShaderDock dock;
    loadShipped(dock);
    dock.resize(720, 640);
    dock.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dock));
    dock.showDiagnostics({diagnostic(BuildStep::CompileFragment, Severity::Error, 40, 26,
                                     QStringLiteral("'viewMatrx' undeclared identifier")),
                          diagnostic(BuildStep::CompileFragment, Severity::Warning, 43, 15,
                                     QStringLiteral("'d' shadows a previous declaration"))});
    dock.setCompileStatus(QStringLiteral("1 error — last good program still running"), false);
    dock.goTo(ShaderStage::Fragment, 40, 26);

    // The error circle, the box's tint and the squiggle, once the scroll to
    // the line has been painted.
    const auto reddishPixels = [](const QImage &shot) {
        int reddish = 0;
        for (int y = 0; y < shot.height(); ++y)
            for (int x = 0; x < shot.width(); ++x) {
                const QColor c = shot.pixelColor(x, y);
                reddish += c.red() > 180 && c.green() < 120 && c.blue() < 120;
            }
        return reddish;
    };
    QImage shot;
    QTRY_VERIFY((shot = dock.grab().toImage(), reddishPixels(shot) > 20));
    const QString folder = qEnvironmentVariable("PHONGLAB_TEST_SCREENSHOT_DIR");
    if (!folder.isEmpty())
        QVERIFY(shot.save(QDir(folder).filePath(QStringLiteral("shader-dock.png"))));
}

// Typing at the end of phong.frag, an error appears: the list under the code
// takes its room from the editor, which must keep the line being typed in
// view (it fell out of view: lines 15-52 shown with the cursor on 57).
void TestShaderEditor::cursorLineStaysInViewAsTheErrorListComesAndGoes()
{
    ShaderDock dock;
    loadShipped(dock);
    dock.resize(720, 640);
    dock.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dock));
    ShaderEditor *editor = dock.editor(ShaderStage::Fragment);
    const int lastLine = editor->lines();
    dock.goTo(ShaderStage::Fragment, lastLine, 0);
    QTRY_VERIFY(cursorLineInView(*editor));
    const int heightBefore = editor->height();

    std::vector<ShaderDiagnostic> errors;
    for (int i = 0; i < 6; ++i) // without lines: in the list alone
        errors.push_back(diagnostic(BuildStep::CompileFragment, Severity::Error, 0, 0,
                                    QStringLiteral("error %1").arg(i)));
    dock.showDiagnostics(errors);
    QTRY_VERIFY(editor->height() < heightBefore); // the list took its room
    QVERIFY2(cursorLineInView(*editor), "the line being typed left the view as the list came");

    dock.showDiagnostics({});
    QTRY_COMPARE(editor->height(), heightBefore);
    QVERIFY2(cursorLineInView(*editor), "the line being typed left the view as the list went");

    // A cursor the user scrolled away from is left where it is.
    dock.showDiagnostics({});
    QTRY_COMPARE(editor->height(), heightBefore);
    editor->setCursorPosition(lastLine - 1, 0);
    editor->setFirstVisibleLine(0);
    QVERIFY(!cursorLineInView(*editor));
    dock.showDiagnostics(errors);
    QTRY_VERIFY(editor->height() < heightBefore);
    QCOMPARE(editor->firstVisibleLine(), 0);
}

QTEST_MAIN(TestShaderEditor)
#include "tst_shadereditor.moc"
