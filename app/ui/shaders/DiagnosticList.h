#pragma once
#include "render/program/ShaderDiagnostic.h"

#include <QListWidget>
#include <vector>

namespace phonglab {

// The compiler's and linker's messages, one per row as
// "phong.frag:12:5: error: message", errors and warnings with their own
// icons. Clicking a row (or pressing Enter on it) asks to go there.
class DiagnosticList : public QListWidget
{
    Q_OBJECT

public:
    explicit DiagnosticList(QWidget *parent = nullptr);

    void setDiagnostics(const std::vector<ShaderDiagnostic> &diagnostics);
    int errorCount() const { return m_errors; }

signals:
    // Not named activated(): that would hide QAbstractItemView::activated
    // and make every pointer-to-member connect to it ambiguous.
    void diagnosticActivated(phonglab::ShaderStage stage, int line, int column);

private:
    void addDiagnostic(const ShaderDiagnostic &diagnostic);
    void emitActivated(QListWidgetItem *item);

    int m_errors = 0;
};

} // namespace phonglab
