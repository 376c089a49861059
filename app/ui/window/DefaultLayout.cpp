#include "DefaultLayout.h"

#include <QDockWidget>
#include <QMainWindow>
#include <QPlainTextEdit>
#include <QScrollArea>
#include <algorithm>

namespace phonglab {

namespace {

// The tabs under the code get the height the material needs, but never
// more than 40 % of the column, and in a short column (a laptop's) no more
// than what leaves the code 640 pixels, down to 22 % of it: the code is
// what people come for, and a short tab scrolls.
constexpr double kMostTabsShareOfHeight = 0.4;
constexpr double kLeastTabsShareOfHeight = 0.25;
constexpr int kCodeHeight = 610;
constexpr int kSplitterWidth = 8;

void tabify(QMainWindow &window, std::initializer_list<QDockWidget *> docks)
{
    QDockWidget *previous = nullptr;
    for (QDockWidget *dock : docks) {
        if (previous)
            window.tabifyDockWidget(previous, dock);
        previous = dock;
    }
}

} // namespace

void scrollWhenShort(QDockWidget *dock)
{
    QWidget *contents = dock->widget();
    if (!contents || qobject_cast<QScrollArea *>(contents))
        return;
    auto *scroll = new QScrollArea(dock);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidgetResizable(true);
    scroll->setWidget(contents);
    dock->setWidget(scroll);
}

namespace {

// The height `contents` would show itself in whole: its hint, with each
// text view as tall as its text (the inspector's terms).
int wholeHeight(QWidget *contents)
{
    int height = contents->sizeHint().height();
    for (const QPlainTextEdit *text : contents->findChildren<QPlainTextEdit *>()) {
        const int needed = text->blockCount() * text->fontMetrics().lineSpacing()
            + 2 * text->frameWidth() + int(2 * text->document()->documentMargin());
        height += std::max(0, needed - text->sizeHint().height());
    }
    return height;
}

} // namespace

void giveRoomUnderTheCode(QMainWindow &window, const WindowDocks &d, QDockWidget *dock)
{
    if (!dock || dock->isFloating() || !dock->isVisible() || !d.shaders->isVisible()
        || window.dockWidgetArea(dock) != window.dockWidgetArea(d.shaders) || dock == d.shaders)
        return;
    const int column = d.shaders->height() + dock->height();
    QWidget *contents = dock->widget();
    // A scroll area's own hint is its viewport's: the contents' is wanted.
    if (auto *scroll = qobject_cast<QScrollArea *>(contents); scroll && scroll->widget())
        contents = scroll->widget();
    const int chrome = dock->height() - (dock->widget() ? dock->widget()->height() : 0);
    const int wanted =
        std::min(wholeHeight(contents) + chrome, int(column * kMostRoomForAShownDock));
    if (dock->height() >= wanted)
        return;
    window.resizeDocks({d.shaders, dock}, {column - wanted, wanted}, Qt::Vertical);
}

QRect defaultWindowGeometry(const QRect &available)
{
    const QSize size(int(available.width() * kWindowShareOfScreen),
                     int(available.height() * kWindowShareOfScreenHeight));
    QRect geometry(QPoint(), size);
    geometry.moveCenter(available.center());
    return geometry;
}

void applyDefaultLayout(QMainWindow &window, const WindowDocks &d, int editorWidth)
{
    const std::initializer_list<QDockWidget *> all = {d.scene,     d.object,      d.lights,
                                                      d.shaders,   d.material,    d.uniforms,
                                                      d.inspector, d.performance, d.verdict};
    for (QDockWidget *dock : all) {
        dock->setFloating(false); // before leaving the layout: a floating one would stay afloat
        window.removeDockWidget(dock);
    }
    // The side columns reach from the toolbar to the status bar.
    window.setCorner(Qt::TopLeftCorner, Qt::LeftDockWidgetArea);
    window.setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);
    window.setCorner(Qt::TopRightCorner, Qt::RightDockWidgetArea);
    window.setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);

    const int width = window.width();
    // The view keeps at least half the window's width (and the splitter
    // between it and the code); the code gets 80 columns where that leaves
    // room for them.
    const int viewWidth = std::max(kMinViewportWidth, width / 2 + kSplitterWidth);
    const bool sceneColumn = width >= kSceneColumnWidth + editorWidth + viewWidth;
    const int codeWidth = std::min(editorWidth, std::max(0, width - viewWidth));

    window.addDockWidget(Qt::RightDockWidgetArea, d.shaders);
    window.addDockWidget(Qt::RightDockWidgetArea, d.material, Qt::Vertical);
    if (sceneColumn) {
        window.addDockWidget(Qt::LeftDockWidgetArea, d.scene);
        tabify(window, {d.scene, d.object, d.lights, d.performance});
        tabify(window, {d.material, d.uniforms, d.inspector, d.verdict});
    } else {
        tabify(window,
               {d.material, d.uniforms, d.lights, d.object, d.scene, d.inspector, d.verdict,
                d.performance});
    }
    for (QDockWidget *dock : all)
        dock->setVisible(dock != d.performance && dock != d.inspector && dock != d.verdict);
    d.scene->raise();
    d.material->raise();

    window.resizeDocks({d.shaders}, {codeWidth}, Qt::Horizontal);
    if (sceneColumn)
        window.resizeDocks({d.scene}, {kSceneColumnWidth}, Qt::Horizontal);
    const int height = window.centralWidget() ? window.centralWidget()->height() : window.height();
    const int tabs =
        std::min({d.material->widget()->sizeHint().height(), int(height * kMostTabsShareOfHeight),
                  std::max(int(height * kLeastTabsShareOfHeight), height - kCodeHeight)});
    window.resizeDocks({d.shaders, d.material}, {height - tabs, tabs}, Qt::Vertical);
}

} // namespace phonglab
