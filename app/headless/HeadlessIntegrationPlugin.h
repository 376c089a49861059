#pragma once
#include <qpa/qplatformintegrationplugin.h>

namespace phonglab::headless {

// Registers HeadlessIntegration as the platform "phonglab-headless". Built
// as a static plugin (QT_STATICPLUGIN) and imported by HeadlessPlatform.cpp,
// so every PhongLab executable carries it and nothing is installed into
// Qt's plugin folder.
class HeadlessIntegrationPlugin : public QPlatformIntegrationPlugin
{
    Q_OBJECT
    Q_PLUGIN_METADATA(IID QPlatformIntegrationFactoryInterface_iid FILE "phonglab-headless.json")

public:
    QPlatformIntegration *create(const QString &key, const QStringList &parameters) override;
};

} // namespace phonglab::headless
