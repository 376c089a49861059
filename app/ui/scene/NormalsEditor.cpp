#include "NormalsEditor.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QSignalBlocker>
#include <QSpinBox>

namespace phonglab {

namespace {

constexpr int kDefaultCreaseDeg = 30; // offered when the crease is switched on
constexpr int kMaxCreaseDeg = 180;

QString methodToolTip(NormalMethod method)
{
    switch (method) {
    case NormalMethod::Auto:
        return QObject::tr("The file's normals; computed angle-weighted when it has none");
    case NormalMethod::Flat:
        return QObject::tr("Each face's own normal at all its corners (faceted)");
    case NormalMethod::Average:
        return QObject::tr("Unweighted mean of the normals of the faces around a vertex");
    case NormalMethod::AreaWeighted: return QObject::tr("Face normals weighted by face area");
    case NormalMethod::AngleWeighted:
        return QObject::tr("Face normals weighted by the face's angle at the vertex");
    }
    return {};
}

QString creaseToolTip()
{
    return QObject::tr("Faces meeting at a sharper angle than this do not share normals");
}

} // namespace

NormalsEditor::NormalsEditor(QWidget *parent)
    : QGroupBox(tr("Normals"), parent)
    , m_method(new QComboBox(this))
    , m_creaseEnabled(new QCheckBox(tr("Crease"), this))
    , m_creaseAngle(new QSpinBox(this))
{
    m_method->setObjectName(QStringLiteral("normalMethod"));
    m_creaseEnabled->setObjectName(QStringLiteral("creaseEnabled"));
    m_creaseAngle->setObjectName(QStringLiteral("creaseAngle"));

    for (const QString &name : normalMethodNames()) {
        m_method->addItem(name, name);
        m_method->setItemData(m_method->count() - 1, methodToolTip(*normalMethodFromName(name)),
                              Qt::ToolTipRole);
    }
    m_creaseEnabled->setToolTip(creaseToolTip());
    m_creaseAngle->setRange(0, kMaxCreaseDeg);
    m_creaseAngle->setValue(kDefaultCreaseDeg);
    m_creaseAngle->setSuffix(QStringLiteral("°"));
    // Every reported value reloads the mesh: not one per digit typed.
    m_creaseAngle->setKeyboardTracking(false);

    auto *crease = new QHBoxLayout;
    crease->addWidget(m_creaseEnabled);
    crease->addWidget(m_creaseAngle, 1);
    auto *form = new QFormLayout(this);
    form->addRow(tr("Method"), m_method);
    form->addRow(crease);
    updateCreaseEnabled();

    connect(m_method, &QComboBox::activated, this, &NormalsEditor::emitEdited);
    connect(m_creaseEnabled, &QCheckBox::toggled, this, [this] {
        updateCreaseEnabled();
        emitEdited();
    });
    connect(m_creaseAngle, &QSpinBox::valueChanged, this, &NormalsEditor::emitEdited);
}

void NormalsEditor::setOptions(const NormalOptions &options)
{
    const QSignalBlocker blockMethod(m_method), blockCheck(m_creaseEnabled),
        blockAngle(m_creaseAngle);
    m_method->setCurrentIndex(m_method->findData(normalMethodName(options.method)));
    m_creaseEnabled->setChecked(options.creaseAngleDeg.has_value());
    if (options.creaseAngleDeg)
        m_creaseAngle->setValue(qRound(*options.creaseAngleDeg));
    updateCreaseEnabled();
}

NormalOptions NormalsEditor::options() const
{
    NormalOptions options;
    options.method =
        normalMethodFromName(m_method->currentData().toString()).value_or(NormalMethod::Auto);
    if (m_creaseEnabled->isChecked())
        options.creaseAngleDeg = double(m_creaseAngle->value());
    return options;
}

void NormalsEditor::setApplicable(bool applicable, const QString &reason)
{
    setEnabled(applicable);
    // Disabled widgets still show tooltips: these explain why.
    const QString tip = applicable ? QString() : reason;
    setToolTip(tip);
    m_method->setToolTip(tip);
    m_creaseAngle->setToolTip(tip);
    m_creaseEnabled->setToolTip(applicable ? creaseToolTip() : reason);
}

void NormalsEditor::emitEdited()
{
    emit optionsEdited(options());
}

void NormalsEditor::updateCreaseEnabled()
{
    m_creaseAngle->setEnabled(m_creaseEnabled->isChecked());
}

} // namespace phonglab
