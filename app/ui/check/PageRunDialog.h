#pragma once
#include "render/page/PageCheck.h"

#include <QDialog>
#include <QFutureWatcher>

#include <atomic>
#include <memory>

class QLabel;
class QProgressBar;
class QPushButton;
class QTextBrowser;

namespace phonglab {

// File → Run the Page: the project's page run in headless Chromium as
// `phonglab check --page` runs it (render/page/PageCheck), in the
// background, cancellable; then the browser's frame, PhongLab's drawing of
// it and their difference side by side, with what the run found: the
// fidelity, the JavaScript half (each with its file and line), the
// student's own scene against its exact image.
class PageRunDialog : public QDialog
{
    Q_OBJECT

public:
    PageRunDialog(const PageRequest &request, QWidget *parent = nullptr);
    ~PageRunDialog() override;

    // Whether the run has ended (finished, failed or cancelled); the
    // findings' text, as `check --page` prints it.
    bool finished() const { return m_finished; }
    QString findingsText() const;
    const PageCheck &result() const { return m_check; }

signals:
    void runFinished();

private:
    void start();
    void showResult();
    void cancelOrClose();
    QLabel *frameLabel(const QString &objectName);

    PageRequest m_request;
    PageCheck m_check;
    std::shared_ptr<std::atomic<bool>> m_cancelled = std::make_shared<std::atomic<bool>>(false);
    QFutureWatcher<PageCapturing> m_watcher;
    bool m_finished = false;
    QLabel *m_status = nullptr;
    QProgressBar *m_progress = nullptr;
    QLabel *m_browser = nullptr;
    QLabel *m_drawn = nullptr;
    QLabel *m_difference = nullptr;
    QTextBrowser *m_findings = nullptr;
    QPushButton *m_button = nullptr;
};

} // namespace phonglab
