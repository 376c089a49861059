#include "PerformanceDock.h"

#include <QCheckBox>
#include <QSignalBlocker>

#include "BenchProcess.h"
#include "charts/SpeedAccuracyChart.h"
#include "ui/viewport/Viewport.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

namespace phonglab {

namespace {

constexpr int kMaxErrorIndex = 0;
constexpr int kPsnrIndex = 1;

} // namespace

PerformanceDock::PerformanceDock(Viewport *viewport, QWidget *parent)
    : QDockWidget(tr("Performance"), parent)
    , m_viewport(viewport)
    , m_process(new BenchProcess(this))
{
    setObjectName(QStringLiteral("PerformanceDock"));
    auto *body = new QWidget(this);
    auto *layout = new QVBoxLayout(body);

    m_frameLabel = new QLabel(tr("Frame: -"), body);
    m_frameLabel->setToolTip(
        tr("Draw time per frame (first OpenGL call to glFinish), the mean of the last "
           "second's frames, and the triangles drawn."));
    layout->addWidget(m_frameLabel);

    addBudgetRow(body, layout);
    addAutoDetailToggle(body, layout);
    addButtons(body, layout);
    addResultsArea(body, layout);
    layout->addStretch(0);
    setWidget(body);
    connectActions();
}

void PerformanceDock::addBudgetRow(QWidget *body, QVBoxLayout *layout)
{
    auto *budgetRow = new QHBoxLayout;
    budgetRow->addWidget(new QLabel(tr("Error budget:"), body));
    m_budgetKind = new QComboBox(body);
    m_budgetKind->addItems({tr("max error (8-bit steps)"), tr("PSNR at least (dB)")});
    m_budgetKind->setToolTip(
        tr("Measured against the exact CPU reference, more than 2 px from silhouettes."));
    m_budgetValue = new QDoubleSpinBox(body);
    budgetRow->addWidget(m_budgetKind, 1);
    budgetRow->addWidget(m_budgetValue);
    layout->addLayout(budgetRow);
    connect(m_budgetKind, &QComboBox::currentIndexChanged, this, &PerformanceDock::setBudgetKind);
    setBudget(ErrorBudget{});
}

// Needs the budget widgets: the allowance it sends is read from them.
void PerformanceDock::addAutoDetailToggle(QWidget *body, QVBoxLayout *layout)
{
    m_autoDetail = new QCheckBox(tr("Model only what the view needs"), body);
    m_autoDetail->setObjectName(QStringLiteral("autoDetail"));
    m_autoDetail->setToolTip(
        tr("Every object at \"detail\": \"auto\": drawn at the coarsest level its size on "
           "screen allows, and without the lights it cannot show, each within a quarter of the "
           "budget. The levels are built in the background the first time."));
    layout->addWidget(m_autoDetail);
    connect(m_autoDetail, &QCheckBox::toggled, this, [this](bool on) {
        sendReductionAllowance();
        emit autoDetailRequested(on);
    });
    connect(m_budgetKind, &QComboBox::currentIndexChanged, this,
            &PerformanceDock::sendReductionAllowance);
    connect(m_budgetValue, &QDoubleSpinBox::valueChanged, this,
            &PerformanceDock::sendReductionAllowance);
    sendReductionAllowance();
}

void PerformanceDock::addButtons(QWidget *body, QVBoxLayout *layout)
{
    auto *buttons = new QHBoxLayout;
    m_measureButton = new QPushButton(tr("Measure"), body);
    m_measureButton->setToolTip(
        tr("Time every shipped method at every detail level for this view and these "
           "lights and compare each with the exact answer."));
    m_fitButton = new QPushButton(tr("Fit to budget"), body);
    m_fitButton->setToolTip(
        tr("Measure, then show the cheapest method and coarsest detail within the budget."));
    m_fullButton = new QPushButton(tr("Full detail"), body);
    m_fullButton->setToolTip(
        tr("Back to every object's full mesh and the shading used before the fit."));
    m_fullButton->setEnabled(false);
    m_cancelButton = new QPushButton(tr("Cancel"), body);
    m_cancelButton->setVisible(false);
    for (QPushButton *b : {m_measureButton, m_fitButton, m_fullButton, m_cancelButton})
        buttons->addWidget(b);
    layout->addLayout(buttons);
}

// The progress bar, the chart and the report under it.
void PerformanceDock::addResultsArea(QWidget *body, QVBoxLayout *layout)
{
    m_progress = new QProgressBar(body);
    m_progress->setVisible(false);
    layout->addWidget(m_progress);

    m_chartView = new QChartView(body);
    m_chartView->setRenderHint(QPainter::Antialiasing);
    m_chartView->setMinimumHeight(260);
    m_chartView->setVisible(false);
    layout->addWidget(m_chartView, 1);

    m_report = new QLabel(
        tr("Measure to see frame time against error for every method and detail level."), body);
    m_report->setWordWrap(true);
    m_report->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_report);
}

