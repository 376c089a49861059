#pragma once
#include "GradeRows.h"
#include "core/check/ShaderCheck.h"
#include "core/support/Result.h"

#include <QString>

#include <functional>
#include <map>
#include <mutex>
#include <utility>

namespace phonglab::cli {

// The exact images `grade` checks against: one CheckReference per scene and
// number of lights a program takes (a shader with room for fewer lights
// than the scene has is checked against the scene it can light), each made
// once, and the exact image of each written once under the out folder's
// images/. Safe to use from the threads that check rows at once.
class GradeReferences
{
public:
    explicit GradeReferences(const GradeResults &results);

    // Every scene's reference with all its lights, before any child starts
    // (they use every core). `progress` gets "the exact image of …, N %".
    // Errors name the scene.
    Result<> prepare(const std::function<void(const QString &)> &progress = {});
    // The reference of scene `scene` as `checked` (sceneForCheck) has it,
    // or why none could be made.
    Result<const CheckReference *> referenceFor(int scene, const Scene &checked);
    // The exact image of `equation` with `lights` lights, relative to the
    // out folder ("images/check-exact.png"); empty where it was not written.
    QString exactImageFor(int scene, int lights, PhongEquation equation,
                          const CheckReference &reference);

private:
    Result<const CheckReference *> make(int scene, const Scene &checked,
                                        const std::function<void(const QString &)> &progress);

    const GradeResults &m_results;
    std::mutex m_mutex; // over both maps; a reference is made under it
    std::map<std::pair<int, int>, CheckReference> m_references; // by scene, then lights
    std::map<QString, QString> m_exactImages;
};

} // namespace phonglab::cli
