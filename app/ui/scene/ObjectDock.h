#pragma once
#include "ObjectEditDock.h"

namespace phonglab {

class Vec3Field;

// Places the selected object: translate, rotate (degrees, about X then Y then
// Z) and scale per axis. Non-uniform scale is fine; a zero scale (the object
// would collapse and its normals with it) is refused at the field.
class ObjectDock : public ObjectEditDock
{
    Q_OBJECT

public:
    explicit ObjectDock(QWidget *parent = nullptr);

    Vec3Field *field(TransformField which) const;

protected:
    void showItem(int index) override;

private:
    Vec3Field *addField(const QString &label, TransformField which, double limit);
    void push(TransformField which, const glm::dvec3 &after);

    Vec3Field *m_fields[3] = {nullptr, nullptr, nullptr};
};

} // namespace phonglab
