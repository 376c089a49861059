#pragma once
#include "CheckRunner.h"
#include "core/program/ShaderStage.h"

#include <QDockWidget>

class QTextBrowser;

namespace phonglab {

// The check's whole verdict, as `phonglab check` prints it on the same scene
// and files (render/check/CheckReportOutput): what nothing could place, the
// bindings and the notes, each mistake with its lines and what it explains,
// the terms this scene cannot check. The status bar carries its short form.
// A uniform to place and a line of code are links: to the Uniforms dock's
// row, to the editor's line.
class VerdictDock : public QDockWidget
{
    Q_OBJECT

public:
    explicit VerdictDock(QWidget *parent = nullptr);

    // `current`: the check is of the code in the editor; false while that
    // code does not compile and the last good program is the one checked.
    void showVerdict(const CheckedFrame &result, bool current);
    QString text() const; // as shown, for tests

signals:
    void uniformChosen(const QString &name);
    void lineChosen(phonglab::ShaderStage stage, int line);

private:
    QTextBrowser *m_text = nullptr;
};

// The status bar's words for a verdict: "no verdict: choose what uZork
// means in Uniforms", "✗ 26.8 dB — attenuation + halfway-vector", "last
// good program: ✓ 95.7 dB" (checkStatusLine() with what the window adds).
QString verdictStatusText(const CheckedFrame &result, bool current);

} // namespace phonglab
