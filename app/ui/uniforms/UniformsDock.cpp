#include "UniformsDock.h"

#include "BindingChoice.h"

#include "UniformBoolRow.h"
#include "UniformFloatRow.h"
#include "UniformIntRow.h"
#include "UniformRowFactory.h"
#include "UniformVectorRow.h"
#include "ui/shaders/ShaderDock.h"
#include "ui/viewport/Viewport.h"

#include <QBoxLayout>
#include <QFormLayout>
#include <QLabel>
#include <QScrollArea>
#include <QStyle>
#include <QTimer>
#include <utility>

namespace phonglab {

namespace {

constexpr qint64 kDrivenRefreshMs = 250;

const UniformDeclaration *findDeclaration(const std::vector<UniformDeclaration> &declared,
                                          const QString &name)
{
    for (const UniformDeclaration &d : declared)
        if (d.name == name)
            return &d;
    return nullptr;
}

} // namespace

UniformsDock::UniformsDock(QWidget *parent)
    : QDockWidget(tr("Uniforms"), parent)
    , m_contents(new QWidget)
    , m_form(new QFormLayout(m_contents))
{
    setObjectName(QStringLiteral("UniformsDock"));
    m_form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    m_scroll = new QScrollArea(this);
    m_scroll->setWidgetResizable(true);
    m_scroll->setWidget(m_contents);
    setWidget(m_scroll);
    m_sinceRefresh.start();
}

void UniformsDock::attach(Viewport *viewport, ShaderDock *shaders)
{
    m_viewport = viewport;
    m_shaders = shaders;
    // Queued: frameRendered comes from inside a frame, where the context
    // must not be released.
    connect(m_viewport, &Viewport::frameRendered, this, &UniformsDock::onFrameRendered,
            Qt::QueuedConnection);
}

void UniformsDock::scheduleRebuild()
{
    m_rebuildPending = true;
    // A frame already on its way (a new program's first, presented by its
    // trial) brings the rebuild as well as one asked for.
    if (m_viewport && !m_viewport->frames().isFrameComing())
        m_viewport->frames().requestFrame();
}

void UniformsDock::onFrameRendered()
{
    if (m_rebuildPending) {
        rebuild();
        return;
    }
    if (m_sinceRefresh.elapsed() >= kDrivenRefreshMs && !m_viewport->glContext().isContextLent())
        refreshDrivenValues();
}

bool UniformsDock::readProgram(Program &program)
{
    if (!m_viewport)
        return false;
    std::optional<ViewProgram::Uniforms> uniforms = m_viewport->program().readUniforms();
    if (!uniforms)
        return false;
    program.active = std::move(uniforms->active);
    program.values = std::move(uniforms->values);
    program.bindings = std::move(uniforms->bindings);
    program.explicitBindings = m_viewport->currentScene().bindings;
    return true;
}

std::vector<UniformDeclaration> UniformsDock::declarations() const
{
    std::vector<UniformDeclaration> all =
        parseUniformDeclarations(QString::fromUtf8(m_shaders->text(ShaderStage::Vertex)));
    for (UniformDeclaration &d :
         parseUniformDeclarations(QString::fromUtf8(m_shaders->text(ShaderStage::Fragment))))
        all.push_back(std::move(d));
    return all;
}

// What the rows are made from, besides the values: a program whose key is
// the last one's gets its values shown in the rows there are.
QStringList UniformsDock::layoutKey(const Program &program,
                                    const std::vector<UniformDeclaration> &declared)
{
    QStringList key;
    for (const ActiveUniformInfo &u : program.active) {
        const QString name = QString::fromUtf8(u.name);
        const auto word = program.explicitBindings.find(name);
        key << QStringLiteral("%1 %2 %3 %4 %5 %6")
                   .arg(name)
                   .arg(u.type)
                   .arg(u.size)
                   .arg(u.isArray)
                   .arg(int(uniformOwner(program.bindings.meaningOf(name))))
                   .arg(word == program.explicitBindings.end() ? QStringLiteral("-")
                            : word->second                     ? bindingMeaningKey(*word->second)
                                                               : kUnboundWord);
    }
    for (const UniformDeclaration &d : declared)
        key << QStringLiteral("%1 %2 %3 %4 %5 %6 %7 %8")
                   .arg(d.type, d.name)
                   .arg(d.isArray)
                   .arg(d.arraySize)
                   .arg(d.rangeLow.value_or(qQNaN()))
                   .arg(d.rangeHigh.value_or(qQNaN()))
                   .arg(d.step.value_or(qQNaN()))
                   .arg(d.color);
    return key;
}

bool UniformsDock::rebuild()
{
    Program program;
    if (!readProgram(program))
        return false;
    m_rebuildPending = false;
    const std::vector<UniformDeclaration> declared = declarations();
    // An edit that keeps the uniforms (most do) keeps the rows: making them
    // again took the GUI thread ~25 ms after every applied program.
    QStringList key = layoutKey(program, declared);
    if (key == m_layoutKey && !m_rows.isEmpty()) {
        m_values = program.values;
        for (const UniformValue &value : m_values.values)
            if (QWidget *row = m_rows.value(QString::fromUtf8(value.name)))
                showUniformValue(row, value);
        m_sinceRefresh.restart();
        emit rebuilt();
        return true;
    }
    m_layoutKey = std::move(key);
    clearRows();
    m_values = program.values;
    for (const ActiveUniformInfo &uniform : program.active)
        addActive(uniform, program, declared);
    for (const UniformDeclaration &d : declared) {
        const bool active =
            std::any_of(program.active.begin(), program.active.end(),
                        [&](const ActiveUniformInfo &u) { return u.name == d.name.toUtf8(); });
        if (!active && !m_rows.contains(d.name))
            addInactive(d);
    }
    m_sinceRefresh.restart();
    emit rebuilt();
    return true;
}

void UniformsDock::clearRows()
{
    while (m_form->rowCount() > 0)
        m_form->removeRow(0); // deletes the label and the row widget
    m_rows.clear();
    m_owners.clear();
    m_inactive.clear();
}

void UniformsDock::addActive(const ActiveUniformInfo &uniform, const Program &program,
                             const std::vector<UniformDeclaration> &declared)
{
    UniformRowSpec spec;
    spec.baseName = QString::fromUtf8(uniform.name);
    spec.type = uniform.type;
    spec.owner = uniformOwner(program.bindings.meaningOf(spec.baseName));
    spec.declaration = findDeclaration(declared, spec.baseName);
    for (int element = 0; element < uniform.size; ++element) {
        spec.element = uniform.isArray ? QStringLiteral("%1[%2]").arg(spec.baseName).arg(element)
                                       : spec.baseName;
        spec.value = m_values.find(spec.element.toUtf8());
        QWidget *row = createUniformRow(spec, m_contents);
        m_owners.insert(spec.element, spec.owner);
        QWidget *label = element == 0 ? labelWithChoice(spec.baseName, program) : nullptr;
        addRow(spec.element, spec.element, row, label);
        if (spec.owner == UniformOwner::User)
            connectRow(row, spec.element);
    }
}

// The uniform's name over its "bound to" choice (BindingChoice).
QWidget *UniformsDock::labelWithChoice(const QString &name, const Program &program)
{
    const auto variable =
        std::find_if(program.bindings.variables.begin(), program.bindings.variables.end(),
                     [&](const VariableBinding &v) { return v.variable.name == name; });
    if (variable == program.bindings.variables.end())
        return nullptr;
    auto *label = new QWidget(m_contents);
    auto *layout = new QVBoxLayout(label);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(1);
    auto *title = new QLabel(name, label);
    layout->addWidget(title);
    std::optional<std::optional<BindingMeaning>> word; // none: automatic
    if (const auto it = program.explicitBindings.find(name); it != program.explicitBindings.end())
        word = it->second;
    // "Automatic" is what PhongLab made of it: by its name, or by its use.
    const std::optional<BindingMeaning> automatic =
        variable->isExplicit ? automaticMeaning(variable->variable) : variable->meaning;
    auto *choice = new BindingChoice(variable->variable, automatic, word, label);
    layout->addWidget(choice);
    if (variable->byUse && !variable->isExplicit) {
        auto *why = new QLabel(tr("by its use: %1 (%2 shader, line %3)")
                                   .arg(variable->byUse->reason, stageName(variable->byUse->stage))
                                   .arg(variable->byUse->line),
                               label);
        why->setObjectName(QStringLiteral("byUse:") + name);
        why->setWordWrap(true);
        why->setEnabled(false); // a note's grey
        layout->addWidget(why);
    }
    // Shown while the check finds nothing to place it (markUnplaced()).
    title->setObjectName(QStringLiteral("uniformName:") + name);
    auto *unplaced = new QLabel(tr("bound to nothing: choose what it is"), label);
    unplaced->setObjectName(QStringLiteral("unplaced:") + name);
    unplaced->setStyleSheet(QStringLiteral("color: #c62828;"));
    unplaced->setWordWrap(true);
    layout->addWidget(unplaced);
    showUnplaced(name);
    connect(choice, &BindingChoice::chosen, this, [this, choice](const QString &variableName) {
        m_viewport->program().setBindings(withBinding(m_viewport->currentScene().bindings,
                                                      variableName, choice->explicitBinding()));
        scheduleRebuild(); // the rows follow once the next frame is drawn with it
    });
    return label;
}
void UniformsDock::markUnplaced(const QStringList &names)
{
    const QStringList before = std::exchange(m_unplaced, names);
    for (const QString &name : before + names)
        showUnplaced(name);
}

// The mark on `name`'s row as m_unplaced says, the rows kept (making them
// again takes the GUI thread's time and the user's focus).
void UniformsDock::showUnplaced(const QString &name)
{
    const bool unplaced = m_unplaced.contains(name);
    if (auto *mark = m_contents->findChild<QLabel *>(QStringLiteral("unplaced:") + name))
        mark->setVisible(unplaced);
    if (auto *title = m_contents->findChild<QLabel *>(QStringLiteral("uniformName:") + name))
        title->setStyleSheet(unplaced ? QStringLiteral("color: #c62828; font-weight: bold;")
                                      : QString());
}

void UniformsDock::showUniform(const QString &name)
{
    show();
    raise();
    QWidget *row = m_rows.value(name);
    if (!row)
        row = m_rows.value(name + QStringLiteral("[0]"));
    if (!row)
        return;
    m_scroll->ensureWidgetVisible(row);
    if (auto *choice = m_contents->findChild<QComboBox *>(QStringLiteral("boundTo:") + name)) {
        // Once the dock just shown is laid out: a hidden widget takes no focus.
        QTimer::singleShot(0, choice, [this, choice] {
            m_scroll->ensureWidgetVisible(choice);
            choice->setFocus(Qt::OtherFocusReason);
        });
    }
}

void UniformsDock::addInactive(const UniformDeclaration &declaration)
{
    auto *row = new QWidget(m_contents);
    auto *layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    auto *icon = new QLabel(row);
    const int size = style()->pixelMetric(QStyle::PM_SmallIconSize);
    icon->setPixmap(style()->standardIcon(QStyle::SP_MessageBoxWarning).pixmap(size, size));
    auto *text = new QLabel(tr("declared but optimised away: not used by the program"), row);
    text->setWordWrap(true);
    layout->addWidget(icon);
    layout->addWidget(text, 1);
    row->setObjectName(QStringLiteral("uniform:") + declaration.name);
    row->setToolTip(tr("The compiler removed %1 %2 because nothing the output depends on reads it.")
                        .arg(declaration.type, declaration.name));
    m_inactive.append(declaration.name);
    addRow(declaration.name, declaration.name, row);
}

void UniformsDock::addRow(const QString &element, const QString &label, QWidget *row,
                          QWidget *labelWidget)
{
    if (labelWidget)
        m_form->addRow(labelWidget, row);
    else
        m_form->addRow(label, row);
    m_rows.insert(element, row);
}

void UniformsDock::connectRow(QWidget *row, const QString &element)
{
    if (auto *f = qobject_cast<UniformFloatRow *>(row))
        connect(f, &UniformFloatRow::edited, this,
                [this, element](float v) { writeFloats(element, {v}); });
    else if (auto *v = qobject_cast<UniformVectorRow *>(row))
        connect(v, &UniformVectorRow::edited, this,
                [this, element](const QList<float> &values) { writeFloats(element, values); });
    else if (auto *i = qobject_cast<UniformIntRow *>(row))
        connect(i, &UniformIntRow::edited, this,
                [this, element](int value) { writeInt(element, value); });
    else if (auto *b = qobject_cast<UniformBoolRow *>(row))
        connect(b, &UniformBoolRow::edited, this,
                [this, element](bool value) { writeInt(element, value ? 1 : 0); });
}

void UniformsDock::writeFloats(const QString &element, const QList<float> &values)
{
    const UniformValue *known = m_values.find(element.toUtf8());
    if (!known)
        return;
    UniformValue value = *known;
    for (int i = 0; i < value.components && i < values.size(); ++i)
        value.floats[size_t(i)] = values[i];
    write(value);
}

void UniformsDock::writeInt(const QString &element, int number)
{
    const UniformValue *known = m_values.find(element.toUtf8());
    if (!known)
        return;
    UniformValue value = *known;
    value.ints[0] = number;
    value.uints[0] = GLuint(std::max(number, 0));
    write(value);
}

void UniformsDock::write(const UniformValue &value)
{
    // Set only where name and type still match the program.
    if (!m_viewport || !m_viewport->program().set(value))
        return;
    for (UniformValue &kept : m_values.values)
        if (kept.name == value.name)
            kept = value;
    m_viewport->frames().requestFrame();
    emit valueWritten();
}

void UniformsDock::refreshDrivenValues()
{
    m_sinceRefresh.restart();
    if (m_rows.isEmpty() || !isVisible())
        return;
    Program program;
    if (!readProgram(program))
        return;
    for (const UniformValue &value : program.values.values) {
        const QString element = QString::fromUtf8(value.name);
        if (m_owners.value(element, UniformOwner::User) != UniformOwner::User)
            showUniformValue(m_rows.value(element), value);
    }
}

} // namespace phonglab
