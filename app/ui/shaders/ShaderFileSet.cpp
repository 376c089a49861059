#include "ShaderFileSet.h"

#include "core/program/ShaderStage.h"
#include "core/project/ProjectSave.h"

#include "core/scene/ResourcePaths.h"
#include "core/scene/ShadingMethod.h"
#include "core/support/AtomicFile.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QFileSystemWatcher>
#include <QMessageBox>
#include <QPushButton>
#include <QSet>
#include <QStandardPaths>
#include <QTimer>

namespace phonglab {

namespace {

constexpr int kRecheckDelayMs = 150;

bool isResource(const QString &path)
{
    return path.startsWith(QLatin1String(":/")) || path.startsWith(QLatin1String("qrc:"));
}

// Symlinks resolved where the file or its folder exists, so that a shipped
// file reached through a link is still recognised.
QString canonical(const QString &path)
{
    const QFileInfo info(path);
    const QString resolved = info.canonicalFilePath();
    if (!resolved.isEmpty())
        return resolved;
    const QString folder = QDir(info.absolutePath()).canonicalPath();
    return folder.isEmpty() ? QDir::cleanPath(info.absoluteFilePath())
                            : folder + QLatin1Char('/') + info.fileName();
}

QString defaultFileName(ShaderStage stage)
{
    return stage == ShaderStage::Vertex ? QStringLiteral("shader.vert")
                                        : QStringLiteral("shader.frag");
}

// `name` in `folder`, or name-1, name-2, ... before the suffix if taken.
QString unusedPath(const QString &folder, const QString &name)
{
    const QFileInfo info(name);
    const QString base = info.completeBaseName();
    const QString suffix = info.suffix().isEmpty() ? QString() : QLatin1Char('.') + info.suffix();
    QString candidate = QDir(folder).filePath(name);
    for (int n = 1; QFileInfo::exists(candidate); ++n)
        candidate = QDir(folder).filePath(QStringLiteral("%1-%2%3").arg(base).arg(n).arg(suffix));
    return candidate;
}

} // namespace

ShaderFileSet::ShaderFileSet(QObject *parent)
    : QObject(parent)
    , m_watcher(new QFileSystemWatcher(this))
    , m_recheckTimer(new QTimer(this))
{
    setShippedFolders(defaultShippedFolders());
    m_recheckTimer->setSingleShot(true);
    m_recheckTimer->setInterval(kRecheckDelayMs);
    connect(m_recheckTimer, &QTimer::timeout, this, &ShaderFileSet::checkForExternalChanges);
    connect(m_watcher, &QFileSystemWatcher::directoryChanged, m_recheckTimer,
            qOverload<>(&QTimer::start));
}

QStringList ShaderFileSet::defaultShippedFolders()
{
    QStringList folders = shaderSearchFolders();
    for (const QString &name : shadingNames()) {
        for (const ShaderStage stage : {ShaderStage::Vertex, ShaderStage::Fragment}) {
            const QString path = shippedShaderPath(*shadingFromName(name), stage);
            if (!isResource(path))
                folders << QFileInfo(path).absolutePath();
        }
    }
    folders.removeDuplicates();
    return folders;
}

void ShaderFileSet::setShippedFolders(const QStringList &folders)
{
    m_shippedFolders.clear();
    for (const QString &folder : folders)
        m_shippedFolders << canonical(folder);
    m_shippedFolders.removeDuplicates();
}

bool ShaderFileSet::isShipped(const QString &path) const
{
    if (isResource(path))
        return true;
    if (path.isEmpty())
        return false;
    const QString resolved = canonical(path);
    for (const QString &folder : m_shippedFolders)
        if (resolved.startsWith(folder + QLatin1Char('/')))
            return true;
    return false;
}

QString ShaderFileSet::userFolder()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)
        + QStringLiteral("/shaders");
}

ShaderFileSet::File &ShaderFileSet::file(ShaderStage stage)
{
    return m_files[stage == ShaderStage::Vertex ? 0 : 1];
}

const ShaderFileSet::File &ShaderFileSet::file(ShaderStage stage) const
{
    return m_files[stage == ShaderStage::Vertex ? 0 : 1];
}

void ShaderFileSet::setFile(ShaderStage stage, const QString &path, const QByteArray &code)
{
    File &f = file(stage);
    const bool wasDirty = f.dirty;
    f = {path, code, false};
    watchFolders();
    emit pathChanged(stage, path);
    if (wasDirty)
        emit dirtyChanged(stage, false);
}

// Labels and relative names have no file of their own to write either.
bool ShaderFileSet::needsUserCopy(const QString &path) const
{
    return path.isEmpty() || isShipped(path) || QFileInfo(path).isRelative();
}

void ShaderFileSet::setDirty(ShaderStage stage, bool dirty)
{
    File &f = file(stage);
    if (f.dirty == dirty)
        return;
    if (dirty && needsUserCopy(f.path)) {
        if (const Result<> moved = moveToUserCopy(stage, f.diskCode); !moved)
            emit problem(moved.error()); // still dirty; saving will try again
    }
    f.dirty = dirty;
    emit dirtyChanged(stage, dirty);
}

Result<> ShaderFileSet::moveToUserCopy(ShaderStage stage, const QByteArray &content)
{
    const QString folder = userFolder();
    if (!QDir().mkpath(folder))
        return fail(tr("%1: cannot create the folder for user shaders")
                        .arg(QDir::toNativeSeparators(folder)));
    File &f = file(stage);
    const QString name = f.path.isEmpty() ? defaultFileName(stage) : QFileInfo(f.path).fileName();
    const QString copy = unusedPath(folder, name);
    if (Result<> done = writeFileAtomically(copy, content); !done)
        return done;
    f.path = copy;
    f.diskCode = content;
    watchFolders();
    emit pathChanged(stage, copy);
    return {};
}

