#include "ObjectPanel.h"

#include "ObjectChoice.h"

#include "Vec3Field.h"

#include <QComboBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QUndoStack>

namespace phonglab {

namespace {

constexpr double kMaxTranslate = 1e4;
constexpr double kMaxRotateDeg = 3600.0;
constexpr double kMaxScale = 1e3;

QString refuseZeroScale(const glm::dvec3 &scale)
{
    for (int axis = 0; axis < 3; ++axis)
        if (scale[axis] == 0.0)
            return ObjectPanel::tr("scale must not be zero: the object would collapse to a plane");
    return {};
}

} // namespace

ObjectPanel::ObjectPanel(QWidget *parent)
    : QDockWidget(tr("Object"), parent)
{
    setObjectName(QStringLiteral("ObjectPanel"));
    auto *form = new QWidget(this);
    auto *layout = new QFormLayout(form);
    m_objects = new QComboBox(form);
    connect(m_objects, &QComboBox::currentIndexChanged, this, &ObjectPanel::showSelected);
    layout->addRow(tr("Object"), m_objects);
    setWidget(form);
    addField(tr("Translate"), TransformField::Translate, kMaxTranslate);
    addField(tr("Rotate (°)"), TransformField::Rotate, kMaxRotateDeg);
    addField(tr("Scale"), TransformField::Scale, kMaxScale)->setCheck(refuseZeroScale);
}

Vec3Field *ObjectPanel::addField(const QString &label, TransformField which, double limit)
{
    auto *field = new Vec3Field(-limit, limit, widget());
    connect(field, &Vec3Field::edited, this,
            [this, which](const glm::dvec3 &, const glm::dvec3 &after) { push(which, after); });
    static_cast<QFormLayout *>(widget()->layout())->addRow(label, field);
    m_fields[int(which)] = field;
    return field;
}

void ObjectPanel::bind(QUndoStack *stack, SceneAccess access)
{
    m_stack = stack;
    m_access = std::move(access);
}

void ObjectPanel::refresh(const Scene &scene)
{
    m_scene = scene;
    m_showing = true;
    fillObjectChoice(m_objects, scene);
    m_showing = false;
    showSelected();
}

int ObjectPanel::selectedObject() const
{
    return m_objects->currentIndex();
}

void ObjectPanel::selectObject(int index)
{
    m_objects->setCurrentIndex(index);
}

Vec3Field *ObjectPanel::field(TransformField which) const
{
    return m_fields[int(which)];
}

void ObjectPanel::showSelected()
{
    const int index = selectedObject();
    const bool valid = index >= 0 && index < int(m_scene.objects.size());
    widget()->setEnabled(valid);
    if (!valid || m_showing)
        return;
    const Transform &t = m_scene.objects[index].transform;
    m_fields[int(TransformField::Translate)]->setValue(t.translate);
    m_fields[int(TransformField::Rotate)]->setValue(t.rotateDeg);
    m_fields[int(TransformField::Scale)]->setValue(t.scale);
}

void ObjectPanel::push(TransformField which, const glm::dvec3 &after)
{
    const int index = selectedObject();
    if (!m_stack || index < 0)
        return;
    const Transform before = m_scene.objects.at(index).transform;
    Transform changed = before;
    (which == TransformField::Translate    ? changed.translate
         : which == TransformField::Rotate ? changed.rotateDeg
                                           : changed.scale) = after;
    m_stack->push(new SetTransformCommand(m_access, index, before, changed, which));
}

} // namespace phonglab
