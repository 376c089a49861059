#include "LightsDock.h"

#include "core/view/LightPlacement.h"

#include "Vec3Field.h"

#include <QCheckBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QListWidgetItem>
#include <QPushButton>
#include <QUndoStack>
#include <QVBoxLayout>
#include <algorithm>

namespace phonglab {

namespace {

constexpr double kMaxPosition = 1e4;
constexpr double kMaxIntensity = 100.0;
constexpr double kMaxAttenuation = 1e6;

// f_att = 1 / (c1 + c2·d + c3·d²): a sum of zero divides by zero at d = 0.
QString refuseNoAttenuation(const glm::dvec3 &c)
{
    if (c.x + c.y + c.z <= 0.0)
        return LightsDock::tr("c1 + c2 + c3 must be positive (got %1)").arg(c.x + c.y + c.z);
    return {};
}

} // namespace

LightsDock::LightsDock(QWidget *parent)
    : SceneEditDock(tr("Lights"), QStringLiteral("LightsDock"), parent)
{
    auto *content = new QWidget(this);
    auto *layout = new QVBoxLayout(content);
    layout->addWidget(buildList(content));

    m_editor = new QWidget(content);
    auto *form = new QFormLayout(m_editor);
    form->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_editor);
    setWidget(content);
    m_name = new QLineEdit(m_editor);
    m_name->setObjectName(QStringLiteral("lightName"));
    connect(m_name, &QLineEdit::editingFinished, this,
            [this] { renameLight(selectedLight(), m_name->text()); });
    form->addRow(tr("Name"), m_name);
    addField(tr("Position (world)"), LightField::Position, -kMaxPosition, kMaxPosition);
    addField(tr("Id (diffuse)"), LightField::Diffuse, 0.0, kMaxIntensity)->enableColourPicker();
    addField(tr("Is (specular)"), LightField::Specular, 0.0, kMaxIntensity)->enableColourPicker();
    addField(tr("c1, c2, c3"), LightField::Attenuation, 0.0, kMaxAttenuation)
        ->setCheck(refuseNoAttenuation);

    auto *ambientForm = new QFormLayout;
    m_ambient = new Vec3Field(0.0, kMaxIntensity, content);
    m_ambient->enableColourPicker();
    connect(m_ambient, &Vec3Field::edited, this,
            [this](const glm::dvec3 &before, const glm::dvec3 &after) {
                pushEdit(new SetAmbientCommand(access(), before, after));
            });
    ambientForm->addRow(tr("Ambient Ia"), m_ambient);
    layout->addLayout(ambientForm);
    m_headlight =
        new QCheckBox(tr("Headlight: follows the camera (not in world space, not saved)"), content);
    connect(m_headlight, &QCheckBox::toggled, this, &LightsDock::headlightToggled);
    layout->addWidget(m_headlight);
    layout->addStretch(1);
    updateButtons();
}

QWidget *LightsDock::buildList(QWidget *parent)
{
    auto *box = new QWidget(parent);
    auto *layout = new QVBoxLayout(box);
    layout->setContentsMargins(0, 0, 0, 0);
    m_list = new QListWidget(box);
    m_list->setMaximumHeight(120);
    connect(m_list, &QListWidget::currentRowChanged, this, [this] {
        showChosen();
        updateButtons();
        emit lightSelected(selectedLight());
    });
    connect(m_list, &QListWidget::itemChanged, this, &LightsDock::itemToggled);
    layout->addWidget(m_list);
    m_status = new QLabel(box);
    m_status->setWordWrap(true);
    layout->addWidget(m_status);
    auto *buttons = new QHBoxLayout;
    m_add = new QPushButton(tr("Add Light"), box);
    m_remove = new QPushButton(tr("Remove"), box);
    connect(m_add, &QPushButton::clicked, this, &LightsDock::addLight);
    connect(m_remove, &QPushButton::clicked, this, &LightsDock::removeSelectedLight);
    buttons->addWidget(m_add);
    buttons->addWidget(m_remove);
    layout->addLayout(buttons);
    return box;
}

Vec3Field *LightsDock::addField(const QString &label, LightField which, double minimum,
                                double maximum)
{
    auto *field = new Vec3Field(minimum, maximum, m_editor);
    connect(field, &Vec3Field::edited, this,
            [this, which](const glm::dvec3 &, const glm::dvec3 &after) { push(which, after); });
    static_cast<QFormLayout *>(m_editor->layout())->addRow(label, field);
    m_fields[int(which)] = field;
    return field;
}

