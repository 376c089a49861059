#include "HeadlessPlatform.h"

#include "HeadlessIntegration.h"

#include <QtPlugin>

// The plugin is linked statically into every executable (app/CMakeLists.txt
// links this library whole), so this import always finds it.
Q_IMPORT_PLUGIN(HeadlessIntegrationPlugin)

namespace phonglab {

void useHeadlessPlatformWithoutDisplay()
{
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") && qEnvironmentVariableIsEmpty("DISPLAY")
        && qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY"))
        qputenv("QT_QPA_PLATFORM", kHeadlessPlatformName);
}

bool runsHeadless()
{
    return headless::HeadlessIntegration::instance() != nullptr;
}

QString headlessGlProblem()
{
    const auto *integration = headless::HeadlessIntegration::instance();
    return integration ? integration->problem() : QString();
}

} // namespace phonglab
