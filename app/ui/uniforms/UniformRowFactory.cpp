#include "UniformRowFactory.h"

#include "UniformBoolRow.h"
#include "UniformFloatRow.h"
#include "UniformIntRow.h"
#include "UniformVectorRow.h"
#include "render/program/UniformIntrospection.h"

#include <QLabel>
#include <algorithm>
#include <climits>

namespace phonglab {

namespace {

// What may be typed where the text gives no @range: anything finite a
// person would mean; the slider keeps a small default span.
constexpr double kOpenLimit = 1e6;

struct FloatRange {
    double sliderLow = 0.0, sliderHigh = 1.0, fieldLow = -kOpenLimit, fieldHigh = kOpenLimit,
           step = 0.01;
};

FloatRange floatRangeOf(const UniformRowSpec &spec)
{
    FloatRange r;
    const UniformDeclaration *d = spec.declaration;
    if (d && d->hasRange()) {
        r.sliderLow = r.fieldLow = *d->rangeLow;
        r.sliderHigh = r.fieldHigh = *d->rangeHigh;
        r.step = (r.sliderHigh - r.sliderLow) / 100.0;
    } else if (spec.baseName == QLatin1String("shininess")) {
        r.sliderLow = 1.0;
        r.sliderHigh = 512.0;
        r.step = 1.0;
    }
    if (d && d->step)
        r.step = *d->step;
    return r;
}

QList<float> floatsOf(const UniformValue &value)
{
    return QList<float>(value.floats.begin(), value.floats.begin() + value.components);
}

int intOf(const UniformValue &value)
{
    return value.kind == UniformValue::Kind::UInt ? int(std::min<GLuint>(value.uints[0], INT_MAX))
                                                  : value.ints[0];
}

QWidget *createFloatRow(const UniformRowSpec &spec, QWidget *parent)
{
    const FloatRange r = floatRangeOf(spec);
    return new UniformFloatRow(r.sliderLow, r.sliderHigh, r.fieldLow, r.fieldHigh, r.step, parent);
}

QWidget *createVectorRow(const UniformRowSpec &spec, int components, QWidget *parent)
{
    const FloatRange r = floatRangeOf(spec);
    const bool color = components == 3
        && (isColorUniformName(spec.baseName) || (spec.declaration && spec.declaration->color));
    return new UniformVectorRow(components, color, r.fieldLow, r.fieldHigh, r.step, parent);
}

QWidget *createIntRow(const UniformRowSpec &spec, bool isUnsigned, QWidget *parent)
{
    int low = isUnsigned ? 0 : -int(kOpenLimit), high = int(kOpenLimit);
    if (spec.declaration && spec.declaration->hasRange()) {
        low = int(*spec.declaration->rangeLow);
        high = int(*spec.declaration->rangeHigh);
    }
    return new UniformIntRow(low, high, parent);
}

QWidget *createTypedRow(const UniformRowSpec &spec, QWidget *parent)
{
    switch (spec.type) {
    case GL_FLOAT: return createFloatRow(spec, parent);
    case GL_FLOAT_VEC2: return createVectorRow(spec, 2, parent);
    case GL_FLOAT_VEC3: return createVectorRow(spec, 3, parent);
    case GL_FLOAT_VEC4: return createVectorRow(spec, 4, parent);
    case GL_INT: return createIntRow(spec, false, parent);
    case GL_UNSIGNED_INT: return createIntRow(spec, true, parent);
    case GL_BOOL: return new UniformBoolRow(parent);
    default: break;
    }
    // Matrices, samplers, ivecN...: named, not edited here.
    const QString type = glslTypeName(spec.type);
    return new QLabel(type.isEmpty() ? QObject::tr("(not editable here)") : type, parent);
}

void describeOwner(QWidget *row, const UniformRowSpec &spec)
{
    if (spec.owner != UniformOwner::User) {
        row->setEnabled(false);
        row->setToolTip(uniformOwnerNote(spec.owner));
        return;
    }
    if (qobject_cast<QLabel *>(row)) { // a type the dock has no editor for
        row->setToolTip(
            QObject::tr("%1 %2: not editable here").arg(glslTypeName(spec.type), spec.element));
        return;
    }
    row->setToolTip(QObject::tr("%1 %2: set on the program as you edit; kept across recompiles")
                        .arg(glslTypeName(spec.type), spec.element));
}

} // namespace

bool isColorUniformName(const QString &baseName)
{
    static const QStringList names = {QStringLiteral("ka"), QStringLiteral("kd"),
                                      QStringLiteral("ks"), QStringLiteral("Ia"),
                                      QStringLiteral("Id"), QStringLiteral("Is")};
    return names.contains(baseName);
}

QWidget *createUniformRow(const UniformRowSpec &spec, QWidget *parent)
{
    QWidget *row = createTypedRow(spec, parent);
    row->setObjectName(QStringLiteral("uniform:") + spec.element);
    if (spec.value) {
        showUniformValue(row, *spec.value);
    }
    describeOwner(row, spec);
    return row;
}

void showUniformValue(QWidget *row, const UniformValue &value)
{
    if (auto *f = qobject_cast<UniformFloatRow *>(row))
        f->setValue(value.floats[0]);
    else if (auto *v = qobject_cast<UniformVectorRow *>(row))
        v->setValues(floatsOf(value));
    else if (auto *i = qobject_cast<UniformIntRow *>(row))
        i->setValue(intOf(value));
    else if (auto *b = qobject_cast<UniformBoolRow *>(row))
        b->setValue(value.ints[0] != 0);
}

} // namespace phonglab
