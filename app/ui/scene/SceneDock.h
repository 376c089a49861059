#pragma once
#include "core/scene/Scene.h"
#include "mesh/loading/SceneMeshes.h"

#include <QDockWidget>

class QTreeWidget;
class QTreeWidgetItem;

namespace phonglab {

class NormalsEditor;

// The Scene dock: every object with its mesh's statistics (vertices,
// triangles, split vertices, normals, bounds, closed or open, load time) and
// the warnings loading it raised, and the normals control of the selected
// object.
class SceneDock : public QDockWidget
{
    Q_OBJECT

public:
    explicit SceneDock(QWidget *parent = nullptr);

    // `meshes`: stats and warnings by meshKey(), as Viewport::meshInfo().
    void showScene(const Scene &scene, const QHash<QString, SceneMeshes::Entry> &meshes);
    int selectedObject() const { return m_selected; }
    void selectObject(int index);

    QTreeWidget *objectTree() const { return m_tree; }
    NormalsEditor *normalsEditor() const { return m_normals; }

signals:
    // The user chose other normals for scene object `objectIndex`.
    void normalsChangeRequested(int objectIndex, const phonglab::NormalOptions &options);

private:
    void addObject(int index, const SceneObject &object, const SceneMeshes::Entry *entry);
    void addStats(QTreeWidgetItem *item, const SceneMeshes::Entry &entry, bool builtin);
    void addWarnings(QTreeWidgetItem *item, const QStringList &warnings);
    void followCurrentItem(QTreeWidgetItem *current);
    void syncNormalsEditor();

    QTreeWidget *m_tree = nullptr;
    NormalsEditor *m_normals = nullptr;
    Scene m_scene;
    int m_selected = -1;
};

} // namespace phonglab
