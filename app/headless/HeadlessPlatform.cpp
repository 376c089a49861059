#include "HeadlessPlatform.h"

#include "HeadlessIntegration.h"

#include <QtPlugin>

// The plugin is linked statically into every executable (app/CMakeLists.txt
// links this library whole), so this import always finds it.
Q_IMPORT_PLUGIN(HeadlessIntegrationPlugin)

namespace phonglab {

void chooseCommandPlatform()
{
    if (!qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        return;
    // Qt tries a ';'-separated list in order.
    QByteArray platforms;
    if (!qEnvironmentVariableIsEmpty("DISPLAY"))
        platforms = "xcb;";
    else if (!qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY"))
        platforms = "wayland;";
    qputenv("QT_QPA_PLATFORM", platforms + kHeadlessPlatformName);
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
