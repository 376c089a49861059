#include "DetailLevelLabel.h"

#include "Viewport.h"

#include <QFileInfo>
#include <QLocale>

namespace phonglab {

DetailLevelLabel::DetailLevelLabel(Viewport *viewport)
    : QLabel(viewport)
    , m_viewport(viewport)
{
    setObjectName(QStringLiteral("detailLevels"));
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setStyleSheet(QStringLiteral(
        "QLabel { background: rgba(0, 0, 0, 150); color: white; padding: 3px 6px; }"));
    setToolTip(tr("\"detail\": \"auto\": the level each object is drawn at, chosen from its size "
                  "on screen within the Performance dock's budget"));
    hide();
    connect(viewport, &Viewport::frameRendered, this, &DetailLevelLabel::refresh);
}

QString DetailLevelLabel::describe(Viewport &viewport)
{
    const Scene &scene = viewport.currentScene();
    const std::vector<Renderer::ObjectDraw> &draws = viewport.drawing().objectDraws();
    QStringList lines;
    const QLocale locale;
    for (std::size_t i = 0; i < scene.objects.size() && i < draws.size(); ++i) {
        const SceneObject &object = scene.objects[i];
        if (!object.autoDetail)
            continue;
        const Renderer::ObjectDraw &d = draws[i];
        QString line = QObject::tr("%1: level %2 of %3, %4 triangles")
                           .arg(QFileInfo(object.mesh).fileName())
                           .arg(d.level)
                           .arg(d.levels - 1)
                           .arg(locale.toString(d.triangles));
        if (d.lightsLeftOut > 0)
            line += QObject::tr(", %n light(s) left out", nullptr, d.lightsLeftOut);
        lines << line;
    }
    return lines.join(QLatin1Char('\n'));
}

void DetailLevelLabel::refresh()
{
    const QString text = describe(*m_viewport);
    if (text == this->text() && isVisible() == !text.isEmpty())
        return;
    setText(text);
    setVisible(!text.isEmpty());
    adjustSize();
    move(8, m_viewport->height() - height() - 8);
}

} // namespace phonglab
