#include "ShaderFileDialogs.h"

#include "ShaderDock.h"
#include "ShaderFileSet.h"

#include "core/project/ProjectShader.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QPushButton>

namespace phonglab {

ShaderFileDialogs::ShaderFileDialogs(ShaderDock *dock)
    : QObject(dock)
    , m_dock(dock)
{
    connect(dock, &ShaderDock::saveRequested, this, &ShaderFileDialogs::saveCurrent);
    connect(dock, &ShaderDock::saveAsRequested, this, &ShaderFileDialogs::chooseAndSaveAsCurrent);
}

void ShaderFileDialogs::saveCurrent()
{
    const ShaderStage stage = m_dock->currentStage();
    const Result<> saved = m_dock->save(stage);
    if (saved)
        return;
    if (!isShaderLocator(m_dock->filePath(stage))) {
        warn(saved.error());
        return;
    }
    // A shader the page or script cannot take back as it is: say why, and
    // offer a file of its own.
    QMessageBox box(QMessageBox::Warning, tr("Shaders"), saved.error(), QMessageBox::Cancel,
                    m_dock);
    QPushButton *saveAs = box.addButton(tr("Save As…"), QMessageBox::AcceptRole);
    box.setDefaultButton(saveAs);
    box.exec();
    if (box.clickedButton() == saveAs)
        chooseAndSaveAsCurrent();
}

void ShaderFileDialogs::chooseAndSaveAsCurrent()
{
    const ShaderStage stage = m_dock->currentStage();
    QDir().mkpath(ShaderFileSet::userFolder());
    // A project's shader ("index.html#vsSource") suggests a file of its own.
    const QString current = m_dock->filePath(stage);
    const QString name = isShaderLocator(current) ? current.section(QLatin1Char('#'), -1)
            + (stage == ShaderStage::Vertex ? QStringLiteral(".vert") : QStringLiteral(".frag"))
                                                  : QFileInfo(current).fileName();
    const QString suggested = QDir(ShaderFileSet::userFolder()).filePath(name);
    const QString path =
        QFileDialog::getSaveFileName(m_dock, tr("Save Shader As"), suggested, shaderFileFilter());
    if (path.isEmpty())
        return;
    if (const Result<> saved = m_dock->saveAs(stage, path); !saved)
        warn(saved.error());
}

void ShaderFileDialogs::warn(const QString &message)
{
    QMessageBox::warning(m_dock, tr("Shaders"), message);
}

} // namespace phonglab