namespace {

// The text a stage's path holds now: a file's, or a project shader's.
std::optional<QByteArray> currentText(const QString &path)
{
    if (isShaderLocator(path)) {
        const Result<ProjectShader> shader = shaderAtLocator(path);
        return shader ? std::optional<QByteArray>(shader->text) : std::nullopt;
    }
    QFile in(path);
    if (!in.open(QIODevice::ReadOnly))
        return std::nullopt;
    return in.readAll();
}

// Saves `code` in place of a project shader's text; every other byte of
// its page or script stays.
Result<> saveIntoProjectFile(const QString &locator, const QByteArray &code)
{
    const Result<ProjectShader> shader = shaderAtLocator(locator);
    if (!shader)
        return fail(shader.error());
    QFile in(shader->file);
    if (!in.open(QIODevice::ReadOnly))
        return fail(QStringLiteral("%1: %2").arg(shader->file, in.errorString()));
    const Result<QByteArray> saved = withShaderText(in.readAll(), *shader, code);
    if (!saved)
        return fail(saved.error());
    return writeFileAtomically(shader->file, *saved);
}

} // namespace

Result<> ShaderFileSet::save(ShaderStage stage, const QByteArray &code)
{
    File &f = file(stage);
    if (isShaderLocator(f.path)) {
        if (Result<> done = saveIntoProjectFile(f.path, code); !done)
            return done;
        f.diskCode = code;
    } else if (needsUserCopy(f.path)) {
        if (Result<> done = moveToUserCopy(stage, code); !done)
            return done;
    } else {
        if (Result<> done = writeFileAtomically(f.path, code); !done)
            return done;
        f.diskCode = code; // so the watcher does not take our own write for someone else's
    }
    setDirty(stage, false);
    return {};
}

Result<> ShaderFileSet::saveAs(ShaderStage stage, const QString &path, const QByteArray &code)
{
    if (isShipped(path))
        return fail(tr("%1 is a shader shipped with PhongLab and is never overwritten; "
                       "save under another name or folder.")
                        .arg(QDir::toNativeSeparators(path)));
    if (Result<> done = writeFileAtomically(path, code); !done)
        return done;
    File &f = file(stage);
    f.path = path;
    f.diskCode = code;
    watchFolders();
    emit pathChanged(stage, path);
    setDirty(stage, false);
    return {};
}

void ShaderFileSet::watchFolders()
{
    QSet<QString> wanted;
    for (const File &f : m_files)
        if (!f.path.isEmpty() && !isResource(f.path) && QFileInfo(f.path).isAbsolute())
            wanted.insert(QFileInfo(f.path).absolutePath());
    const QStringList watched = m_watcher->directories();
    for (const QString &folder : watched)
        if (!wanted.contains(folder))
            m_watcher->removePath(folder);
    for (const QString &folder : std::as_const(wanted))
        if (!watched.contains(folder) && QFileInfo(folder).isDir())
            m_watcher->addPath(folder);
}

void ShaderFileSet::checkForExternalChanges()
{
    if (m_asking) {
        m_recheckWhileAsking = true; // look again once the question is answered
        return;
    }
    for (ShaderStage stage : {ShaderStage::Vertex, ShaderStage::Fragment}) {
        const File &f = file(stage);
        if (f.path.isEmpty() || isResource(f.path))
            continue;
        // A missing file is mid-rename or deleted: keep the buffer either way.
        const std::optional<QByteArray> onDisk = currentText(f.path);
        if (onDisk && *onDisk != f.diskCode)
            handleExternalChange(stage, *onDisk);
    }
}

void ShaderFileSet::handleExternalChange(ShaderStage stage, const QByteArray &onDisk)
{
    bool reload = !file(stage).dirty || m_policy == ExternalChangePolicy::Reload;
    if (!reload && m_policy == ExternalChangePolicy::Ask)
        reload = askToReload(stage);
    if (reload) {
        applyReload(stage, onDisk);
    } else {
        // Keep the user's text, still unsaved; ask again only for a newer change.
        file(stage).diskCode = onDisk;
    }
    emit externalChangeHandled(stage, reload);
}

void ShaderFileSet::applyReload(ShaderStage stage, const QByteArray &onDisk)
{
    File &f = file(stage);
    f.diskCode = onDisk;
    if (f.dirty) {
        f.dirty = false;
        emit dirtyChanged(stage, false);
    }
    emit reloaded(stage, onDisk);
}

bool ShaderFileSet::askToReload(ShaderStage stage)
{
    QMessageBox box(
        QMessageBox::Question, tr("Shader changed on disk"),
        tr("%1 was changed by another program, and the editor has unsaved changes to it.")
            .arg(QDir::toNativeSeparators(file(stage).path)),
        QMessageBox::NoButton, m_dialogParent);
    box.setInformativeText(tr("Reload it and lose your changes, or keep your version?"));
    QPushButton *reload = box.addButton(tr("Reload"), QMessageBox::DestructiveRole);
    QPushButton *keep = box.addButton(tr("Keep mine"), QMessageBox::RejectRole);
    box.setDefaultButton(keep);
    box.setEscapeButton(keep);
    m_asking = true;
    box.exec();
    m_asking = false;
    if (m_recheckWhileAsking) {
        m_recheckWhileAsking = false;
        m_recheckTimer->start();
    }
    return box.clickedButton() == reload;
}

QString shaderFileFilter()
{
    return ShaderFileSet::tr("GLSL shaders (%1);;All files (*)").arg(shaderFilePatterns());
}

} // namespace phonglab