void PerformanceDock::connectActions()
{
    connect(m_measureButton, &QPushButton::clicked, this, &PerformanceDock::measure);
    connect(m_fitButton, &QPushButton::clicked, this, &PerformanceDock::fitToBudget);
    connect(m_fullButton, &QPushButton::clicked, this, &PerformanceDock::restoreFullDetail);
    connect(m_cancelButton, &QPushButton::clicked, this, &PerformanceDock::cancel);
    connect(m_process, &BenchProcess::progress, this, &PerformanceDock::showProgress);
    connect(m_process, &BenchProcess::finished, this, &PerformanceDock::measurementFinished);
    connect(m_viewport, &Viewport::frameRendered, this, &PerformanceDock::showFrame);
    // Hidden, the readout was not written: coming into sight it asks the
    // view for a frame, whose figures it shows (the view may be still).
    connect(this, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible)
            m_viewport->frames().requestFrame();
    });
}

PerformanceDock::~PerformanceDock() = default;

void PerformanceDock::sendReductionAllowance()
{
    m_viewport->drawing().setReductionAllowance(budget().reductionAllowance(),
                                                m_autoDetail->isChecked());
}

void PerformanceDock::showAutoDetail(bool on)
{
    const QSignalBlocker quiet(m_autoDetail);
    m_autoDetail->setChecked(on);
    sendReductionAllowance();
}

ErrorBudget PerformanceDock::budget() const
{
    ErrorBudget budget;
    if (m_budgetKind->currentIndex() == kPsnrIndex) {
        budget.kind = ErrorBudget::Kind::Psnr;
        budget.minPsnr = m_budgetValue->value();
    } else {
        budget.kind = ErrorBudget::Kind::MaxError;
        budget.maxError = int(m_budgetValue->value());
    }
    return budget;
}

void PerformanceDock::setBudget(const ErrorBudget &budget)
{
    const bool psnr = budget.kind == ErrorBudget::Kind::Psnr;
    m_budgetKind->setCurrentIndex(psnr ? kPsnrIndex : kMaxErrorIndex);
    setBudgetKind(m_budgetKind->currentIndex()); // the ranges, even if the kind did not change
    m_budgetValue->setValue(psnr ? budget.minPsnr : double(budget.maxError));
}

// Each kind keeps a sensible range; switching resets to its default.
void PerformanceDock::setBudgetKind(int index)
{
    const bool psnr = index == kPsnrIndex;
    m_budgetValue->setDecimals(psnr ? 1 : 0);
    m_budgetValue->setRange(psnr ? 10.0 : 0.0, psnr ? 99.0 : 255.0);
    m_budgetValue->setValue(psnr ? 40.0 : 2.0);
    m_budgetValue->setSuffix(psnr ? tr(" dB") : tr(" /255"));
}

QString PerformanceDock::reportText() const
{
    return m_report->text();
}

bool PerformanceDock::isMeasuring() const
{
    return m_process->isRunning();
}

void PerformanceDock::measure()
{
    startMeasurement(false);
}

void PerformanceDock::fitToBudget()
{
    startMeasurement(true);
}

void PerformanceDock::cancel()
{
    m_process->cancel();
}

void PerformanceDock::startMeasurement(bool thenFit)
{
    m_fitAfterMeasuring = thenFit;
    // Measured at what the viewport shows, in device pixels.
    const QSize size = m_viewport->size() * m_viewport->devicePixelRatioF();
    if (const Result<> started = m_process->start(m_viewport->currentScene(), size, budget());
        !started) {
        m_report->setText(tr("Cannot measure: %1").arg(started.error()));
        emit measured();
        return;
    }
    m_report->setText(
        tr("Measuring %1 × %2 px with the scene's lights…").arg(size.width()).arg(size.height()));
    setRunning(true);
}

