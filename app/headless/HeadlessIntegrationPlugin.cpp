#include "HeadlessIntegrationPlugin.h"

#include "HeadlessIntegration.h"
#include "HeadlessPlatform.h"

namespace phonglab::headless {

QPlatformIntegration *HeadlessIntegrationPlugin::create(const QString &key, const QStringList &)
{
    if (key.compare(QLatin1String(kHeadlessPlatformName), Qt::CaseInsensitive) != 0)
        return nullptr;
    return new HeadlessIntegration;
}

} // namespace phonglab::headless
