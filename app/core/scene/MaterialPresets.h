#pragma once
#include "Material.h"

#include <QList>
#include <QString>

namespace phonglab {

struct MaterialPreset {
    QString name;
    Material material;
};

// The shipped looks (plastic, rubber, polished metal, chalk) followed by the
// user's own, which live in QSettings under "materialPresets".
QList<MaterialPreset> builtinMaterialPresets();
QList<MaterialPreset> userMaterialPresets();
QList<MaterialPreset> allMaterialPresets();
// Adds or replaces (same name) a user preset.
void saveUserMaterialPreset(const MaterialPreset &preset);

} // namespace phonglab
