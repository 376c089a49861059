#pragma once
#include "bench/BenchResult.h"
#include "bench/ErrorBudget.h"
#include "core/scene/ShadingMethod.h"
#include "ui/viewport/ReadoutPace.h"

#include <QDockWidget>
#include <vector>

class QChartView;
class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QVBoxLayout;

namespace phonglab {

class BenchProcess;
class Viewport;

// No more drawing than the scene needs: live frame time, the speed-against-
// accuracy chart of the scene in the window (every shipped method at every
// detail level, measured for the current view and lights by `phonglab
// bench` in a child process), and Fit to budget, which picks the cheapest
// method and coarsest detail whose measured error stays within the budget,
// applies it and reports the triangles and milliseconds saved.
class PerformanceDock : public QDockWidget
{
    Q_OBJECT

public:
    // The bench runs in phonglabExecutable() (core/support/PhonglabExecutable).
    explicit PerformanceDock(Viewport *viewport, QWidget *parent = nullptr);
    ~PerformanceDock() override;

    ErrorBudget budget() const;
    void setBudget(const ErrorBudget &budget);
    // The clock the frame readout's pace reads (tests move their own on).
    void setReadoutClock(ReadoutPace::Clock clock) { m_framePace.setClock(std::move(clock)); }

    // The rows of the last measurement (empty before the first).
    const std::vector<BenchRow> &rows() const { return m_rows; }
    // What the last fit chose (chosen -1 before one ran or when nothing fits).
    const BudgetFit &lastFit() const { return m_fit; }
    QString reportText() const;
    bool isMeasuring() const;

public slots:
    // The toggle as the scene on screen has it (no request sent).
    void showAutoDetail(bool on);
    void measure();     // measure only: chart, no change to the scene
    void fitToBudget(); // measure, then apply the cheapest method and detail within budget
    void restoreFullDetail();
    void cancel();

signals:
    // Show the scene with every object at `detail` and `method` shading.
    void applyFitRequested(phonglab::ShadingMethod method, double detail);
    // The toggle: every object to "detail": "auto" (true) or back to full detail.
    void autoDetailRequested(bool on);
    void measured();   // rows() are new (or the run failed: rows() empty)
    void fitApplied(); // the fit was handed to applyFitRequested

private:
    // The constructor's widgets, top to bottom, then the buttons' and the view's signals.
    void addBudgetRow(QWidget *body, QVBoxLayout *layout);
    void addAutoDetailToggle(QWidget *body, QVBoxLayout *layout);
    void addButtons(QWidget *body, QVBoxLayout *layout);
    void addResultsArea(QWidget *body, QVBoxLayout *layout);
    void connectActions();
    void setBudgetKind(int index);
    void sendReductionAllowance();
    void startMeasurement(bool thenFit);
    void showProgress(int done, int total, const QString &stage);
    void measurementFinished(const std::vector<BenchRow> &rows, const QString &error);
    void applyFit();
    void showChart();
    void showFrame(double meanMsOfLastSecond, qint64 triangles);
    void setRunning(bool running);

    Viewport *m_viewport = nullptr;
    BenchProcess *m_process = nullptr;
    QLabel *m_frameLabel = nullptr;
    ReadoutPace m_framePace;
    QComboBox *m_budgetKind = nullptr;
    QCheckBox *m_autoDetail = nullptr;
    QDoubleSpinBox *m_budgetValue = nullptr;
    QPushButton *m_measureButton = nullptr;
    QPushButton *m_fitButton = nullptr;
    QPushButton *m_fullButton = nullptr;
    QPushButton *m_cancelButton = nullptr;
    QProgressBar *m_progress = nullptr;
    QChartView *m_chartView = nullptr;
    QLabel *m_report = nullptr;

    std::vector<BenchRow> m_rows;
    BudgetFit m_fit;
    bool m_fitAfterMeasuring = false;
    // The shading shown before the last fit, for Full detail.
    ShadingMethod m_shadingBeforeFit = ShadingMethod::Phong;
};

} // namespace phonglab
