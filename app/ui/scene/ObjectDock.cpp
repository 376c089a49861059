#include "ObjectDock.h"

#include "Vec3Field.h"

#include <QFileInfo>
#include <QFormLayout>

namespace phonglab {

namespace {

constexpr double kMaxTranslate = 1e4;
constexpr double kMaxRotateDeg = 3600.0;
constexpr double kMaxScale = 1e3;

QString refuseZeroScale(const glm::dvec3 &scale)
{
    for (int axis = 0; axis < 3; ++axis)
        if (scale[axis] == 0.0)
            return ObjectDock::tr("scale must not be zero: the object would collapse to a plane");
    return {};
}

} // namespace

ObjectDock::ObjectDock(QWidget *parent)
    : ObjectEditDock(tr("Object"), QStringLiteral("ObjectPanel"),
                     parent) // the name saved layouts know it by
{
    addField(tr("Translate"), TransformField::Translate, kMaxTranslate);
    addField(tr("Rotate (°)"), TransformField::Rotate, kMaxRotateDeg);
    addField(tr("Scale"), TransformField::Scale, kMaxScale)->setCheck(refuseZeroScale);
}

Vec3Field *ObjectDock::addField(const QString &label, TransformField which, double limit)
{
    auto *field = new Vec3Field(-limit, limit, widget());
    connect(field, &Vec3Field::edited, this,
            [this, which](const glm::dvec3 &, const glm::dvec3 &after) { push(which, after); });
    form()->addRow(label, field);
    m_fields[int(which)] = field;
    return field;
}

Vec3Field *ObjectDock::field(TransformField which) const
{
    return m_fields[int(which)];
}

void ObjectDock::showItem(int index)
{
    const Transform &t = scene().objects[index].transform;
    m_fields[int(TransformField::Translate)]->setValue(t.translate);
    m_fields[int(TransformField::Rotate)]->setValue(t.rotateDeg);
    m_fields[int(TransformField::Scale)]->setValue(t.scale);
}

void ObjectDock::push(TransformField which, const glm::dvec3 &after)
{
    const int index = selectedObject();
    if (!isBound() || index < 0)
        return;
    const Transform before = scene().objects.at(index).transform;
    Transform changed = before;
    (which == TransformField::Translate    ? changed.translate
         : which == TransformField::Rotate ? changed.rotateDeg
                                           : changed.scale) = after;
    pushEdit(new SetTransformCommand(access(), index, before, changed, which));
}

} // namespace phonglab
