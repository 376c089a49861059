#include "GradeReferences.h"

#include "cli/common/PngFiles.h"
#include "render/gl/QtImages.h"

#include <QCoreApplication>

namespace phonglab::cli {

// Messages a user reads, in the language the run speaks (core/support/Language).
struct GradeReferencesWords {
    Q_DECLARE_TR_FUNCTIONS(phonglab::cli::GradeReferences)
};

GradeReferences::GradeReferences(const GradeResults &results)
    : m_results(results)
{
}

Result<> GradeReferences::prepare(const std::function<void(const QString &)> &progress)
{
    for (std::size_t i = 0; i < m_results.scenes.size(); ++i) {
        const GradeScene &scene = m_results.scenes[i];
        const std::lock_guard lock(m_mutex);
        if (const Result<const CheckReference *> made = make(int(i), scene.scene, progress); !made)
            return fail(
                GradeReferencesWords::tr("%1: no exact image: %2").arg(scene.path, made.error()));
    }
    return {};
}

Result<const CheckReference *> GradeReferences::referenceFor(int scene, const Scene &checked)
{
    const std::lock_guard lock(m_mutex);
    return make(scene, checked, {});
}

Result<const CheckReference *> GradeReferences::make(
    int scene, const Scene &checked, const std::function<void(const QString &)> &progress)
{
    const std::pair key{scene, checked.enabledLightCount()};
    if (const auto found = m_references.find(key); found != m_references.end())
        return &found->second;
    const GradeScene &s = m_results.scenes[std::size_t(scene)];
    const auto shown = [&](double done) {
        if (progress)
            progress(GradeReferencesWords::tr("grade: the exact image of %1, %2 %")
                         .arg(s.label, QString::number(int(done * 100))));
        return true;
    };
    Result<CheckReference> made =
        makeCheckReference(checked, s.objectMeshes, m_results.settings.size.width(),
                           m_results.settings.size.height(), shown);
    if (!made)
        return fail(made.error());
    return &m_references.emplace(key, std::move(*made)).first->second;
}

QString GradeReferences::exactImageFor(int scene, int lights, PhongEquation equation,
                                       const CheckReference &reference)
{
    const GradeScene &s = m_results.scenes[std::size_t(scene)];
    const bool slide = equation == PhongEquation::Slide && !reference.slide.color.empty();
    QString name = QStringLiteral("images/%1-exact").arg(s.slug);
    if (lights != s.scene.enabledLightCount())
        name += QStringLiteral("-%1-lights").arg(lights);
    if (slide)
        name += QStringLiteral("-slide");
    name += QStringLiteral(".png");
    const std::lock_guard lock(m_mutex);
    if (const auto found = m_exactImages.find(name); found != m_exactImages.end())
        return found->second;
    const RgbImage exact =
        slide ? reference.slide.toImage(reference.background) : reference.exactImage;
    const bool written =
        bool(writePng(toQImage(exact), m_results.settings.outFolder + QLatin1Char('/') + name));
    return m_exactImages[name] = written ? name : QString();
}

} // namespace phonglab::cli
