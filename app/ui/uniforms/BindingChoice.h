#pragma once
#include "core/program/ShaderBindings.h"

#include <QComboBox>

namespace phonglab {

// The Uniforms dock's "bound to" choice for one uniform: what
// PhongLab sets it to. "automatic" leaves it to the name and type (and says
// what they gave); "your own" keeps PhongLab's hands off (the dock edits it);
// a meaning binds it explicitly, whatever its name. Only the meanings its
// type can hold are offered. The choice goes into the scene's "bindings".
class BindingChoice : public QComboBox
{
    Q_OBJECT

public:
    // `automatic`: the meaning the name and type give (none: the user's own);
    // `explicitBinding`: the scene's word on it, if it has one.
    BindingChoice(const ShaderVariable &variable, std::optional<BindingMeaning> automatic,
                  const std::optional<std::optional<BindingMeaning>> &explicitBinding,
                  QWidget *parent = nullptr);

    // The scene's word as chosen now: none for "automatic".
    std::optional<std::optional<BindingMeaning>> explicitBinding() const;

signals:
    // The user chose another entry.
    void chosen(const QString &variable);

private:
    QString m_variable;
};

// `bindings` with `variable`'s entry set to `word` (none: removed).
ExplicitBindings withBinding(ExplicitBindings bindings, const QString &variable,
                             const std::optional<std::optional<BindingMeaning>> &word);

} // namespace phonglab
