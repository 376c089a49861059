#include "ShaderRecovery.h"

#include "ShaderDock.h"
#include "ShaderEditor.h"

#include <QFileInfo>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QTimer>

namespace phonglab {

namespace {

// The text a buffer starts from: its file as on disk, so that the dock's
// notion of "unsaved" compares with the real file; the journal's text then
// goes in as an edit.
ShaderSource baseSource(const RecoveryBuffer &buffer)
{
    if (!buffer.filePath.isEmpty() && QFileInfo::exists(buffer.filePath)) {
        if (Result<ShaderSource> source = ShaderSource::fromFile(buffer.filePath))
            return std::move(*source);
    }
    return {buffer.filePath, buffer.text};
}

QString when(const QDateTime &savedAt)
{
    return QLocale().toString(savedAt.toLocalTime(), QLocale::ShortFormat);
}

} // namespace

ShaderRecovery::ShaderRecovery(ShaderDock *dock, QObject *parent)
    : QObject(parent)
    , m_dock(dock)
    , m_timer(new QTimer(this))
    , m_probationTimer(new QTimer(this))
{
    m_timer->setInterval(kJournalPeriodMs);
    connect(m_timer, &QTimer::timeout, this, &ShaderRecovery::writeIfStale);
    m_probationTimer->setSingleShot(true);
    m_probationTimer->setInterval(kProvenAfterMs);
    connect(m_probationTimer, &QTimer::timeout, this, &ShaderRecovery::checkProbation);
}

ShaderRecovery::~ShaderRecovery() = default;

ShaderRecovery::Outcome ShaderRecovery::offer(Answer answer, QWidget *parent)
{
    const QList<OrphanedSession> orphans = m_journal.orphans();
    if (orphans.isEmpty())
        return {};
    // The newest only: older ones (several instances that died) are offered
    // at later starts rather than merged into one editor.
    const OrphanedSession &session = orphans.front();
    const bool yes = answer == Answer::Ask ? ask(session, parent) : answer == Answer::Restore;
    if (!yes) {
        m_journal.discard(session.id);
        return {
            false,
            false,
            tr("Discarded the shader edits recovered from %1").arg(when(session.record.savedAt)),
            {}};
    }
    restore(session);
    m_journal.discard(session.id); // from now on this session's journal holds them
    writeNow();
    Outcome outcome{true, session.runningHash.has_value(), {}, session.record.shading};
    if (!outcome.suspect)
        outcome.note =
            tr("Restored the shader edits recovered from %1").arg(when(session.record.savedAt));
    else if (session.isSuspect())
        outcome.note =
            tr("Restored shaders were running when PhongLab stopped unexpectedly, so they were not "
               "compiled; the shipped program is shown. Press F5 to compile them.");
    else
        outcome.note =
            tr("PhongLab stopped unexpectedly while trying a new shader; the restored shaders were "
               "not compiled and the shipped program is shown. Press F5 to compile them.");
    return outcome;
}

bool ShaderRecovery::ask(const OrphanedSession &session, QWidget *parent) const
{
    QMessageBox box(
        QMessageBox::Question, tr("Recover shader edits"),
        tr("PhongLab did not shut down cleanly. Shader edits from %1 were recovered.\n\n"
           "Restore them into the editor?")
            .arg(when(session.record.savedAt)),
        QMessageBox::NoButton, parent);
    QPushButton *restore = box.addButton(tr("Restore"), QMessageBox::AcceptRole);
    box.addButton(tr("Discard"), QMessageBox::DestructiveRole);
    box.setDefaultButton(restore);
    if (session.runningHash)
        box.setInformativeText(
            tr("A new shader was running when it stopped; it will not be compiled "
               "until you press F5."));
    box.exec();
    return box.clickedButton() == static_cast<QAbstractButton *>(restore);
}

void ShaderRecovery::restore(const OrphanedSession &session)
{
    const RecoveryRecord &r = session.record;
    const ShaderSource vertex = baseSource(r.vertex);
    const ShaderSource fragment = baseSource(r.fragment);
    m_dock->setSources(vertex, fragment);
    // setText() is an ordinary edit: the buffer becomes unsaved and the dock
    // reports it, as if the user had typed it again.
    if (vertex.code != r.vertex.text)
        m_dock->editor(ShaderStage::Vertex)->setText(QString::fromUtf8(r.vertex.text));
    if (fragment.code != r.fragment.text)
        m_dock->editor(ShaderStage::Fragment)->setText(QString::fromUtf8(r.fragment.text));
    m_shading = r.shading;
}

void ShaderRecovery::writeNow()
{
    RecoveryRecord record;
    record.vertex = {m_dock->filePath(ShaderStage::Vertex), m_dock->text(ShaderStage::Vertex),
                     m_dock->isDirty(ShaderStage::Vertex)};
    record.fragment = {m_dock->filePath(ShaderStage::Fragment), m_dock->text(ShaderStage::Fragment),
                       m_dock->isDirty(ShaderStage::Fragment)};
    record.shading = m_shading;
    if (const Result<> written = m_journal.write(record); !written) {
        qWarning("phonglab: cannot write the recovery journal: %s", qPrintable(written.error()));
        return;
    }
    m_stale = false;
}

void ShaderRecovery::noteEdited()
{
    m_stale = true;
    if (!m_timer->isActive())
        m_timer->start();
}

void ShaderRecovery::writeIfStale()
{
    if (m_stale)
        writeNow();
    else if (!m_dock->hasUnsavedChanges())
        m_timer->stop(); // nothing more to keep safe until the next edit
}

void ShaderRecovery::noteFilesChanged()
{
    // The sentinel needs its journal: a program not yet proven keeps both.
    if (m_dock->hasUnsavedChanges() || m_running)
        return;
    m_journal.clear();
    m_stale = false;
    m_timer->stop();
}

void ShaderRecovery::clear()
{
    m_timer->stop();
    m_probationTimer->stop();
    m_journal.clear();
    m_running = false;
    m_stale = false;
}

bool ShaderRecovery::confirmUnsaved(QWidget *parent)
{
    if (!m_dock->hasUnsavedChanges())
        return true;
    const auto answer = QMessageBox::question(
        parent, tr("Unsaved shader changes"),
        tr("The shaders have unsaved changes. Save them before quitting?"),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer != QMessageBox::Save)
        return answer == QMessageBox::Discard;
    for (ShaderStage stage : {ShaderStage::Vertex, ShaderStage::Fragment}) {
        if (!m_dock->isDirty(stage))
            continue;
        if (const Result<> saved = m_dock->save(stage); !saved) {
            QMessageBox::warning(parent, tr("Cannot save shader"), saved.error());
            return false;
        }
    }
    return true;
}

void ShaderRecovery::buildStarted(const QByteArray &hash)
{
    m_building = true;
    markRunning(hash);
}

void ShaderRecovery::buildFailed()
{
    m_building = false;
    // The program that never existed is no suspect; one still on probation is.
    if (!m_probation.isEmpty())
        markRunning(m_probation);
    else
        clearRunning();
}

void ShaderRecovery::programShown(const QByteArray &hash)
{
    m_building = false;
    m_probation = hash; // the sentinel already names it
    m_probationFrames = 0;
    m_probationClock.start();
    m_probationTimer->start();
}

void ShaderRecovery::frameRendered()
{
    if (m_probation.isEmpty())
        return;
    ++m_probationFrames;
    checkProbation();
}

void ShaderRecovery::checkProbation()
{
    if (m_probation.isEmpty())
        return;
    const bool enoughFrames = m_probationFrames >= kProvenFrames;
    const bool enoughTime = m_probationFrames >= 1 && m_probationClock.elapsed() >= kProvenAfterMs;
    if (!enoughFrames && !enoughTime) {
        if (!m_probationTimer->isActive())
            m_probationTimer->start(); // e.g. a hidden window: wait for a frame
        return;
    }
    m_probationTimer->stop();
    m_probation.clear();
    if (!m_building) // a newer build keeps its own mark
        clearRunning();
}

void ShaderRecovery::markRunning(const QByteArray &hash)
{
    if (const Result<> marked = m_journal.markRunning(hash); !marked)
        qWarning("phonglab: cannot write the running-shader sentinel: %s",
                 qPrintable(marked.error()));
    m_running = true;
}

void ShaderRecovery::clearRunning()
{
    m_journal.clearRunning();
    m_running = false;
    noteFilesChanged(); // saved meanwhile: nothing left to keep
}

} // namespace phonglab
