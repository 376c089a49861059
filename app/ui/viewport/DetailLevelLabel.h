#pragma once
#include <QLabel>

namespace phonglab {

class Viewport;

// In the viewport's bottom-left corner while any object has "detail":
// "auto": the level each object is drawn at ("tree.obj: level 2 of 6, 716
// triangles"), and the lights its draw leaves out. Rewritten only when
// what it says changes: each change paints it into the view's frame again.
class DetailLevelLabel : public QLabel
{
    Q_OBJECT

public:
    explicit DetailLevelLabel(Viewport *viewport);

    // What the last frame drew, as the label says it (empty: hidden).
    static QString describe(Viewport &viewport);

private:
    void refresh();

    Viewport *m_viewport = nullptr;
};

} // namespace phonglab