void LightsDock::showScene()
{
    const int keep = selectedLight();
    m_list->clear();
    const auto addItem = [this](const QString &text, bool on) {
        auto *item = new QListWidgetItem(text, m_list);
        item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
        item->setCheckState(on ? Qt::Checked : Qt::Unchecked);
    };
    for (int i = 0; i < int(scene().lights.size()); ++i)
        addItem(displayName(i), scene().lights[i].enabled);
    m_list->setCurrentRow(std::min(keep < 0 ? 0 : keep, m_list->count() - 1));
    m_ambient->setValue(scene().ambient);
}

void LightsDock::refreshed()
{
    updateButtons();
    emit lightSelected(selectedLight());
}

int LightsDock::selectedLight() const
{
    const int row = m_list->currentRow();
    return row < int(scene().lights.size()) ? row : -1;
}

void LightsDock::itemToggled(QListWidgetItem *item)
{
    if (isShowing())
        return;
    const bool on = item->checkState() == Qt::Checked;
    const int row = m_list->row(item);
    if (!setLightEnabled(row, on)) // put the box back as it was
        whileShowing([&] { item->setCheckState(on ? Qt::Unchecked : Qt::Checked); });
}

bool LightsDock::setLightEnabled(int index, bool on)
{
    if (!isBound() || index < 0 || index >= int(scene().lights.size())
        || scene().lights[index].enabled == on)
        return false;
    m_status->clear();
    pushEdit(new SetLightEnabledCommand(access(), index, on));
    return true;
}

int LightsDock::switchedOffCount() const
{
    return int(scene().lights.size()) - scene().enabledLightCount();
}

bool LightsDock::renameLight(int index, const QString &name)
{
    const std::string after = name.trimmed().toStdString();
    if (!isBound() || index < 0 || index >= int(scene().lights.size())
        || scene().lights[index].name == after)
        return false;
    pushEdit(new RenameLightCommand(access(), index, scene().lights[index].name, after));
    return true;
}

QString LightsDock::displayName(int index) const
{
    if (index < 0 || index >= int(scene().lights.size()))
        return {};
    const std::string &name = scene().lights[index].name;
    return name.empty() ? tr("Light %1").arg(index + 1) : QString::fromStdString(name);
}

void LightsDock::selectLight(int index)
{
    m_list->setCurrentRow(index);
}

void LightsDock::showItem(int index)
{
    const PointLight &light = scene().lights[index];
    m_name->setText(QString::fromStdString(light.name));
    m_name->setPlaceholderText(tr("Light %1").arg(index + 1));
    m_fields[int(LightField::Position)]->setValue(light.position);
    m_fields[int(LightField::Diffuse)]->setValue(light.diffuse);
    m_fields[int(LightField::Specular)]->setValue(light.specular);
    m_fields[int(LightField::Attenuation)]->setValue(light.attenuation);
}

void LightsDock::updateButtons()
{
    m_add->setEnabled(int(scene().lights.size()) < kMaxLights);
    m_remove->setEnabled(selectedLight() >= 0);
}

void LightsDock::push(LightField which, const glm::dvec3 &after)
{
    const int index = selectedLight();
    if (!isBound() || index < 0)
        return;
    const PointLight before = scene().lights.at(index);
    PointLight changed = before;
    switch (which) {
    case LightField::Position: changed.position = after; break;
    case LightField::Diffuse: changed.diffuse = after; break;
    case LightField::Specular: changed.specular = after; break;
    case LightField::Attenuation: changed.attenuation = after; break;
    }
    pushEdit(new SetLightCommand(access(), index, before, changed, which));
}

void LightsDock::addLight()
{
    if (!isBound() || int(scene().lights.size()) >= kMaxLights)
        return;
    PointLight light;
    light.position = visibleLightPosition(scene().camera, int(scene().lights.size()));
    pushEdit(new AddLightCommand(access(), light));
    selectLight(int(scene().lights.size()) - 1);
}

void LightsDock::removeSelectedLight()
{
    const int index = selectedLight();
    if (!isBound() || index < 0 || index >= int(scene().lights.size()))
        return;
    pushEdit(new RemoveLightCommand(access(), index, scene().lights[index]));
}

} // namespace phonglab
