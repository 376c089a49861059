#pragma once
#include "core/support/Result.h"
#include "render/program/ShaderDiagnostic.h"

#include <QByteArray>
#include <QObject>
#include <QPointer>
#include <QStringList>
#include <array>

class QFileSystemWatcher;
class QTimer;
class QWidget;

namespace phonglab {

// The files behind the vertex and fragment editors: their paths, what is
// on disk, and whether the buffers hold unsaved edits. It never holds the
// text being edited; the caller passes it in to save and gets reloaded text
// back through reloaded().
//
// Shipped shaders (under a shipped folder, or embedded ":/..." resources)
// are never written: the first edit or save of one moves that stage onto a
// user copy in <AppDataLocation>/shaders/ (same name, or name-1, name-2, ...).
//
// The folders of the open files are watched, not the files, so that editors
// that save by writing a new file and renaming it over the old one are seen.
// A file that changes on disk is reloaded when its buffer is clean; with
// unsaved edits the policy decides (by default the user is asked).
class ShaderFileSet : public QObject
{
    Q_OBJECT

public:
    enum class ExternalChangePolicy {
        Ask,
        Reload,
        Keep
    };
    Q_ENUM(ExternalChangePolicy)

    explicit ShaderFileSet(QObject *parent = nullptr);

    // Where the shipped shaders can be: $PHONGLAB_SHADER_DIR, the folders
    // beside the executable that shaderPath() searches, and the folder every
    // shading method's shaders resolve to.
    static QStringList defaultShippedFolders();
    void setShippedFolders(const QStringList &folders);
    bool isShipped(const QString &path) const;
    // <AppDataLocation>/shaders, where user copies go.
    static QString userFolder();

    void setExternalChangePolicy(ExternalChangePolicy policy) { m_policy = policy; }
    ExternalChangePolicy externalChangePolicy() const { return m_policy; }
    void setDialogParent(QWidget *parent) { m_dialogParent = parent; }

    // `stage` now shows `path` (a file, a resource or a label), whose text
    // is `code`; the buffer is clean.
    void setFile(ShaderStage stage, const QString &path, const QByteArray &code);
    QString path(ShaderStage stage) const { return file(stage).path; }
    bool isDirty(ShaderStage stage) const { return file(stage).dirty; }
    // The buffer gained or lost unsaved edits. The first edit of a shipped
    // shader creates its user copy (with the shipped text) and moves there.
    void setDirty(ShaderStage stage, bool dirty);

    // Atomic writes (QSaveFile). save() goes to the user copy for shipped
    // shaders; saveAs() refuses shipped targets. Both leave the stage clean.
    Result<> save(ShaderStage stage, const QByteArray &code);
    Result<> saveAs(ShaderStage stage, const QString &path, const QByteArray &code);

    // Compares the files with what was last read or written and handles any
    // difference. The folder watcher calls it shortly after a change.
    void checkForExternalChanges();

signals:
    void pathChanged(phonglab::ShaderStage stage, const QString &path);
    void dirtyChanged(phonglab::ShaderStage stage, bool dirty);
    // The file changed on disk and its text replaces the buffer.
    void reloaded(phonglab::ShaderStage stage, const QByteArray &code);
    // After every external change: reloaded or kept the user's buffer.
    void externalChangeHandled(phonglab::ShaderStage stage, bool reloaded);
    // Something failed without a caller to tell (creating a user copy).
    void problem(const QString &message);

private:
    struct File {
        QString path;
        QByteArray diskCode; // what the file held when last read or written
        bool dirty = false;
    };

    File &file(ShaderStage stage);
    const File &file(ShaderStage stage) const;
    bool needsUserCopy(const QString &path) const;
    Result<> moveToUserCopy(ShaderStage stage, const QByteArray &content);
    void handleExternalChange(ShaderStage stage, const QByteArray &onDisk);
    bool askToReload(ShaderStage stage);
    void applyReload(ShaderStage stage, const QByteArray &onDisk);
    void watchFolders();

    std::array<File, 2> m_files; // vertex, fragment
    QStringList m_shippedFolders;
    ExternalChangePolicy m_policy = ExternalChangePolicy::Ask;
    QPointer<QWidget> m_dialogParent;
    QFileSystemWatcher *m_watcher = nullptr;
    QTimer *m_recheckTimer = nullptr; // coalesces bursts of folder events
    bool m_asking = false;
    bool m_recheckWhileAsking = false;
};

// The file dialogs' filter for shaders: "GLSL shaders (*.vert … *.glsl)",
// then all files.
QString shaderFileFilter();

} // namespace phonglab
