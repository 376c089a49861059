#include "StartupOptions.h"

#include <QtGlobal>

namespace phonglab {

namespace {

QString lowerValue(const char *name)
{
    return qEnvironmentVariable(name).trimmed().toLower();
}

} // namespace

StartupOptions StartupOptions::fromEnvironment()
{
    StartupOptions o;
    const QString answer = lowerValue("PHONGLAB_RECOVERY_ANSWER");
    if (answer == QLatin1String("restore"))
        o.recoveryAnswer = ShaderRecovery::Answer::Restore;
    else if (answer == QLatin1String("discard"))
        o.recoveryAnswer = ShaderRecovery::Answer::Discard;
    o.presentOnGuiThread = qEnvironmentVariableIsSet("PHONGLAB_PRESENT_ON_GUI_THREAD");
    o.documentationFolder = qEnvironmentVariable("PHONGLAB_DOC_DIR");
    o.typeAfterStart = qEnvironmentVariable("PHONGLAB_TEST_TYPE_AFTER_START");
    return o;
}

} // namespace phonglab
