#pragma once
#include "ui/shaders/DiagnosticList.h"
#include "ui/shaders/ShaderDock.h"

#include <QAction>
#include <QComboBox>
#include <QLabel>
#include <QPushButton>
#include <QTabWidget>

// The Shaders dock's widgets as a test reaches them: by the object names
// the dock gives them, as a user reaches them by sight. The dock keeps no
// getters for tests.
namespace phonglab::test {

template <class Part> Part *partNamed(const QObject *owner, const char *name)
{
    Part *part = owner->findChild<Part *>(QLatin1String(name));
    if (!part)
        qFatal("%s has no %s named %s", owner->metaObject()->className(),
               Part::staticMetaObject.className(), name);
    return part;
}

inline QLabel *shaderStatus(const ShaderDock *dock)
{
    return partNamed<QLabel>(dock, "shaderStatus");
}
inline QAction *compileAction(const ShaderDock *dock)
{
    return partNamed<QAction>(dock, "compileAction");
}
inline QPushButton *applyAnywayButton(const ShaderDock *dock)
{
    return partNamed<QPushButton>(dock, "applyAnyway");
}
inline QComboBox *shadingMethodBox(const ShaderDock *dock)
{
    return partNamed<QComboBox>(dock, "shadingMethodBox");
}
inline DiagnosticList *diagnosticList(const ShaderDock *dock)
{
    return partNamed<DiagnosticList>(dock, "diagnosticList");
}
inline QTabWidget *shaderTabs(const ShaderDock *dock)
{
    return partNamed<QTabWidget>(dock, "shaderTabs");
}

} // namespace phonglab::test
