#include "LiveCheck.h"

#include "PixelInspectorDock.h"
#include "ui/scene/SceneLoadJob.h"
#include "ui/shaders/LiveShaderController.h"
#include "ui/viewport/Viewport.h"

#include <QAction>
#include <QComboBox>
#include <QLabel>
#include <QMainWindow>
#include <QMenu>
#include <QMouseEvent>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>
#include <utility>

#include <algorithm>
#include <cmath>

namespace phonglab {

namespace {

constexpr int kDividerGrabPx = 6;
// A new program's check waits this long after its first frame, so that the
// event loop handles what queued up meanwhile (keys typed, the window's
// repaint) before the check's thread builds and draws the program again.
constexpr int kAfterFrameMs = 20;

} // namespace

LiveCheck::LiveCheck(QMainWindow *window, Viewport *viewport, LiveShaderController *live)
    : QObject(window)
    , m_viewport(viewport)
    , m_live(live)
    , m_runner(new CheckRunner(this))
    , m_overlay(new CheckOverlay(viewport))
    , m_inspector(new PixelInspectorDock(window))
    , m_status(new VerdictLabel(window))
    , m_verdict(new VerdictDock(window))
    , m_debounce(new QTimer(this))
{
    m_status->setObjectName(QStringLiteral("checkStatus"));
    m_status->setVerdict(tr("check: waiting for the first frame"));
    window->statusBar()->addPermanentWidget(m_status, 1);
    window->addDockWidget(Qt::RightDockWidgetArea, m_inspector);
    m_inspector->hide();
    window->addDockWidget(Qt::RightDockWidgetArea, m_verdict);
    m_verdict->hide();
    connect(m_status, &VerdictLabel::clicked, this, &LiveCheck::followStatusClick);
    connect(m_verdict, &VerdictDock::uniformChosen, this, &LiveCheck::uniformToPlace);
    // The editor's code does not compile: what is shown is the last good
    // program's verdict, and says so.
    connect(live, &LiveShaderController::buildFailed, this, [this] {
        m_codeCompiles = false;
        showVerdict();
    });
    createToolBar(window);

    m_debounce->setSingleShot(true);
    connect(m_debounce, &QTimer::timeout, this, &LiveCheck::run);
    connect(m_runner, &CheckRunner::finished, this, &LiveCheck::show);
    connect(m_runner, &CheckRunner::progressed, this, &LiveCheck::showProgress);
    // A new program is checked at once, but after its first frame is on
    // screen: the check's own build and draw of it would otherwise take
    // cores from that frame. View and scene changes come in bursts.
    connect(live, &LiveShaderController::programApplied, this, [this] {
        m_codeCompiles = true;
        m_debounce->stop(); // a check due now would draw the old frame's moment
        m_checkAfterFrame = true;
        m_pending = true;
        m_overlay->setFresh(false);
    });
    connect(viewport, &Viewport::frameSwapped, this, [this] {
        if (std::exchange(m_checkAfterFrame, false))
            schedule(kAfterFrameMs);
    });
    for (auto signal : {&Viewport::sceneChanged, &Viewport::sceneParametersChanged,
                        &Viewport::cameraChanged, &Viewport::glInitialized})
        connect(viewport, signal, this, [this] { schedule(); });
    connect(viewport, &Viewport::shippedProgramLoaded, this, [this] { schedule(); });
    connect(viewport, &Viewport::headlightChanged, this, [this] { schedule(); });
    // A new scene: what was inspected belongs to the old one.
    connect(viewport, &Viewport::sceneChanged, this, [this] {
        m_inspectWhenReady.reset();
        m_overlay->setArrows(std::nullopt, {});
    });
    connect(viewport, &Viewport::cameraChanged, this,
            [this] { m_overlay->setCamera(m_viewport->camera()); });
    viewport->installEventFilter(this);
}

void LiveCheck::pauseWhileLoading(const SceneLoadJob *job)
{
    m_loadJob = job;
    connect(job, &SceneLoadJob::started, m_runner, &CheckRunner::cancel);
    // A load that does not end in a new scene leaves the old one to check again.
    connect(job, &SceneLoadJob::failed, this, [this] { schedule(); });
    connect(job, &SceneLoadJob::cancelled, this, [this] { schedule(); });
}

void LiveCheck::addViewActions(QMenu *view)
{
    view->addSeparator();
    QAction *dock = m_inspector->toggleViewAction();
    dock->setText(tr("Pi&xel Inspector"));
    view->addAction(dock);
    QAction *verdict = m_verdict->toggleViewAction();
    verdict->setText(tr("Check &Verdict"));
    view->addAction(verdict);
    QAction *bar = m_toolBar->toggleViewAction();
    bar->setText(tr("&Check Toolbar"));
    view->addAction(bar);
}

void LiveCheck::createToolBar(QMainWindow *window)
{
    QToolBar *bar = m_toolBar = window->addToolBar(tr("Check"));
    bar->setObjectName(QStringLiteral("checkToolBar"));
    bar->addWidget(new QLabel(tr(" Overlay: "), bar));
    m_modes = new QComboBox(bar);
    m_modes->setObjectName(QStringLiteral("overlayMode"));
    m_modes->addItem(tr("Off"), int(OverlayMode::Off));
    m_modes->addItem(tr("Error heatmap"), int(OverlayMode::Heatmap));
    m_modes->addItem(tr("Split: exact | yours"), int(OverlayMode::Split));
    m_modes->addItem(tr("Exact"), int(OverlayMode::Exact));
    m_modes->setToolTip(tr("Compare the view with the exact image of the illumination equation"));
    bar->addWidget(m_modes);
    connect(m_modes, &QComboBox::currentIndexChanged, this,
            [this](int i) { setOverlayMode(OverlayMode(m_modes->itemData(i).toInt())); });
    m_inspectAction = bar->addAction(tr("Inspect"));
    m_inspectAction->setCheckable(true);
    m_inspectAction->setShortcut(Qt::Key_I);
    m_inspectAction->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    m_viewport->addAction(m_inspectAction);
    m_inspectAction->setToolTip(
        tr("Click a pixel to see the terms of the equation there (or Ctrl+click) [I]"));
    connect(m_inspectAction, &QAction::toggled, this, [this](bool on) {
        m_viewport->setCursor(on ? Qt::CrossCursor : Qt::ArrowCursor);
        if (on) {
            m_inspector->show();
            m_inspector->raise();
            emit dockBroughtForward(m_inspector);
        }
    });
}

void LiveCheck::setOverlayMode(OverlayMode mode)
{
    m_overlay->setMode(mode);
    const int index = m_modes->findData(int(mode));
    if (index != m_modes->currentIndex())
        m_modes->setCurrentIndex(index);
}

void LiveCheck::schedule(int delayMs)
{
    m_pending = true;
    m_overlay->setFresh(false);
    // Every change restarts the wait, so a drag is checked once it rests;
    // only a check already due at once (a new program) is not put off.
    const bool immediateDue = m_debounce->isActive() && m_debounce->interval() == 0;
    if (delayMs == 0 || !immediateDue)
        m_debounce->start(delayMs);
}

void LiveCheck::run()
{
    if (!m_viewport->isRenderReady() || m_viewport->glContext().isContextLent()
        || !m_viewport->isVisible() || (m_loadJob && m_loadJob->isRunning())) {
        m_debounce->start(kCheckDebounceMs); // the frame cannot be had now: try again shortly
        return;
    }
    m_pending = false;
    // No drawing here: the checker's thread draws this frame again itself.
    FrameRecipe frame{m_viewport->renderedScene(), m_live->appliedSources(),
                      m_viewport->program().values(), m_viewport->drawing().renderOptions(),
                      checkSize()};
    if (frame.size.isEmpty())
        return;
    m_checkingPrefix = m_last && m_last->hasVerdict()
        ? m_status->verdict().section(QLatin1Char(' '), 0, 0) + QLatin1Char(' ')
        : QString();
    m_status->setVerdict(m_checkingPrefix + tr("checking…"));
    m_runner->request(frame);
}

void LiveCheck::showProgress(int percent)
{
    if (!m_runner->isBusy())
        return; // a late report of a check that has answered
    m_status->setVerdict(m_checkingPrefix + tr("checking… %1 %").arg(percent));
}

QSize LiveCheck::checkSize() const
{
    const QSize full = m_viewport->size() * m_viewport->devicePixelRatioF();
    const qint64 pixels = qint64(full.width()) * full.height();
    if (pixels <= kMaxCheckPixels)
        return full;
    const double scale = std::sqrt(double(kMaxCheckPixels) / double(pixels));
    return QSize(std::max(1, int(full.width() * scale)), std::max(1, int(full.height() * scale)));
}

bool LiveCheck::isCurrent(const CheckedFrame &result) const
{
    return result.generation == m_runner->newestGeneration() && !m_pending && !m_runner->isBusy()
        && result.reference && result.yours.size() == checkSize();
}

void LiveCheck::show(const CheckedFrame &result)
{
    m_last = result;
    showVerdict();
    m_overlay->setImages(result.exact, result.heatmap);
    m_overlay->setFresh(isCurrent(result));
    if (m_inspectWhenReady && isCurrent(result)) {
        showInspected(*m_inspectWhenReady);
        m_inspectWhenReady.reset();
    }
    emit checked(result);
}

void LiveCheck::showVerdict()
{
    if (!m_last)
        return;
    m_status->setVerdict(verdictStatusText(*m_last, m_codeCompiles));
    m_verdict->showVerdict(*m_last, m_codeCompiles);
}

void LiveCheck::followStatusClick()
{
    if (m_last && !m_last->unbound.empty()) {
        emit uniformToPlace(m_last->unbound.front().name);
        return;
    }
    m_verdict->show();
    m_verdict->raise();
    emit dockBroughtForward(m_verdict);
}

void LiveCheck::inspect(QPoint position)
{
    // Pixel centres: the point's fraction of the view, whatever the size the
    // frame was checked at.
    const QPointF fraction((position.x() + 0.5) / std::max(1, m_viewport->width()),
                           (position.y() + 0.5) / std::max(1, m_viewport->height()));
    m_inspector->show();
    m_inspector->raise();
    emit dockBroughtForward(m_inspector);
    if (m_last && isCurrent(*m_last)) {
        showInspected(fraction);
        return;
    }
    m_inspectWhenReady = fraction;
    m_inspector->showMessage(
        tr("Checking the current view; the pixel is shown when that is done."));
}

void LiveCheck::showInspected(QPointF fraction)
{
    const CheckedFrame &r = *m_last;
    const QPoint pixel(
        std::clamp(int(std::floor(fraction.x() * r.yours.width())), 0, r.yours.width() - 1),
        std::clamp(int(std::floor(fraction.y() * r.yours.height())), 0, r.yours.height() - 1));
    const std::optional<PixelTerms> terms =
        pixelTerms(r.reference->hits, r.scene, r.reference->shader.shading, pixel.x(), pixel.y(),
                   r.report().equation);
    if (!terms) {
        m_inspector->showMessage(tr("Pixel (%1, %2) shows the background: no surface, no equation.")
                                     .arg(pixel.x())
                                     .arg(pixel.y()));
        m_overlay->setArrows(std::nullopt, {});
        return;
    }
    m_inspector->showPixel(*terms, r.yours.pixelColor(pixel), r.exact.pixelColor(pixel));
    m_overlay->setCamera(m_viewport->camera());
    m_overlay->setArrows(terms, r.scene.camera.viewMatrix());
}

bool LiveCheck::eventFilter(QObject *watched, QEvent *event)
{
    if (watched != m_viewport)
        return false;
    if (event->type() == QEvent::Resize) {
        m_overlay->setGeometry(m_viewport->rect());
        schedule();
        return false;
    }
    if (dragDivider(event))
        return true;
    if (event->type() == QEvent::MouseButtonPress) {
        const auto *mouse = static_cast<QMouseEvent *>(event);
        const bool inspecting =
            m_inspectAction->isChecked() || mouse->modifiers().testFlag(Qt::ControlModifier);
        if (mouse->button() == Qt::LeftButton && inspecting) {
            inspect(mouse->position().toPoint());
            return true;
        }
    }
    return false;
}

// In split mode a press near the divider moves the divider, not the camera.
bool LiveCheck::dragDivider(QEvent *event)
{
    if (m_overlay->mode() != OverlayMode::Split)
        return false;
    const auto type = event->type();
    if (type != QEvent::MouseButtonPress && type != QEvent::MouseMove
        && type != QEvent::MouseButtonRelease)
        return false;
    const auto *mouse = static_cast<QMouseEvent *>(event);
    const double x = mouse->position().x();
    if (type == QEvent::MouseButtonPress && mouse->button() == Qt::LeftButton
        && std::abs(x - m_overlay->divider() * m_viewport->width()) <= kDividerGrabPx) {
        m_draggingDivider = true;
        return true;
    }
    if (!m_draggingDivider)
        return false;
    m_overlay->setDivider(x / std::max(1, m_viewport->width()));
    if (type == QEvent::MouseButtonRelease)
        m_draggingDivider = false;
    return true;
}

} // namespace phonglab
