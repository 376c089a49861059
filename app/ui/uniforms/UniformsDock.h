#pragma once
#include "core/program/UniformAnnotations.h"
#include "core/program/UniformOwner.h"
#include "render/program/UniformIntrospection.h"
#include "render/program/UniformSnapshot.h"

#include <QDockWidget>
#include <QElapsedTimer>
#include <QHash>

class QFormLayout;
class QScrollArea;

namespace phonglab {

class ShaderDock;
class Viewport;

// The lighting program's uniforms, read from the linked program
// (glGetActiveUniform) after every successful build, with hints from the
// shader text (// @range lo hi, @color, @step). One row per uniform and per
// array element; the ones the renderer or the scene sets are shown
// read-only with their current value, the rest are edited here and set on
// the program at once (ShaderProgram carries them across rebuilds). A
// uniform the text declares but the compiler dropped is listed with a
// warning, so an unused parameter does not look broken.
class UniformsDock : public QDockWidget
{
    Q_OBJECT

public:
    explicit UniformsDock(QWidget *parent = nullptr);

    // Where the program and its text come from. Call once.
    void attach(Viewport *viewport, ShaderDock *shaders);
    // Rebuilds the rows once the next frame has drawn, so the values the
    // renderer sets are in place. Call after every successful build.
    void scheduleRebuild();
    bool rebuildPending() const { return m_rebuildPending; } // rows due after the next frame
    // Rebuilds now (GL must be up); false if there is no program yet.
    bool rebuild();

    // The row of one element ("gain", "Id[1]") or declared-but-inactive name.
    QWidget *row(const QString &element) const { return m_rows.value(element); }
    QStringList inactiveNames() const { return m_inactive; }

    // The uniforms the check found nothing to place (render/check/ProgramFindings):
    // their rows in red, "bound to nothing: choose what it is", until the
    // next check says otherwise.
    void markUnplaced(const QStringList &names);
    QStringList unplacedNames() const { return m_unplaced; }
    // Brings the dock to the front with `name`'s row in view and its
    // "bound to" choice in focus.
    void showUniform(const QString &name);

signals:
    void rebuilt();
    // A value the user set went into the program: the frame changed.
    void valueWritten();

private:
    struct Program {
        std::vector<ActiveUniformInfo> active;
        UniformSnapshot values;
        ProgramBindings bindings;
        ExplicitBindings explicitBindings; // the scene's word
    };

    bool readProgram(Program &program);
    static QStringList layoutKey(const Program &program,
                                 const std::vector<UniformDeclaration> &declared);
    std::vector<UniformDeclaration> declarations() const;
    void clearRows();
    void addActive(const ActiveUniformInfo &uniform, const Program &program,
                   const std::vector<UniformDeclaration> &declared);
    void addInactive(const UniformDeclaration &declaration);
    void addRow(const QString &element, const QString &label, QWidget *row,
                QWidget *labelWidget = nullptr);
    QWidget *labelWithChoice(const QString &name, const Program &program);
    void connectRow(QWidget *row, const QString &element);
    void showUnplaced(const QString &name);
    void writeFloats(const QString &element, const QList<float> &values);
    void writeInt(const QString &element, int value);
    void write(const UniformValue &value);
    void onFrameRendered();
    void refreshDrivenValues();

    Viewport *m_viewport = nullptr;
    ShaderDock *m_shaders = nullptr;
    QWidget *m_contents = nullptr;
    QFormLayout *m_form = nullptr;
    QHash<QString, QWidget *> m_rows;
    QHash<QString, UniformOwner> m_owners;
    QStringList m_inactive;
    QStringList m_unplaced;
    QStringList m_layoutKey;  // of the rows shown (layoutKey())
    UniformSnapshot m_values; // as last read: the type and layout each write needs
    bool m_rebuildPending = false;
    QScrollArea *m_scroll = nullptr;
    QElapsedTimer m_sinceRefresh; // read-only values follow the scene a few times a second
};

} // namespace phonglab
