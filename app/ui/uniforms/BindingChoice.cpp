#include "BindingChoice.h"

#include <QAbstractItemView>

namespace phonglab {

namespace {

// Item data: the word a scene file writes ("none", a meaning's key), or an
// empty string for "automatic" (no word at all).
const QString kAutomatic;

} // namespace

BindingChoice::BindingChoice(const ShaderVariable &variable,
                             std::optional<BindingMeaning> automatic,
                             const std::optional<std::optional<BindingMeaning>> &explicitBinding,
                             QWidget *parent)
    : QComboBox(parent)
    , m_variable(variable.name)
{
    setObjectName(QStringLiteral("boundTo:") + variable.name);
    // Closed it shows the meaning's start; open, each meaning with its
    // description in full.
    setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    setMinimumContentsLength(22);
    addItem(automatic ? tr("automatic: %1").arg(bindingMeaningKey(*automatic))
                      : tr("automatic: your own"),
            kAutomatic);
    addItem(tr("your own"), kUnboundWord);
    setItemData(1, tr("PhongLab never sets it: you edit it here"), Qt::ToolTipRole);
    for (const QString &key : bindingMeaningKeys()) {
        const BindingMeaning meaning = *bindingMeaningFromKey(key);
        if (isVertexInput(meaning) || !bindingFits(meaning, variable))
            continue;
        addItem(tr("%1 — %2").arg(key, bindingMeaningDescription(meaning)), key);
        setItemData(count() - 1, bindingMeaningDescription(meaning), Qt::ToolTipRole);
    }
    int current = 0;
    if (explicitBinding)
        current = findData(*explicitBinding ? bindingMeaningKey(**explicitBinding) : kUnboundWord);
    setCurrentIndex(std::max(0, current));
    setToolTip(
        tr("What PhongLab sets %1 to (saved with the scene as \"bindings\")").arg(variable.name));
    view()->setMinimumWidth(view()->sizeHintForColumn(0) + 24);
    connect(this, &QComboBox::activated, this, [this] { emit chosen(m_variable); });
}

std::optional<std::optional<BindingMeaning>> BindingChoice::explicitBinding() const
{
    const QString word = currentData().toString();
    if (word.isEmpty())
        return std::nullopt;
    if (word == kUnboundWord)
        return std::optional<BindingMeaning>();
    return bindingMeaningFromKey(word);
}

ExplicitBindings withBinding(ExplicitBindings bindings, const QString &variable,
                             const std::optional<std::optional<BindingMeaning>> &word)
{
    if (word)
        bindings[variable] = *word;
    else
        bindings.erase(variable);
    return bindings;
}

} // namespace phonglab
