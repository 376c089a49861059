#pragma once
#include "CheckOverlay.h"
#include "CheckRunner.h"
#include "VerdictDock.h"
#include "VerdictLabel.h"

#include <QObject>
#include <QPoint>
#include <optional>

class QAction;
class QComboBox;
class QDockWidget;
class QLabel;
class QMainWindow;
class QMenu;
class QTimer;
class QToolBar;

namespace phonglab {

class LiveShaderController;
class PixelInspectorDock;
class SceneLoadJob;
class Viewport;

// The editor's check: after every applied program, and
// whenever the view or the scene changes, the frame is drawn again
// single-sampled and checked against the exact image in the background
// (CheckRunner; typing is never blocked and the newest frame wins). Shows ✓ / ✗ with PSNR and the top diagnosis in
// the status bar, the overlays over the viewport, and the pixel inspector.
inline constexpr int kCheckDebounceMs = 150; // lets an orbit drag or a burst of edits settle
// A larger view is checked at a smaller size of the same shape: the reference
// costs ~190 bytes a pixel, and a 5K screen would ask for gigabytes.
inline constexpr qint64 kMaxCheckPixels = 1920 * 1080;

class LiveCheck : public QObject
{
    Q_OBJECT

public:
    LiveCheck(QMainWindow *window, Viewport *viewport, LiveShaderController *live);
    // No check runs while `job` loads a scene (the load gets every core);
    // the loaded scene is checked when it is shown.
    void pauseWhileLoading(const SceneLoadJob *job);
    // The View menu's entries: the inspector dock, the Check toolbar.
    void addViewActions(QMenu *view);
    // Something the check cannot see changed the frame (a uniform's value).
    void frameChanged() { schedule(); }

    void setOverlayMode(OverlayMode mode);
    // Inspects the pixel under `position` (viewport coordinates): at once
    // when the newest check shows the current view, else when it arrives.
    void inspect(QPoint position);

    const std::optional<CheckedFrame> &lastResult() const { return m_last; }
    bool isChecking() const { return m_pending || m_runner->isBusy(); }
    VerdictLabel *statusLabel() const { return m_status; }
    VerdictDock *verdictDock() const { return m_verdict; }
    CheckOverlay *overlay() const { return m_overlay; }
    PixelInspectorDock *inspector() const { return m_inspector; }

signals:
    void checked(const phonglab::CheckedFrame &result);
    // The way on from a verdict that has none: the Uniforms dock's row.
    void uniformToPlace(const QString &name);
    // The inspector or the verdict was brought to the front to be read.
    void dockBroughtForward(QDockWidget *dock);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void createToolBar(QMainWindow *window);
    void schedule(int delayMs = kCheckDebounceMs);
    void run();
    void show(const CheckedFrame &result);
    void showVerdict();
    void followStatusClick();
    // "checking… 40 %" while the exact image of a new view is made.
    void showProgress(int percent);
    void showInspected(QPointF position);
    QSize checkSize() const;
    bool isCurrent(const CheckedFrame &result) const;
    bool dragDivider(QEvent *event);

    Viewport *m_viewport = nullptr;
    LiveShaderController *m_live = nullptr;
    CheckRunner *m_runner = nullptr;
    CheckOverlay *m_overlay = nullptr;
    PixelInspectorDock *m_inspector = nullptr;
    VerdictLabel *m_status = nullptr;
    VerdictDock *m_verdict = nullptr;
    // False from a failed build of the editor's code until a program of it
    // is applied: the verdict shown is the last good program's.
    bool m_codeCompiles = true;
    QString m_checkingPrefix; // the last verdict's mark ("✓ "), kept while checking
    QComboBox *m_modes = nullptr;
    QAction *m_inspectAction = nullptr;
    QToolBar *m_toolBar = nullptr;
    QTimer *m_debounce = nullptr;
    std::optional<CheckedFrame> m_last;
    std::optional<QPointF>
        m_inspectWhenReady;         // where, as a fraction of the view's width and height
    bool m_pending = false;         // scheduled, not yet handed to the checker
    bool m_checkAfterFrame = false; // a new program: checked once its first frame is shown
    bool m_draggingDivider = false;
    const SceneLoadJob *m_loadJob = nullptr;
};

} // namespace phonglab
