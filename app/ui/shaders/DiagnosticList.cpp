#include "DiagnosticList.h"

#include <QFileInfo>
#include <QStyle>

namespace phonglab {

namespace {

constexpr int kStageRole = Qt::UserRole;
constexpr int kLineRole = Qt::UserRole + 1;
constexpr int kColumnRole = Qt::UserRole + 2;

// The row names the file only: user copies live in long per-user folders.
// The tooltip keeps the full path.
QString shortFormat(ShaderDiagnostic diagnostic)
{
    if (!diagnostic.file.startsWith(QLatin1String(":/")))
        diagnostic.file = QFileInfo(diagnostic.file).fileName();
    return diagnostic.format();
}

} // namespace

DiagnosticList::DiagnosticList(QWidget *parent)
    : QListWidget(parent)
{
    setObjectName(QStringLiteral("diagnosticList"));
    setUniformItemSizes(true);
    setWordWrap(false);
    setSelectionMode(SingleSelection);
    connect(this, &QListWidget::itemClicked, this, &DiagnosticList::emitActivated);
    connect(this, &QListWidget::itemActivated, this, &DiagnosticList::emitActivated);
    hide(); // until there is something to say
}

void DiagnosticList::setDiagnostics(const std::vector<ShaderDiagnostic> &diagnostics)
{
    clear();
    m_errors = 0;
    for (const ShaderDiagnostic &diagnostic : diagnostics)
        addDiagnostic(diagnostic);
    // Room only when there is something to say: the code has the rest.
    setVisible(count() > 0);
}

void DiagnosticList::addDiagnostic(const ShaderDiagnostic &diagnostic)
{
    const bool error = diagnostic.isError();
    if (error)
        ++m_errors;
    auto *item = new QListWidgetItem(shortFormat(diagnostic), this);
    item->setIcon(style()->standardIcon(error ? QStyle::SP_MessageBoxCritical
                                              : QStyle::SP_MessageBoxWarning));
    item->setToolTip(diagnostic.format());
    item->setData(kStageRole, static_cast<int>(editorStage(diagnostic.step)));
    item->setData(kLineRole, diagnostic.line);
    item->setData(kColumnRole, diagnostic.column);
    show();
}

void DiagnosticList::emitActivated(QListWidgetItem *item)
{
    if (!item)
        return;
    emit diagnosticActivated(static_cast<ShaderStage>(item->data(kStageRole).toInt()),
                             item->data(kLineRole).toInt(), item->data(kColumnRole).toInt());
}

} // namespace phonglab
