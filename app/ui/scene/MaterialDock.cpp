#include "MaterialDock.h"

#include "Vec3Field.h"
#include "core/scene/MaterialPresets.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QPushButton>
#include <QSlider>

namespace phonglab {

namespace {

constexpr double kMaxCoefficient = 10.0; // beyond this a coefficient is a typo
constexpr double kMinShininess = 0.01;   // the scene format needs n > 0
constexpr double kMaxShininess = 4096.0;
constexpr int kSliderMax = 512; // the slider covers the useful part

} // namespace

MaterialDock::MaterialDock(QWidget *parent)
    : ObjectEditDock(tr("Material"), QStringLiteral("MaterialPanel"),
                     parent) // the name saved layouts know it by
{
    buildForm();
}

void MaterialDock::buildForm()
{
    QWidget *form = widget();
    QFormLayout *layout = this->form();

    const auto addCoefficient = [&](const QString &label, MaterialField which) {
        auto *field = new Vec3Field(0.0, kMaxCoefficient, form);
        field->enableColourPicker();
        connect(field, &Vec3Field::edited, this,
                [this, which](const glm::dvec3 &, const glm::dvec3 &after) {
                    Material m = scene().objects.at(selectedObject()).material;
                    (which == MaterialField::Ka       ? m.ka
                         : which == MaterialField::Kd ? m.kd
                                                      : m.ks) = after;
                    pushMaterial(m, which);
                });
        layout->addRow(label, field);
        return field;
    };
    m_ka = addCoefficient(tr("ka (ambient)"), MaterialField::Ka);
    m_kd = addCoefficient(tr("kd (diffuse)"), MaterialField::Kd);
    m_ks = addCoefficient(tr("ks (specular)"), MaterialField::Ks);

    m_shininess = new QDoubleSpinBox(form);
    m_shininess->setRange(kMinShininess, kMaxShininess);
    m_shininess->setDecimals(2);
    m_shininess->setKeyboardTracking(false); // one edit per finished number, not per key
    m_shininessSlider = new QSlider(Qt::Horizontal, form);
    m_shininessSlider->setRange(1, kSliderMax);
    connect(m_shininessSlider, &QSlider::valueChanged, this, [this](int v) {
        if (!isShowing())
            m_shininess->setValue(v);
    });
    connect(m_shininess, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        if (isShowing() || selectedObject() < 0)
            return;
        Material m = scene().objects.at(selectedObject()).material;
        m.shininess = v;
        pushMaterial(m, MaterialField::Shininess);
    });
    auto *shininessRow = new QHBoxLayout;
    shininessRow->addWidget(m_shininessSlider, 1);
    shininessRow->addWidget(m_shininess);
    layout->addRow(tr("Shininess n"), shininessRow);

    m_presets = new QComboBox(form);
    auto *apply = new QPushButton(tr("Apply"), form);
    auto *save = new QPushButton(tr("Save as Preset…"), form);
    connect(apply, &QPushButton::clicked, this,
            [this] { applyMaterialPreset(m_presets->currentIndex()); });
    connect(save, &QPushButton::clicked, this, &MaterialDock::askPresetName);
    auto *presetRow = new QHBoxLayout;
    presetRow->addWidget(m_presets, 1);
    presetRow->addWidget(apply);
    layout->addRow(tr("Preset"), presetRow);
    layout->addRow(QString(), save);
    reloadPresets();
}

Vec3Field *MaterialDock::field(MaterialField which) const
{
    return which == MaterialField::Ka ? m_ka : which == MaterialField::Kd ? m_kd : m_ks;
}

void MaterialDock::showItem(int index)
{
    const Material &m = scene().objects[index].material;
    m_ka->setValue(m.ka);
    m_kd->setValue(m.kd);
    m_ks->setValue(m.ks);
    m_shininess->setValue(m.shininess);
    m_shininessSlider->setValue(int(std::round(m.shininess)));
}

void MaterialDock::pushMaterial(const Material &after, MaterialField field)
{
    const int index = selectedObject();
    const Material before = scene().objects.at(index).material;
    if (before != after)
        pushEdit(new SetMaterialCommand(access(), index, before, after, field));
}

void MaterialDock::applyMaterialPreset(int index)
{
    const QList<MaterialPreset> presets = allMaterialPresets();
    if (index < 0 || index >= presets.size() || selectedObject() < 0)
        return;
    pushMaterial(presets[index].material, MaterialField::Preset);
}

void MaterialDock::saveAsPreset(const QString &name)
{
    if (name.trimmed().isEmpty() || selectedObject() < 0)
        return;
    saveUserMaterialPreset({name.trimmed(), scene().objects.at(selectedObject()).material});
    reloadPresets();
    m_presets->setCurrentIndex(m_presets->findText(name.trimmed()));
}

void MaterialDock::askPresetName()
{
    bool ok = false;
    const QString name = QInputDialog::getText(this, tr("Save Material Preset"), tr("Name:"),
                                               QLineEdit::Normal, {}, &ok);
    if (ok)
        saveAsPreset(name);
}

void MaterialDock::reloadPresets()
{
    m_presets->clear();
    for (const MaterialPreset &preset : allMaterialPresets())
        m_presets->addItem(preset.name);
}

} // namespace phonglab
