#pragma once
#include <QWidget>

class QLabel;
class QProgressBar;
class QToolButton;

namespace phonglab {

class SceneLoadJob;

// The status bar's view of a SceneLoadJob: "Loading tree.obj", a progress
// bar and a Cancel button, shown only while a load runs.
class LoadProgressWidget : public QWidget
{
    Q_OBJECT

public:
    explicit LoadProgressWidget(SceneLoadJob *job, QWidget *parent = nullptr);

    QProgressBar *progressBar() const { return m_bar; }
    QToolButton *cancelButton() const { return m_cancel; }

private:
    void showStarted(const QString &label);
    void showProgress(double fraction);

    QLabel *m_label = nullptr;
    QProgressBar *m_bar = nullptr;
    QToolButton *m_cancel = nullptr;
};

} // namespace phonglab
