#include "ShadedMistakes.h"

namespace phonglab {

const MistakeImages &ShadedMistakes::slideMistakes(const std::function<MistakeImages()> &shadeAll)
{
    std::call_once(m_slideOnce, [&] { m_slide = shadeAll(); });
    return m_slide;
}

RgbImage ShadedMistakes::setImage(PhongEquation equation, const std::vector<MistakeVariant> &set,
                                  const Shade &shade)
{
    const std::pair key{equation, set};
    {
        const std::lock_guard lock(m_setsMutex);
        if (const auto found = m_sets.find(key); found != m_sets.end())
            return found->second;
    }
    // Shaded outside the lock: two threads may shade the same set at once,
    // and both get the same pixels; only one is kept.
    RgbImage image = shade();
    const std::lock_guard lock(m_setsMutex);
    if (m_sets.size() < kMaxKeptSets)
        m_sets.emplace(key, image);
    return image;
}

} // namespace phonglab
