#include "ObjectEditDock.h"

#include "ObjectChoice.h"

#include <QComboBox>
#include <QFormLayout>

namespace phonglab {

ObjectEditDock::ObjectEditDock(const QString &title, const QString &objectName, QWidget *parent)
    : SceneEditDock(title, objectName, parent)
{
    auto *editor = new QWidget(this);
    m_form = new QFormLayout(editor);
    m_objects = new QComboBox(editor);
    connect(m_objects, &QComboBox::currentIndexChanged, this, &ObjectEditDock::showChosen);
    m_form->addRow(tr("Object"), m_objects);
    setWidget(editor);
}

int ObjectEditDock::selectedObject() const
{
    return m_objects->currentIndex();
}

void ObjectEditDock::selectObject(int index)
{
    m_objects->setCurrentIndex(index);
}

QWidget *ObjectEditDock::itemEditor() const
{
    // The form itself, not widget(): the window may put the form in a
    // scroll area (scrollWhenShort), and the form is what is enabled.
    return m_form->parentWidget();
}

void ObjectEditDock::showScene()
{
    fillObjectChoice(m_objects, scene());
}

} // namespace phonglab
