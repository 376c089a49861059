#include "SceneDock.h"
#include "core/support/Language.h"

#include "MeshStatsText.h"
#include "NormalsEditor.h"
#include "mesh/import/BuiltinMeshes.h"

#include <QDir>
#include <QFileInfo>
#include <QHeaderView>
#include <QLocale>
#include <QSignalBlocker>
#include <QStyle>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace phonglab {

namespace {

constexpr int kObjectIndexRole = Qt::UserRole;

QTreeWidgetItem *addField(QTreeWidgetItem *parent, const QString &name, const QString &value)
{
    auto *item = new QTreeWidgetItem(parent, {name, value});
    item->setToolTip(1, value); // values can be wider than the dock
    return item;
}

QString meshDisplayName(const QString &resolved)
{
    return isBuiltinMeshSpec(resolved) ? resolved : QFileInfo(resolved).fileName();
}

} // namespace

SceneDock::SceneDock(QWidget *parent)
    : QDockWidget(tr("Scene"), parent)
    , m_tree(new QTreeWidget)
    , m_normals(new NormalsEditor)
{
    setObjectName(QStringLiteral("sceneDock")); // for QMainWindow::saveState
    m_tree->setColumnCount(2);
    m_tree->setHeaderLabels({tr("Object"), tr("Value")});
    m_tree->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_tree->setUniformRowHeights(true);

    auto *contents = new QWidget;
    auto *layout = new QVBoxLayout(contents);
    layout->addWidget(m_tree, 1);
    layout->addWidget(m_normals);
    setWidget(contents);

    connect(m_tree, &QTreeWidget::currentItemChanged, this, &SceneDock::followCurrentItem);
    connect(m_normals, &NormalsEditor::optionsEdited, this, [this](const NormalOptions &options) {
        if (m_selected >= 0)
            emit normalsChangeRequested(m_selected, options);
    });
    syncNormalsEditor();
}

void SceneDock::showScene(const Scene &scene, const QHash<QString, SceneMeshes::Entry> &meshes)
{
    m_scene = scene;
    const int keep = m_selected;
    {
        const QSignalBlocker blocker(m_tree); // the selection is restored below
        m_tree->clear();
        for (std::size_t i = 0; i < scene.objects.size(); ++i) {
            const auto it = meshes.constFind(meshKey(scene, scene.objects[i]));
            addObject(int(i), scene.objects[i], it == meshes.cend() ? nullptr : &*it);
        }
        m_tree->expandAll();
    }
    m_selected = -1;
    const int count = int(scene.objects.size());
    selectObject(count == 0 ? -1 : std::clamp(keep, 0, count - 1));
    syncNormalsEditor();
}

void SceneDock::selectObject(int index)
{
    QTreeWidgetItem *item = m_tree->topLevelItem(index);
    if (item)
        m_tree->setCurrentItem(item);
    else
        followCurrentItem(nullptr);
}

void SceneDock::addObject(int index, const SceneObject &object, const SceneMeshes::Entry *entry)
{
    const QString resolved = m_scene.resolveMeshPath(object.mesh);
    const bool builtin = isBuiltinMeshSpec(resolved);
    auto *item = new QTreeWidgetItem(m_tree, {meshDisplayName(resolved)});
    item->setData(0, kObjectIndexRole, index);
    item->setToolTip(0, QDir::toNativeSeparators(resolved));
    if (!entry) {
        item->setText(1, tr("not loaded"));
        return;
    }
    // Warnings first: they are what must not be cut off in a narrow dock.
    QString summary = tr("%1 triangles").arg(countText(entry->stats.triangles));
    if (entry->stats.detail != 1.0)
        summary +=
            tr(" (detail %1 %)").arg(QLocale().toString(entry->stats.detail * 100.0, 'g', 4));
    if (!entry->warnings.isEmpty()) {
        const qsizetype count = entry->warnings.size();
        summary = (count == 1 ? tr("1 warning") : tr("%1 warnings").arg(count))
            + QStringLiteral(" · ") + summary;
        item->setIcon(1, style()->standardIcon(QStyle::SP_MessageBoxWarning));
    }
    item->setText(1, summary);
    addStats(item, *entry, builtin);
    addWarnings(item, entry->warnings);
}

void SceneDock::addStats(QTreeWidgetItem *item, const SceneMeshes::Entry &entry, bool builtin)
{
    const MeshStats &stats = entry.stats;
    addField(item, tr("Vertices"), countText(stats.vertices));
    addField(item, tr("Triangles"), countText(stats.triangles));
    // The counts above are the reduced mesh's; say so, and what it came from.
    if (const QString detail = detailDescription(stats); !detail.isEmpty())
        addField(item, tr("Detail"), detail)
            ->setToolTip(0,
                         builtin ? tr("Tessellated coarser (the object's \"detail\")")
                                 : tr("Decimated from the loaded mesh (the object's \"detail\")"));
    addField(item, tr("Split vertices"), countText(stats.splitVertices))
        ->setToolTip(0, tr("Vertices duplicated where a position has several normals"));
    if (!builtin)
        addField(item, tr("In the file"),
                 tr("%1 vertices, %2 faces")
                     .arg(countText(stats.fileVertices), countText(stats.fileFaces)));
    addField(item, tr("Normals"), normalsDescription(stats, builtin));
    addField(item, tr("Bounds"), boundsDescription(stats));
    addField(item, tr("Surface"), surfaceDescription(stats));
    const QString loadTime = tr("%1 ms").arg(sentenceNumber(stats.loadMs, 'f', 1));
    addField(item, tr("Load time"),
             stats.fromCache ? tr("%1 (from the mesh cache)").arg(loadTime) : loadTime);
}

void SceneDock::addWarnings(QTreeWidgetItem *item, const QStringList &warnings)
{
    if (warnings.isEmpty())
        return;
    const QIcon icon = style()->standardIcon(QStyle::SP_MessageBoxWarning);
    QTreeWidgetItem *list = addField(item, tr("Warnings"), QString::number(warnings.size()));
    list->setIcon(0, icon);
    for (const QString &warning : warnings) {
        auto *row = new QTreeWidgetItem(list);
        row->setIcon(0, icon);
        row->setText(0, warning);
        row->setToolTip(0, warning);
        row->setFirstColumnSpanned(true); // sentences, not name/value pairs
    }
}

void SceneDock::followCurrentItem(QTreeWidgetItem *current)
{
    while (current && current->parent())
        current = current->parent();
    m_selected = current ? current->data(0, kObjectIndexRole).toInt() : -1;
    syncNormalsEditor();
}

void SceneDock::syncNormalsEditor()
{
    if (m_selected < 0 || m_selected >= int(m_scene.objects.size())) {
        m_normals->setOptions({});
        m_normals->setApplicable(false, tr("Select an object to choose how its normals are made"));
        return;
    }
    const SceneObject &object = m_scene.objects[m_selected];
    m_normals->setOptions(object.normals);
    if (isBuiltinMeshSpec(m_scene.resolveMeshPath(object.mesh)))
        m_normals->setApplicable(false, tr("builtin shapes have exact analytic normals"));
    else
        m_normals->setApplicable(true);
}

} // namespace phonglab
