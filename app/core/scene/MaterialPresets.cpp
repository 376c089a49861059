#include "MaterialPresets.h"

#include <QCoreApplication>
#include <QSettings>

namespace phonglab {

namespace {

// The built-in presets' names, in the run's language (user presets keep theirs).
struct PresetWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::MaterialPresets)
};

const char *const kSettingsGroup = "materialPresets";

QList<double> toList(const glm::dvec3 &v)
{
    return {v.x, v.y, v.z};
}

glm::dvec3 toVec(const QVariant &value)
{
    const QVariantList list = value.toList();
    if (list.size() != 3)
        return glm::dvec3(0.0);
    return {list[0].toDouble(), list[1].toDouble(), list[2].toDouble()};
}

QVariantList toVariant(const glm::dvec3 &v)
{
    QVariantList list;
    for (double c : toList(v))
        list << c;
    return list;
}

} // namespace

QList<MaterialPreset> builtinMaterialPresets()
{
    // Classic Phong looks: plastic has a white highlight over a coloured
    // diffuse, rubber almost none, metal a tinted highlight and little
    // diffuse, chalk no highlight at all.
    return {
        {PresetWords::tr("Plastic"), {{0.1, 0.02, 0.02}, {0.7, 0.1, 0.1}, {0.7, 0.7, 0.7}, 32.0}},
        {PresetWords::tr("Rubber"),
         {{0.05, 0.05, 0.05}, {0.4, 0.4, 0.4}, {0.05, 0.05, 0.05}, 10.0}},
        {PresetWords::tr("Polished metal"),
         {{0.25, 0.2, 0.07}, {0.35, 0.3, 0.1}, {0.8, 0.75, 0.55}, 128.0}},
        {PresetWords::tr("Chalk"), {{0.25, 0.25, 0.25}, {0.9, 0.9, 0.88}, {0.0, 0.0, 0.0}, 1.0}},
    };
}

QList<MaterialPreset> userMaterialPresets()
{
    QSettings settings;
    QList<MaterialPreset> presets;
    const int count = settings.beginReadArray(kSettingsGroup);
    for (int i = 0; i < count; ++i) {
        settings.setArrayIndex(i);
        MaterialPreset preset;
        preset.name = settings.value("name").toString();
        preset.material.ka = toVec(settings.value("ka"));
        preset.material.kd = toVec(settings.value("kd"));
        preset.material.ks = toVec(settings.value("ks"));
        preset.material.shininess = settings.value("shininess", 32.0).toDouble();
        if (!preset.name.isEmpty())
            presets << preset;
    }
    settings.endArray();
    return presets;
}

QList<MaterialPreset> allMaterialPresets()
{
    return builtinMaterialPresets() + userMaterialPresets();
}

void saveUserMaterialPreset(const MaterialPreset &preset)
{
    QList<MaterialPreset> presets = userMaterialPresets();
    presets.removeIf([&](const MaterialPreset &p) { return p.name == preset.name; });
    presets << preset;
    QSettings settings;
    settings.beginWriteArray(kSettingsGroup, int(presets.size()));
    for (int i = 0; i < presets.size(); ++i) {
        settings.setArrayIndex(i);
        settings.setValue("name", presets[i].name);
        settings.setValue("ka", toVariant(presets[i].material.ka));
        settings.setValue("kd", toVariant(presets[i].material.kd));
        settings.setValue("ks", toVariant(presets[i].material.ks));
        settings.setValue("shininess", presets[i].material.shininess);
    }
    settings.endArray();
}

} // namespace phonglab