void PerformanceDock::showProgress(int done, int total, const QString &stage)
{
    m_progress->setRange(0, std::max(total, 1));
    m_progress->setValue(done);
    m_progress->setFormat(QStringLiteral("%v / %m"));
    m_progress->setToolTip(stage);
}

void PerformanceDock::measurementFinished(const std::vector<BenchRow> &rows, const QString &error)
{
    setRunning(false);
    m_rows = rows;
    m_fit = {};
    if (!error.isEmpty()) {
        m_report->setText(error == QLatin1String("cancelled")
                              ? tr("Measurement cancelled.")
                              : tr("Measurement failed: %1").arg(error));
        emit measured();
        return;
    }
    m_fit = phonglab::fitToBudget(m_rows, budget());
    showChart();
    m_report->setText(tr("Within %1: %2").arg(budget().describe(), m_fit.summary));
    emit measured();
    if (m_fitAfterMeasuring)
        applyFit();
}

void PerformanceDock::applyFit()
{
    if (m_fit.chosen < 0)
        return; // the report already says nothing fits
    const BenchRow &chosen = m_rows[std::size_t(m_fit.chosen)];
    const auto method = shadingFromName(chosen.method);
    if (!method)
        return;
    m_shadingBeforeFit = m_viewport->currentScene().shading;
    m_fullButton->setEnabled(true);
    emit applyFitRequested(*method, chosen.detail);
    const QLocale locale;
    QString text =
        tr("Fitted to %1: %2 shading at detail %3, %4 triangles, %5 ms per frame (measured "
           "offscreen, without multisampling).")
            .arg(budget().describe(), chosen.method, detailPercent(chosen.detail),
                 locale.toString(chosen.triangles), locale.toString(chosen.frameMs, 'f', 2));
    if (m_fit.baseline >= 0) {
        const BenchRow &full = m_rows[std::size_t(m_fit.baseline)];
        const double share = full.triangles > 0
            ? 100.0 * double(m_fit.trianglesSaved) / double(full.triangles)
            : 0.0;
        text +=
            tr(" Saved against full-detail Phong: %1 triangles (%2 %) and %3 ms (%4 → %5 ms).")
                .arg(locale.toString(m_fit.trianglesSaved), locale.toString(share, 'f', 0),
                     locale.toString(m_fit.msSaved, 'f', 2), locale.toString(full.frameMs, 'f', 2),
                     locale.toString(chosen.frameMs, 'f', 2));
    }
    m_report->setText(text);
    emit fitApplied();
}

void PerformanceDock::restoreFullDetail()
{
    emit applyFitRequested(m_shadingBeforeFit, 1.0);
    m_fullButton->setEnabled(false);
    m_report->setText(
        tr("Back to full detail with %1 shading.").arg(shadingName(m_shadingBeforeFit)));
}

void PerformanceDock::showChart()
{
    QChart *chart = createSpeedAccuracyChart(m_rows, tr("This view: frame time against error"));
    QChart *old = m_chartView->chart();
    m_chartView->setChart(chart); // the view owns the new chart
    delete old;
    m_chartView->setVisible(true);
}

// Only while the label can be seen, at the status bar's pace.
void PerformanceDock::showFrame(double meanMsOfLastSecond, qint64 triangles)
{
    if (!m_frameLabel->isVisible()) {
        m_framePace.forget();
        return;
    }
    if (!m_framePace.isDue(triangles))
        return;
    m_framePace.shown(triangles);
    const QLocale locale;
    m_frameLabel->setText(
        tr("Frame: %1 ms · %2 triangles")
            .arg(locale.toString(meanMsOfLastSecond, 'f', 2), locale.toString(triangles)));
}

void PerformanceDock::setRunning(bool running)
{
    m_progress->setVisible(running);
    m_progress->setValue(0);
    m_cancelButton->setVisible(running);
    m_measureButton->setEnabled(!running);
    m_fitButton->setEnabled(!running);
    m_budgetKind->setEnabled(!running);
    m_budgetValue->setEnabled(!running);
}

} // namespace phonglab
