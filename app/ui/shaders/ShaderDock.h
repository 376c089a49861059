#pragma once
#include "core/scene/ShadingMethod.h"
#include "core/support/Result.h"
#include "render/program/ShaderDiagnostic.h"
#include "render/program/ShaderSource.h"

#include <QDockWidget>
#include <utility>
#include <vector>

class QComboBox;
class QLabel;
class QPushButton;
class QTabWidget;

namespace phonglab {

class DiagnosticList;
class ShaderEditor;
class ShaderFileSet;

// The Shaders dock: a vertex and a fragment ShaderEditor in tabs, a shading
// method chooser (its shipped shaders), Compile (F5), Open, Save and Save As, a status line and the
// compiler's messages. It compiles nothing itself: it reports edits and
// requests, and shows what the owner sends back. Nothing here does work
// per keystroke beyond the editor's own; the owner debounces compiles.
// It opens no dialog either: Open, Save and Save As are requests, answered
// by the File menu and ShaderFileDialogs, so tests drive the dock without one.
// Tests reach its widgets by their object names (see the constructor).
class ShaderDock : public QDockWidget
{
    Q_OBJECT

public:
    explicit ShaderDock(QWidget *parent = nullptr);

    // Shows both stages; each source's name is its path (or a label such as
    // ":/shaders/phong.frag"). Both buffers become clean; no textEdited().
    void setSources(const ShaderSource &vertex, const ShaderSource &fragment);
    QByteArray text(ShaderStage stage) const;
    QString filePath(ShaderStage stage) const;
    bool isDirty(ShaderStage stage) const;
    bool hasUnsavedChanges() const;

    // Routes each diagnostic to its stage's editor (Link ones to the
    // fragment editor when they carry a line) and lists them all.
    void showDiagnostics(const std::vector<ShaderDiagnostic> &diagnostics);
    // What the check found, on the lines of the text it checked: a stage's
    // marks are shown only while its editor holds that text (after an edit
    // they wait for the next check).
    void showCheckMarks(const std::vector<ShaderDiagnostic> &vertex, const QByteArray &vertexText,
                        const std::vector<ShaderDiagnostic> &fragment,
                        const QByteArray &fragmentText);
    // "compiled in 12 ms" (ok) or "2 errors — last good program still running".
    void setCompileStatus(const QString &text, bool ok);
    // A program kept out for its frame time: `text` as a failed status,
    // with an "Apply anyway" button beside it (until the next status).
    void offerToApplyAnyway(const QString &text);
    // Selects `method` in the shading method box without emitting shadingMethodRequested().
    void selectShadingMethod(ShadingMethod method);

    // Without dialogs (tests, command line). openFiles() takes one file or a
    // .vert/.frag pair; the stage comes from the suffix, else the current tab.
    Result<> openFiles(const QStringList &paths);
    // `path` into `stage`'s editor, whatever its suffix says.
    Result<> openFile(ShaderStage stage, const QString &path);
    Result<> save(ShaderStage stage);
    Result<> saveAs(ShaderStage stage, const QString &path);
    // Shows `stage`'s editor with the cursor at the
    // 1-based line and column, focused.
    void goTo(ShaderStage stage, int line, int column);

    ShaderEditor *editor(ShaderStage stage) const;
    ShaderStage currentStage() const;
    ShaderFileSet *files() const { return m_files; }

signals:
    // A stage's text changed other than through setSources(): typing, a
    // reload from disk, Open. Emitted per change; debounce before compiling.
    void textEdited(phonglab::ShaderStage stage);
    void compileRequested();
    // The tool bar's Open…, Save and Save As… (the current tab's stage).
    void openRequested();
    void saveRequested();
    void saveAsRequested();
    void shadingMethodRequested(phonglab::ShadingMethod method);
    // A stage now shows another file (Open, Save As, a user copy of a
    // shipped shader) or its file was reloaded from disk.
    void filesChanged();
    // "Apply anyway" on a program kept out for its frame time.
    void applyAnywayRequested();

private:
    QWidget *createToolBar();
    void connectEditor(ShaderStage stage);
    void connectFiles();
    void showWhoseShaders();
    void setEditorCode(ShaderStage stage, const QByteArray &code);
    void showOpened(const QList<std::pair<ShaderStage, ShaderSource>> &opened);
    void updateTab(ShaderStage stage);

    ShaderEditor *m_vertex = nullptr;
    ShaderEditor *m_fragment = nullptr;
    QTabWidget *m_tabs = nullptr;
    QComboBox *m_shadingMethods = nullptr;
    QLabel *m_status = nullptr;
    QPushButton *m_applyAnyway = nullptr;
    DiagnosticList *m_diagnostics = nullptr;
    ShaderFileSet *m_files = nullptr;
    ShadingMethod m_method = ShadingMethod::Phong; // the scene's, shown when no own shaders are
    bool m_settingText = false;                    // our own setCode(): not an edit
};

} // namespace phonglab
