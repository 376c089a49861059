#include "LoadProgressWidget.h"

#include "ui/scene/SceneLoadJob.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QToolButton>

namespace phonglab {

namespace {
constexpr int kBarSteps = 1000;
constexpr int kBarWidth = 160; // wide enough to read, narrow enough for the frame stats beside it
} // namespace

LoadProgressWidget::LoadProgressWidget(SceneLoadJob *job, QWidget *parent)
    : QWidget(parent)
    , m_label(new QLabel(this))
    , m_bar(new QProgressBar(this))
    , m_cancel(new QToolButton(this))
{
    m_bar->setRange(0, kBarSteps);
    m_bar->setFixedWidth(kBarWidth);
    m_bar->setTextVisible(false);
    m_cancel->setText(tr("Cancel"));
    m_cancel->setToolTip(tr("Stop loading and keep the current scene"));
    m_cancel->setAutoRaise(true);

    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_label);
    layout->addWidget(m_bar);
    layout->addWidget(m_cancel);
    hide();

    connect(m_cancel, &QToolButton::clicked, job, &SceneLoadJob::cancel);
    connect(job, &SceneLoadJob::started, this, &LoadProgressWidget::showStarted);
    connect(job, &SceneLoadJob::progressChanged, this, &LoadProgressWidget::showProgress);
    connect(job, &SceneLoadJob::loaded, this, &QWidget::hide);
    connect(job, &SceneLoadJob::failed, this, &QWidget::hide);
    connect(job, &SceneLoadJob::cancelled, this, &QWidget::hide);
}

void LoadProgressWidget::showStarted(const QString &label)
{
    m_label->setText(tr("Loading %1").arg(label));
    m_bar->setValue(0);
    show();
}

void LoadProgressWidget::showProgress(double fraction)
{
    m_bar->setValue(qRound(fraction * kBarSteps));
}

} // namespace phonglab
